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
import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.IntVector;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;

/**
 * How fast the fog pass's arithmetic can go on this machine: the demo at 1920x1080 drawn once (per
 * pixel, one thread), then each round fogs it band by band (16 rows, copied in from the unfogged frame
 * just before, so in cache as the fill leaves them) by {@code FogPass} and by one fused loop written
 * with the incubating Vector API: the same float and integer operations per pixel as the pass (so the
 * same pixels, checked), read from the frame's depth and colour and written back in place, 16 lanes
 * (512 bits) at a time, no working rows, no copies, no scans (each row's covered run found once,
 * before the rounds), and by the same loop with a cheaper arithmetic ({@link #converted}). Linear fog 5..60. Prints the median (lowest, highest) CPU ms of the thread per
 * round and ns a covered pixel. Then the pass and the fused loop once more over one row that stays in
 * the L1 data cache ({@link #inCache}): the arithmetic with no cache misses. A measurement only: the
 * product does not use the Vector API.
 *
 *   java --add-modules jdk.incubator.vector -cp target/trisect.jar scripts/light/FogFloor.java [ROUNDS]
 */
public final class FogFloor {
    private static final VectorSpecies<Float> FS = FloatVector.SPECIES_512;
    private static final VectorSpecies<Integer> IS = IntVector.SPECIES_512;
    private static final int ONE = 4096;
    private static final float ROUND = 0x1.8p23f;
    private static final int ROUND_BITS = Float.floatToRawIntBits(ROUND);
    private static final int BAND = 16;

    /**
     * Linear fog over frame indices [from, bound) of one row, in place: the pass's arithmetic
     * ({@code FogPass.linear}, {@code factor} and {@code blend}), one fused loop; bound - from a multiple of 16.
     */
    static void linear(float[] depth, int[] color, int from, int bound, float a, float b, int fr, int fg, int fb) {
        int hr = ONE * 8 + fr * ONE;
        int hg = ONE * 8 + fg * ONE;
        int hb = ONE * 8 + fb * ONE;
        FloatVector one = FloatVector.broadcast(FS, 1f);
        for (int x = from; x < bound; x += FS.length()) {
            FloatVector q = FloatVector.fromArray(FS, depth, x);
            FloatVector t = one.div(q).neg().add(a);
            FloatVector f = t.add(t.abs()).mul(0.5f).mul(b);
            FloatVector sum = f.add((float) ONE).sub(f.sub((float) ONE).abs()).mul(0.5f).add(ROUND);
            IntVector k = ((IntVector) sum.reinterpretAsInts()).sub(ROUND_BITS);
            IntVector above = k.neg().add(ONE).or(k).lanewise(VectorOperators.ASHR, 31);
            IntVector w = k.lanewise(VectorOperators.XOR, k.lanewise(VectorOperators.XOR, ONE).and(above));
            IntVector c = IntVector.fromArray(IS, color, x);
            IntVector r = c.lanewise(VectorOperators.ASHR, 12).and(0xFF0).sub(fr).mul(w).add(hr)
                    .lanewise(VectorOperators.ASHR, 16).lanewise(VectorOperators.LSHL, 16);
            IntVector g = c.lanewise(VectorOperators.ASHR, 4).and(0xFF0).sub(fg).mul(w).add(hg)
                    .lanewise(VectorOperators.ASHR, 16).lanewise(VectorOperators.LSHL, 8);
            IntVector bl = c.lanewise(VectorOperators.LSHL, 4).and(0xFF0).sub(fb).mul(w).add(hb)
                    .lanewise(VectorOperators.ASHR, 16);
            c.and(0xFF000000).or(r).or(g).or(bl).intoArray(color, x);
        }
    }

