import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.scene.Camera;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.lang.reflect.Method;
import java.util.Locale;
import java.util.Optional;
import java.util.function.LongSupplier;

/**
 * One build's frame for side-by-side.sh: compiled against a Trisect jar and loaded once per build,
 * each in its own class loader. {@link #make} returns a frame that draws once per call and returns
 * the pieces it filled.
 */
public final class Frame {
    private Frame() {
    }

    /**
     * @param path perspective, affine, edge (tessellated, 32 px edges), error (tessellated, 0.5 px) or
     *             spans (0.5 px, builds that have it),
     *             each optionally with @nearest, @bilinear or @trilinear (the texture filter; nearest
     *             when left out), then +borders or +fade (the border overlay, plain or faded, drawn with
     *             the frame): "error@trilinear+borders"
     */
    public static LongSupplier make(String scene, String path, int width, int height) throws ReflectiveOperationException {
        return make(scene, path, width, height, 1);
    }

    /** As {@link #make(String, String, int, int)}, drawn by a renderer of {@code threads} threads (the caller's among them). */
    public static LongSupplier make(String scene, String path, int width, int height, int threads)
            throws ReflectiveOperationException {
        // The built-in scenes moved from dev.trisect.scene.DemoScenes (a Scene record) to
        // dev.trisect.content.DemoScenes (a SceneAsset record): reach either build's through reflection.
        Class<?> scenes;
        try {
            scenes = Class.forName("dev.trisect.content.DemoScenes");
        } catch (ClassNotFoundException e) {
            scenes = Class.forName("dev.trisect.scene.DemoScenes");
        }
        Object s = ((Optional<?>) scenes.getMethod("byName", String.class).invoke(null, scene))
                .orElseThrow(() -> new IllegalArgumentException("no scene " + scene));
        Method accessor = s.getClass().getMethod("textureArray");
        Texture[] textures = (Texture[]) accessor.invoke(s);
        Mesh mesh = (Mesh) s.getClass().getMethod("mesh").invoke(s);
        Camera camera = (Camera) s.getClass().getMethod("camera").invoke(s);
        int background = (int) scenes.getMethod("background", String.class).invoke(null, scene);
        Framebuffer frame = new Framebuffer(width, height);
        Mat4 viewProjection = camera.viewProjection(new Viewport(width, height));
        RenderSettings base = RenderSettings.defaults().withBackground(background);
        // "+borders" draws the border overlay with the frame, "+fade" the faded one.
        String[] parts = path.split("\\+", 2);
        if (parts.length == 2) {
            base = base.withBorders(true).withBorderStyle(switch (parts[1]) {
                case "borders" -> BorderStyle.plain();
                case "fade" -> new BorderStyle(BorderStyle.Colouring.YELLOW, true);
                default -> throw new IllegalArgumentException("no overlay " + parts[1]);
            });
        }
        String[] filtered = parts[0].split("@", 2);
        if (filtered.length == 2) {
            TextureFilter filter;
            try {
                filter = TextureFilter.valueOf(filtered[1].toUpperCase(Locale.ROOT));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("no filter " + filtered[1] + " in path " + path);
            }
            base = base.withFilter(filter);
        }
        RenderSettings settings = switch (filtered[0]) {
            case "perspective" -> base.withMode(RenderMode.PERSPECTIVE);
            case "affine" -> base.withMode(RenderMode.AFFINE);
            case "edge" -> base.withMode(RenderMode.TESSELLATED)
                    .withTessellation(TessellationSettings.defaults().withPolicy(SplitPolicy.EDGE));
            case "error" -> base.withMode(RenderMode.TESSELLATED)
                    .withTessellation(TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR));
            // By name, so that this compiles against builds from before the span path.
            case "spans" -> base.withMode(RenderMode.valueOf("SPANS"));
            default -> throw new IllegalArgumentException("no path " + path);
        };
        FrameRenderer renderer = new FrameRenderer(threads);
        return () -> {
            FrameStats stats = renderer.render(mesh, textures, viewProjection, settings, frame);
            return stats.pieces();
        };
    }
}
