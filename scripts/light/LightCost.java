import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;

/**
 * What light and fog cost, side by side in one JVM: per path, frames of the same scene alternate
 * between the plain frame and each variant (wall time, the renderer's threads), so that the shared
 * machine's load falls on both alike. Prints per path and variant the median ms of each and the
 * median, lowest and highest of the per-round ratios.
 *
 *   java -cp target/trisect.jar scripts/light/LightCost.java SCENE WxH THREADS ROUNDS [VARIANT...]
 *
 * VARIANT: fog-linear, fog-exp (the default: both).
 */
public final class LightCost {
    public static void main(String[] args) {
        String scene = args.length > 0 ? args[0] : "demo";
        String[] size = (args.length > 1 ? args[1] : "1920x1080").split("x");
        int threads = args.length > 2 ? Integer.parseInt(args[2]) : 2;
        int rounds = args.length > 3 ? Integer.parseInt(args[3]) : 15;
        List<String> variants = args.length > 4 ? Arrays.asList(args).subList(4, args.length)
                : List.of("fog-linear", "fog-exp");
        int w = Integer.parseInt(size[0]);
        int h = Integer.parseInt(size[1]);
        SceneAsset s = DemoScenes.byName(scene).orElseThrow();
        Mat4 vp = s.camera().viewProjection(new Viewport(w, h));
        RenderSettings base = RenderSettings.defaults();
        RenderSettings[] paths = {base.withMode(RenderMode.PERSPECTIVE), base.withMode(RenderMode.SPANS)
                .withKnotError(0.5), base.withMode(RenderMode.TESSELLATED).withTessellation(
                TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.5))};
        Framebuffer fb = new Framebuffer(w, h);
        Draws draws = new Draws();
        System.out.printf(Locale.ROOT, "scene %s %dx%d, %d threads, %d rounds%n", scene, w, h, threads, rounds);
        try (FrameRenderer r = new FrameRenderer(threads)) {
            for (RenderSettings path : paths) {
                List<Consumer<Draws>> setups = new ArrayList<>();
                setups.add(d -> { });
                for (String v : variants) {
                    setups.add(variant(v));
                }
                double[][] ms = new double[setups.size()][rounds];
                for (int warm = 0; warm < 5; warm++) {
                    for (Consumer<Draws> setup : setups) {
                        frame(r, draws, s, vp, setup, path, fb);
                    }
                }
                for (int round = 0; round < rounds; round++) {
                    for (int k = 0; k < setups.size(); k++) {
                        ms[k][round] = frame(r, draws, s, vp, setups.get(k), path, fb);
                    }
                }
                for (int k = 1; k < setups.size(); k++) {
                    double[] ratio = new double[rounds];
                    for (int round = 0; round < rounds; round++) {
                        ratio[round] = ms[k][round] / ms[0][round];
                    }
                    Arrays.sort(ratio);
                    System.out.printf(Locale.ROOT, "%-12s %-12s plain %7.2f ms  variant %7.2f ms  ratio median %.3f "
                                    + "(min %.3f, max %.3f)%n", path.mode().name().toLowerCase(Locale.ROOT),
                            variants.get(k - 1), median(ms[0]), median(ms[k]), ratio[rounds / 2], ratio[0],
                            ratio[rounds - 1]);
                }
            }
        }
    }

    private static Consumer<Draws> variant(String name) {
        Colour haze = new Colour(0.6, 0.7, 0.8);
        return switch (name) {
            case "fog-linear" -> d -> d.setFog(Fog.linear(5, 60, haze));
            case "fog-exp" -> d -> d.setFog(Fog.exp(0.05, haze));
            default -> throw new IllegalArgumentException("unknown variant " + name);
        };
    }

    private static double frame(FrameRenderer r, Draws draws, SceneAsset s, Mat4 vp, Consumer<Draws> setup,
                                RenderSettings path, Framebuffer fb) {
        draws.clear();
        draws.add(s.mesh(), s.textureArray(), vp);
        setup.accept(draws);
        long t = System.nanoTime();
        r.render(draws, path, fb);
        return (System.nanoTime() - t) / 1e6;
    }

    private static double median(double[] v) {
        double[] c = v.clone();
        Arrays.sort(c);
        return c[c.length / 2];
    }
}