    /**
     * The same, by a cheaper arithmetic that the Vector API offers and C2's loop vectorizer does not:
     * 4096 f = clamp(4096·end/(end - start) - b/q, 0, 4096.5) by lane minimum and maximum, then
     * truncated to an int by a lane conversion (pixels within one 4096th of the factor of the pass's;
     * not checked).
     */
    static void converted(float[] depth, int[] color, int from, int bound, float a, float b, int fr, int fg, int fb) {
        int hr = ONE * 8 + fr * ONE;
        int hg = ONE * 8 + fg * ONE;
        int hb = ONE * 8 + fb * ONE;
        FloatVector bv = FloatVector.broadcast(FS, b);
        float ab = a * b + 0.5f;
        for (int x = from; x < bound; x += FS.length()) {
            FloatVector q = FloatVector.fromArray(FS, depth, x);
            FloatVector f = bv.div(q).neg().add(ab).max(0.5f).min(ONE + 0.5f);
            IntVector w = (IntVector) f.convert(VectorOperators.F2I, 0);
            IntVector c = IntVector.fromArray(IS, color, x);
            IntVector r = c.lanewise(VectorOperators.ASHR, 12).and(0xFF0).sub(fr).mul(w).add(hr)
                    .lanewise(VectorOperators.ASHR, 16).lanewise(VectorOperators.LSHL, 16);
            IntVector g = c.lanewise(VectorOperators.ASHR, 4).and(0xFF0).sub(fg).mul(w).add(hg)
                    .lanewise(VectorOperators.ASHR, 16).lanewise(VectorOperators.LSHL, 8);
            IntVector bl = c.lanewise(VectorOperators.LSHL, 4).and(0xFF0).sub(fb).mul(w).add(hb)
                    .lanewise(VectorOperators.ASHR, 16);
            c.and(0xFF000000).or(r).or(g).or(bl).intoArray(color, x);
        }
    }

    public static void main(String[] args) {
        int rounds = 30;
        if (args.length > 0) {
            try {
                rounds = Integer.parseInt(args[0]);
            } catch (NumberFormatException e) {
                rounds = 0;
            }
            if (rounds < 1) {
                System.err.println("FogFloor: ROUNDS must be a positive whole number, not '" + args[0] + "'");
                System.exit(2);
            }
        }
        int w = 1920;
        int h = 1080;
        SceneAsset s = DemoScenes.byName("demo").orElseThrow();
        Framebuffer plain = new Framebuffer(w, h);
        Draws draws = new Draws();
        draws.add(s.mesh(), s.textureArray(), s.camera().viewProjection(new Viewport(w, h)));
        try (FrameRenderer r = new FrameRenderer(1)) {
            r.render(draws, RenderSettings.defaults(), plain);
        }
        Colour haze = new Colour(0.6, 0.7, 0.8);
        Fog fog = Fog.linear(5, 60, haze);
        FogPass pass = new FogPass(fog);
        FogPass.Rows rows = new FogPass.Rows();
        float a = (float) fog.end();
        float b = (float) (ONE / (fog.end() - fog.start()));
        int fr = (int) Math.round(haze.r() * 255 * 16);
        int fg = (int) Math.round(haze.g() * 255 * 16);
        int fb = (int) Math.round(haze.b() * 255 * 16);
        // Each row's covered run, found once (the pass finds it each time; that costs little).
        int[] first = new int[h];
        int[] end = new int[h];
        long covered = 0;
        for (int y = 0; y < h; y++) {
            int x0 = y * w;
            int x1 = x0 + w;
            while (x0 < x1 && plain.depth()[x0] == 0) {
                x0++;
            }
            while (x1 > x0 && plain.depth()[x1 - 1] == 0) {
                x1--;
            }
            first[y] = x0;
            end[y] = x1;
            covered += x1 - x0;
        }
        Framebuffer frame = new Framebuffer(w, h);
        Framebuffer ref = new Framebuffer(w, h);
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        double[][] ms = new double[3][rounds];
        for (int round = -15; round < rounds; round++) {
            for (int v = 0; v < 3; v++) {
                long t = 0;
                for (int y = 0; y < h; y += BAND) {
                    int y1 = Math.min(h, y + BAND);
                    System.arraycopy(plain.colour(), y * w, frame.colour(), y * w, (y1 - y) * w);
                    System.arraycopy(plain.depth(), y * w, frame.depth(), y * w, (y1 - y) * w);
                    long t0 = cpu.getCurrentThreadCpuTime();
                    if (v == 0) {
                        pass.apply(frame, y, y1, rows);
                    } else {
                        for (int yy = y; yy < y1; yy++) {
                            int bound = first[yy] + FS.loopBound(end[yy] - first[yy]);
                            if (v == 1) {
                                linear(frame.depth(), frame.colour(), first[yy], bound, a, b, fr, fg, fb);
                            } else {
                                converted(frame.depth(), frame.colour(), first[yy], bound, a, b, fr, fg, fb);
                            }
                            for (int x = bound; x < end[yy]; x++) {
                                frame.colour()[x] = pass.fogged(frame.colour()[x], pass.weight(frame.depth()[x]));
                            }
                        }
                    }
                    t += cpu.getCurrentThreadCpuTime() - t0;
                }
                if (round >= 0) {
                    ms[v][round] = t / 1e6;
                }
                if (round == -1 && v == 0) {
                    System.arraycopy(frame.colour(), 0, ref.colour(), 0, w * h);
                }
                if (round == -1 && v == 1 && !Arrays.equals(frame.colour(), ref.colour())) {
                    System.err.println("FogFloor: the fused loop's pixels differ from FogPass's");
                    System.exit(1);
                }
            }
        }
        String[] names = {"FogPass           ", "fused, same sums  ", "fused, min/max/F2I"};
        for (int v = 0; v < 3; v++) {
            double[] m = ms[v].clone();
            Arrays.sort(m);
            System.out.printf(Locale.ROOT, "%s median %.2f ms (min %.2f, max %.2f), %.2f ns a covered pixel%n",
                    names[v], m[rounds / 2], m[0], m[rounds - 1], m[rounds / 2] * 1e6 / covered);
        }
        long beyond = 0;
        for (float q : plain.depth()) {
            beyond += q > 0 && 1 / q > fog.start() ? 1 : 0;
        }
        inCache(rounds, pass, a, b, fr, fg, fb, covered, beyond);
    }

