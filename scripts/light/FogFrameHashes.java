import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Lines;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import java.util.List;
import java.util.Locale;
import java.util.Random;

/**
 * One hash per fogged frame of the built-in scenes, to show that a change leaves fogged pixels as they
 * were: run it on two builds and compare the outputs ({@code diff}). Per scene, size (640x360, 333x97,
 * and 1920x1080 for demo and sphere160k), thread count (1, 2), path (per pixel, spans at 0.5 px,
 * tessellated at error 0.5, affine, tessellated with borders), fog (linear 5..60 and exp and exp2 0.05
 * towards a haze, linear 1..8 towards a dark brown) and without and with 200 fixed random lines (which
 * are fogged), one frame, its colour and depth buffers hashed together: 1,280 lines for all scenes.
 * Optional arguments name the scenes to draw (default: all).
 *
 *   java -cp target/trisect.jar scripts/light/FogFrameHashes.java [SCENE...] > hashes.txt
 */
public final class FogFrameHashes {
    public static void main(String[] args) {
        Colour haze = new Colour(0.6, 0.7, 0.8);
        Fog[] fogs = {Fog.linear(5, 60, haze), Fog.exp(0.05, haze), Fog.exp2(0.05, haze),
            Fog.linear(1, 8, new Colour(0.2, 0.1, 0.05))};
        String[] fogNames = {"linear5,60", "exp0.05", "exp2-0.05", "linear1,8"};
        Random random = new Random(7);
        Lines.Builder builder = Lines.builder();
        for (int i = 0; i < 200; i++) {
            builder.segment(point(random), point(random), random.nextInt(1 << 24));
        }
        Lines lines = builder.build();
        RenderSettings base = RenderSettings.defaults();
        RenderSettings[] paths = {base.withMode(RenderMode.PERSPECTIVE),
            base.withMode(RenderMode.SPANS).withKnotError(0.5),
            base.withMode(RenderMode.TESSELLATED).withTessellation(
                    TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.5)),
            base.withMode(RenderMode.AFFINE), base.withMode(RenderMode.TESSELLATED).withBorders(true)};
        List<String> scenes = args.length > 0 ? List.of(args) : DemoScenes.names();
        for (String scene : scenes) {
            SceneAsset s = DemoScenes.byName(scene).orElseThrow(
                    () -> new IllegalArgumentException("no built-in scene " + scene));
            for (int[] size : new int[][] {{640, 360}, {1920, 1080}, {333, 97}}) {
                if (size[0] == 1920 && !(scene.equals("demo") || scene.equals("sphere160k"))) {
                    continue;
                }
                Mat4 vp = s.camera().viewProjection(new Viewport(size[0], size[1]));
                Framebuffer frame = new Framebuffer(size[0], size[1]);
                for (int threads = 1; threads <= 2; threads++) {
                    try (FrameRenderer renderer = new FrameRenderer(threads)) {
                        Draws draws = new Draws();
                        for (int p = 0; p < paths.length; p++) {
                            for (int f = 0; f < fogs.length; f++) {
                                for (int withLines = 0; withLines < 2; withLines++) {
                                    draws.clear();
                                    draws.add(s.mesh(), s.textureArray(), vp);
                                    if (withLines == 1) {
                                        draws.addLines(lines, vp, 1);
                                    }
                                    draws.setFog(fogs[f]);
                                    renderer.render(draws, paths[p], frame);
                                    System.out.printf(Locale.ROOT, "%s %dx%d t%d path%d %s lines%d %016x%n", scene,
                                            size[0], size[1], threads, p, fogNames[f], withLines, hash(frame));
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    private static Vec3 point(Random random) {
        return new Vec3(random.nextGaussian() * 5, random.nextGaussian() * 2, random.nextGaussian() * 10);
    }

    private static long hash(Framebuffer frame) {
        long h = 1;
        for (int c : frame.colour()) {
            h = h * 1000003 + c;
        }
        for (float z : frame.depth()) {
            h = h * 1000003 + Float.floatToRawIntBits(z);
        }
        return h;
    }
}
