import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.light.Lights;
import dev.trisect.light.Surface;
import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Colour;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.Shading;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.TextureFilter;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * One hash per lit frame of the built-in scenes, to show that a change leaves lit pixels as they were:
 * run it on two builds and compare the outputs ({@code diff}). Per scene, thread count (1, 2), path
 * (per pixel, spans at 0.5 px, tessellated at error 0.5, affine, tessellated with borders), filter and
 * lighting — "flat" and "flat-tinted" (every fourth material unlit, the others flat, under a white
 * directional light and under a tinted one with a tinted ambient), "smooth", and "mixed" (material m
 * unlit, flat or smooth by m mod 3, so a scene of one material is unlit there) — four
 * frames are drawn (lit copies of textures are built from the third) and their colour, depth, UV and
 * ids buffers hashed together. 640x360.
 *
 *   java -cp target/trisect.jar scripts/light/LitFrameHashes.java [SCENE...] > hashes.txt
 */
public final class LitFrameHashes {
    public static void main(String[] args) {
        int w = 640;
        int h = 360;
        List<String> scenes = args.length > 0 ? List.of(args) : DemoScenes.names();
        Lights white = Lights.builder().ambient(0.2, 0.2, 0.2)
                .directional(0.3, -1, -0.5, new double[3], new double[] {1, 1, 1}).build();
        Lights tinted = Lights.builder().ambient(0.1, 0.15, 0.2)
                .directional(-0.5, -0.4, -1, new double[3], new double[] {0.6, 0.7, 0.5}).build();
        RenderSettings base = RenderSettings.defaults();
        TessellationSettings error = TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.5);
        RenderSettings[] paths = {base.withMode(RenderMode.PERSPECTIVE), base.withMode(RenderMode.SPANS).withKnotError(0.5),
                base.withMode(RenderMode.TESSELLATED).withTessellation(error), base.withMode(RenderMode.AFFINE),
                base.withMode(RenderMode.TESSELLATED).withBorders(true)};
        String[] pathNames = {"perspective", "spans", "tessellated", "affine", "tessellated-borders"};
        for (String scene : scenes) {
            if (DemoScenes.byName(scene).isEmpty()) {
                System.err.println("LitFrameHashes: no built-in scene '" + scene + "' (scenes: " + DemoScenes.names() + ")");
                System.exit(2);
            }
            SceneAsset s = DemoScenes.byName(scene).get();
            Mat4 vp = s.camera().viewProjection(new Viewport(w, h));
            for (int threads = 1; threads <= 2; threads++) {
                try (FrameRenderer r = new FrameRenderer(threads)) {
                    for (int p = 0; p < paths.length; p++) {
                        for (TextureFilter f : TextureFilter.values()) {
                            for (String lighting : List.of("flat", "flat-tinted", "smooth", "mixed")) {
                                long hash = hash(r, s, vp, paths[p].withFilter(f), lighting,
                                        lighting.equals("flat-tinted") ? tinted : white, w, h);
                                System.out.printf(Locale.ROOT, "%s %d %s %s %s %016x%n", scene, threads, pathNames[p],
                                        f.name().toLowerCase(Locale.ROOT), lighting, hash);
                            }
                        }
                    }
                }
            }
        }
    }

    private static long hash(FrameRenderer r, SceneAsset s, Mat4 vp, RenderSettings settings, String lighting,
                             Lights lights, int w, int h) {
        Framebuffer fb = new Framebuffer(w, h);
        fb.recordUv(true);
        Draws d = new Draws();
        int materials = s.mesh().materialCount();
        Surface[] surfaces = new Surface[materials];
        for (int m = 0; m < materials; m++) {
            Shading shading = switch (lighting) {
                case "smooth" -> Shading.SMOOTH;
                case "mixed" -> m % 3 == 0 ? Shading.NONE : m % 3 == 1 ? Shading.FLAT : Shading.SMOOTH;
                default -> m % 4 == 3 ? Shading.NONE : Shading.FLAT;
            };
            surfaces[m] = new Surface(shading, new Colour(0.9, 0.8, 0.7), new Colour(1, 0.95, 0.9));
        }
        long hash = 0;
        for (int frame = 0; frame < 4; frame++) {
            d.clear();
            d.add(s.mesh(), s.textureArray(), vp, Mat4.identity(), surfaces);
            d.setLights(lights);
            r.render(d, settings, fb);
            hash = hash * 31 + 7L * Arrays.hashCode(fb.colour()) + Arrays.hashCode(fb.depth())
                    + 13L * Arrays.hashCode(fb.uv()) + 17L * Arrays.hashCode(fb.ids());
        }
        return hash;
    }
}
