import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.pipeline.FrameStats;
import dev.trisect.pipeline.RenderMode;
import dev.trisect.pipeline.RenderSettings;
import dev.trisect.raster.BorderStyle;
import dev.trisect.raster.Framebuffer;
import dev.trisect.scene.DemoScenes;
import dev.trisect.scene.Scene;
import dev.trisect.tessellate.SplitPolicy;
import dev.trisect.tessellate.TessellationSettings;
import dev.trisect.texture.Texture;
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
     * @param path perspective, affine, edge (tessellated, 32 px edges) or error (tessellated, 0.5 px),
     *             each optionally with +borders or +fade (the border overlay, plain or faded, drawn with the frame)
     */
    public static LongSupplier make(String scene, String path, int width, int height) {
        Scene s = DemoScenes.byName(scene).orElseThrow(() -> new IllegalArgumentException("no scene " + scene));
        Texture[] textures = s.textureArray();
        Framebuffer frame = new Framebuffer(width, height);
        Mat4 viewProjection = s.camera().viewProjection(new Viewport(width, height));
        RenderSettings base = RenderSettings.defaults().withBackground(DemoScenes.background(scene));
        // "+borders" draws the border overlay with the frame, "+fade" the faded one.
        String[] parts = path.split("\\+", 2);
        if (parts.length == 2) {
            base = base.withBorders(true).withBorderStyle(switch (parts[1]) {
                case "borders" -> BorderStyle.plain();
                case "fade" -> new BorderStyle(BorderStyle.Colouring.YELLOW, true);
                default -> throw new IllegalArgumentException("no overlay " + parts[1]);
            });
        }
        RenderSettings settings = switch (parts[0]) {
            case "perspective" -> base.withMode(RenderMode.PERSPECTIVE);
            case "affine" -> base.withMode(RenderMode.AFFINE);
            case "edge" -> base.withMode(RenderMode.TESSELLATED)
                    .withTessellation(TessellationSettings.defaults().withPolicy(SplitPolicy.EDGE));
            case "error" -> base.withMode(RenderMode.TESSELLATED)
                    .withTessellation(TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR));
            default -> throw new IllegalArgumentException("no path " + path);
        };
        FrameRenderer renderer = new FrameRenderer(1);
        return () -> {
            FrameStats stats = renderer.render(s.mesh(), textures, viewProjection, settings, frame);
            return stats.pieces();
        };
    }
}
