import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.light.FogPass;
import dev.trisect.math.Viewport;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.Locale;

/**
 * What the fog pass alone costs: the scene is drawn once without fog (per-pixel path, one thread),
 * then each round fogs a copy of it with each fog (linear 5..60, exp 0.05, exp2 0.05, haze as
 * LightCost's), 16 rows a call as the renderer's bands (so the JIT compiles it as it does in a frame)
 * with one set of working rows kept across calls, as each of the renderer's threads keeps one. Each
 * band's rows are copied in from the unfogged frame just before the pass (so they are in cache, as
 * the band's fill leaves them) and only the pass is timed, in the thread's CPU time (steadier than wall
 * time on a loaded machine). Prints per fog the median, lowest and highest ms and the median ns per
 * covered pixel. Running it on two jars compares two builds' passes (builds with
 * {@code FogPass.Rows}, from a15d08d on):
 *
 *   java -cp target/trisect.jar scripts/light/FogPassCost.java SCENE WxH ROUNDS
 */
public final class FogPassCost {
    /** Rows a call, as the renderer's bands. */
    private static final int BAND = 16;

    public static void main(String[] args) {
        String scene = args.length > 0 ? args[0] : "demo";
        String[] size = (args.length > 1 ? args[1] : "1920x1080").split("x");
        int rounds = args.length > 2 ? Integer.parseInt(args[2]) : 30;
        int w = Integer.parseInt(size[0]);
        int h = Integer.parseInt(size[1]);
        SceneAsset s = DemoScenes.byName(scene).orElseThrow();
        Framebuffer plain = new Framebuffer(w, h);
        Draws draws = new Draws();
        draws.add(s.mesh(), s.textureArray(), s.camera().viewProjection(new Viewport(w, h)));
        try (FrameRenderer r = new FrameRenderer(1)) {
            r.render(draws, RenderSettings.defaults(), plain);
        }
        long covered = 0;
        for (float q : plain.depth()) {
            covered += q > 0 ? 1 : 0;
        }
        Colour haze = new Colour(0.6, 0.7, 0.8);
        Fog[] fogs = {Fog.linear(5, 60, haze), Fog.exp(0.05, haze), Fog.exp2(0.05, haze)};
        Framebuffer frame = new Framebuffer(w, h);
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        double[][] ms = new double[fogs.length][rounds];
        FogPass.Rows[] rows = new FogPass.Rows[fogs.length];
        for (int f = 0; f < fogs.length; f++) {
            rows[f] = new FogPass.Rows();
        }
        for (int round = -10; round < rounds; round++) {
            for (int f = 0; f < fogs.length; f++) {
                FogPass pass = new FogPass(fogs[f]);
                long t = 0;
                for (int y = 0; y < h; y += BAND) {
                    int y1 = Math.min(h, y + BAND);
                    System.arraycopy(plain.colour(), y * w, frame.colour(), y * w, (y1 - y) * w);
                    System.arraycopy(plain.depth(), y * w, frame.depth(), y * w, (y1 - y) * w);
                    long t0 = cpu.getCurrentThreadCpuTime();
                    pass.apply(frame, y, y1, rows[f]);
                    t += cpu.getCurrentThreadCpuTime() - t0;
                }
                if (round >= 0) {
                    ms[f][round] = t / 1e6;
                }
            }
        }
        System.out.printf(Locale.ROOT, "scene %s %dx%d, %d covered pixels, %d rounds, CPU time of the pass%n",
                scene, w, h, covered, rounds);
        for (int f = 0; f < fogs.length; f++) {
            double[] m = ms[f].clone();
            Arrays.sort(m);
            System.out.printf(Locale.ROOT, "%-5s median %6.2f ms (min %.2f, max %.2f)  %.2f ns a covered pixel%n",
                    fogs[f].mode().toString().toLowerCase(Locale.ROOT), m[rounds / 2], m[0], m[rounds - 1],
                    m[rounds / 2] * 1e6 / covered);
        }
    }
}