    /**
     * The same two loops over one row of 1920 pixels that stays in the L1 data cache (7.5 KB of depths
     * and 7.5 KB of colours), every pixel covered and blended (depths from 5 to 60 view units, random
     * colours): the arithmetic alone, with no cache misses at all. Each call first copies the row's
     * colours and depths back in (both variants alike; the copy alone is timed too and subtracted).
     * Prints ns a pixel and what the demo's covered pixels, and those beyond the fog's start, would cost
     * at that rate.
     */
    private static void inCache(int rounds, FogPass pass, float a, float b, int fr, int fg, int fb,
                                long covered, long beyond) {
        int w = 1920;
        int calls = 2000;
        java.util.Random random = new java.util.Random(1);
        Framebuffer src = new Framebuffer(w, 1);
        Framebuffer row = new Framebuffer(w, 1);
        for (int x = 0; x < w; x++) {
            src.depth()[x] = (float) (1 / (5 + 55 * random.nextDouble()));
            src.colour()[x] = random.nextInt() | 0xFF000000;
        }
        FogPass.Rows rows = new FogPass.Rows();
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        double[][] ns = new double[3][rounds];
        for (int round = -15; round < rounds; round++) {
            for (int v = 0; v < 3; v++) {
                long t0 = cpu.getCurrentThreadCpuTime();
                for (int c = 0; c < calls; c++) {
                    System.arraycopy(src.colour(), 0, row.colour(), 0, w);
                    System.arraycopy(src.depth(), 0, row.depth(), 0, w);
                    if (v == 0) {
                        pass.apply(row, 0, 1, rows);
                    } else if (v == 1) {
                        linear(row.depth(), row.colour(), 0, w, a, b, fr, fg, fb);
                    }
                }
                if (round >= 0) {
                    ns[v][round] = (cpu.getCurrentThreadCpuTime() - t0) / (double) calls / w;
                }
            }
        }
        double copy = median(ns[2]);
        System.out.printf(Locale.ROOT, "one row in the L1 cache (every pixel blended), %d rounds of %d calls, CPU ns a pixel:%n",
                rounds, calls);
        String[] names = {"FogPass           ", "fused, same sums  "};
        for (int v = 0; v < 2; v++) {
            double[] m = ns[v].clone();
            Arrays.sort(m);
            double net = m[rounds / 2] - copy;
            System.out.printf(Locale.ROOT, "%s median %.3f (min %.3f, max %.3f) less the copy's %.3f = %.3f ns a pixel:"
                            + " the demo's %d covered pixels %.2f ms, its %d beyond the start %.2f ms%n",
                    names[v], m[rounds / 2], m[0], m[rounds - 1], copy, net, covered, net * covered / 1e6,
                    beyond, net * beyond / 1e6);
        }
    }

    private static double median(double[] values) {
        double[] m = values.clone();
        Arrays.sort(m);
        return m[m.length / 2];
    }
}
