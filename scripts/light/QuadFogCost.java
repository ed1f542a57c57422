import dev.trisect.light.FogPass;
import dev.trisect.raster.QuadRaster;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.Locale;
import java.util.Random;

/**
 * What fogging billboards costs in the quads' loop: a WxH frame covered by PIXELS x PIXELS billboards
 * (64 unless given: 4 x 4 pixels a texel; 16: one pixel a texel) (random 16 x 16 textures, a third each opaque, alpha-tested with a quarter of the texels out, and
 * blended at alpha 128; 1/w from 0.02 to 0.5), drawn by QuadRaster.rows 16 rows a call as the bands
 * do, without fog and with exp fog 0.05, in turn each round, in the thread's CPU time. Prints per
 * variant the median, lowest and highest ms of the rounds, and the median per-round ratio fogged /
 * unfogged with its range:
 *
 *   java -cp target/trisect.jar scripts/light/QuadFogCost.java WxH ROUNDS [PIXELS]
 */
public final class QuadFogCost {
    private static final int BAND = 16;

    public static void main(String[] args) {
        String[] size = (args.length > 0 ? args[0] : "1920x1080").split("x");
        int rounds = args.length > 1 ? Integer.parseInt(args[1]) : 30;
        int w = Integer.parseInt(size[0]);
        int h = Integer.parseInt(size[1]);
        int side = args.length > 2 ? Integer.parseInt(args[2]) : 64;
        Random random = new Random(27);
        QuadRaster quads = new QuadRaster();
        for (int y = 0; y < h; y += side) {
            for (int x = 0; x < w; x += side) {
                int kind = random.nextInt(3);
                int[] tex = new int[256];
                for (int i = 0; i < tex.length; i++) {
                    int rgb = random.nextInt(0x1000000);
                    tex[i] = (kind == 2 ? 0x80000000 : kind == 1 && random.nextInt(4) == 0 ? 0 : 0xFF000000) | rgb;
                }
                quads.add(x, y, x + side, y + side, 0.02 + 0.48 * random.nextDouble(), tex, 16, 0, 16, 16,
                        (kind == 2 ? QuadRaster.BLEND : QuadRaster.TEST) | QuadRaster.FOG, -1, QuadRaster.BILLBOARD);
            }
        }
        FogPass fog = new FogPass(Fog.exp(0.05, new Colour(0.6, 0.7, 0.8)));
        int[] colour = new int[w * h];
        float[] depth = new float[w * h];
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        double[][] ms = new double[2][rounds];
        double[] ratio = new double[rounds];
        for (int round = -10; round < rounds; round++) {
            for (int v = 0; v < 2; v++) {
                quads.setUp(w, h, v == 0 ? null : fog);
                Arrays.fill(colour, 0xFF808080);
                Arrays.fill(depth, 0.01f);
                long t0 = cpu.getCurrentThreadCpuTime();
                for (int y = 0; y < h; y += BAND) {
                    for (int s = 0; s < quads.count(); s++) {
                        quads.rows(s, colour, depth, y, Math.min(h, y + BAND));
                    }
                }
                if (round >= 0) {
                    ms[v][round] = (cpu.getCurrentThreadCpuTime() - t0) / 1e6;
                }
            }
            if (round >= 0) {
                ratio[round] = ms[1][round] / ms[0][round];
            }
        }
        String[] names = {"unfogged", "exp 0.05"};
        for (int v = 0; v < 2; v++) {
            Arrays.sort(ms[v]);
            System.out.printf(Locale.ROOT, "%-9s %7.2f ms (%.2f-%.2f)%n", names[v], ms[v][rounds / 2], ms[v][0],
                    ms[v][rounds - 1]);
        }
        Arrays.sort(ratio);
        System.out.printf(Locale.ROOT, "fogged/unfogged %.3f (%.3f-%.3f)%n", ratio[rounds / 2], ratio[0],
                ratio[rounds - 1]);
    }
}
