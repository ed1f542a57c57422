package dev.trisect.light;

import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.Framebuffer;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.util.Arrays;

/**
 * Fog over filled rows of a frame, per pixel: each covered pixel's colour C becomes
 * {@code f·C + (1 - f)·fog} with f the fog factor ({@link Fog#factor}) of its eye-space depth
 * z = 1 / (1/w), read back from the depth buffer (for a perspective projection, clip w is the
 * eye-space distance along the view axis: OpenGL's fog coordinate |z_e|, OpenGL 2.1 section 3.10). The
 * background (depth 0) is not fogged, as OpenGL fogs fragments, not the clear colour.
 *
 * <p>For opaque surfaces this is fogging every fragment before the depth test, as OpenGL does: the
 * surviving fragment is the pixel's, and its depth is the stored one.
 *
 * <p>A row at a time, between its first and last covered pixels (found by {@link Arrays#mismatch}
 * against a row of zeros, which the JDK compares many pixels at a time), in loops over arrays at one
 * index that C2 (JDK 17) compiles to vector instructions. C2 vectorizes no conversion between floats
 * and ints (not even the reading of a float's bits), no table look-up and no float minimum or maximum.
 * So the factor is found in floats as the sum {@code 4096 f + 1.5·2^23}: adding 1.5·2^23 to a float
 * from 0 to 2^22 rounds it to the nearest integer (ties to even), which the sum's low bits then hold.
 * The sums' bits reach an int array by two bulk copies through a direct buffer seen as floats and as
 * ints (the JDK copies memory; a loop of {@code Float.floatToRawIntBits} stays scalar, a pixel a
 * cycle); the first of the blend's loops turns them into f in 4096ths by integer operations
 * ({@link #factor}), and the blend is integer arithmetic, one loop a channel.
 *
 * <p>Linear fog: 4096 f = 4096 (end - z)/(end - start) = b·(end - z) in floats, z = 1/(1/w) (= w, the
 * eye depth), the difference clamped at 0 by {@code (x + |x|)/2} (exact; so no far pixel overflows)
 * and the product at 4096 by {@code (x + 4096 - |x - 4096|)/2} (within 2^-12 below 4096; above it,
 * exactly 4096 after the rounding while the product is under 2^24, that is end/(end - start) under
 * 4096), then rounded to the nearest integer. With E = end/(end - start), end's and z's roundings move
 * 4096 f by at most E·2^-12 of a 4096th each, the difference's, b's, the product's and the clamp's by
 * at most 2^-12 each, so by at most E·2^-11 + 2^-10 before it is rounded: under 0.1 of a 4096th while E
 * is under 200. The background's 1/0 is infinite, and its sum NaN. A row all nearer than the start
 * (its sums all exactly 4096 + 1.5·2^23, found by {@link Arrays#mismatch} against such a row: the
 * bottom rows of a floor, a scene before the fog begins) is left as it is at once.
 * <br>Exp: f = e^-x, x = density·z. With u = (16/density)/z = 16/x (one multiply: z is 1/(1/w)), e^(x/16)
 * = e^(1/u) is taken by its Taylor polynomial of degree 4, p(1/u) = 1 + 1/u + 1/(2u²) + 1/(6u³) + 1/(24u⁴),
 * so e^(-x/16) = u⁴/Q(u) with Q(u) = u⁴ + u³ + u²/2 + u/6 + 1/24, computed as u⁵/(u·Q(u)) (one division;
 * 0/0, NaN, for the background's u = 0; a far pixel's tiny u gives 0), and raised to the 16th power
 * by four squarings.
 * <br>Exp2: f = e^-(x²); with z = 1/(1/w) (infinite only for the background, which is marked by adding
 * z - z, NaN there and 0 elsewhere) and s = (density/4)·z = x/4, e^(x²/16) = e^(s²) by the same
 * polynomial, f = 1/p(s²)^16 (a second division; an overflowing s or power gives f = 0).
 * <br>The polynomial falls short of e^v (v = x/16 or x²/16) by at most v⁵/120·e^v, so f is at most
 * e^-16v·16·v⁵/120 too large absolutely: in 4096ths at most 4096·16/120·max(e^-16v·v⁵) = 0.011 (at
 * v = 5/16). The floats round some 17 times before the squarings, each by at most 2^-24 relatively and
 * each multiplied by 16 by them, and 15 times in them: at most 290·2^-24 relatively, 0.071 of a 4096th.
 * So 4096 f is within 0.082 of exact before it is rounded (measured over z, in float arithmetic: at
 * most 0.027 exp, 0.009 exp2), within 0.59 after.
 *
 * <p>So f is within 0.59/4096 of the equation (linear: 0.5 + E·2^-11 + 2^-10, under 0.6 while E is
 * under 200), and every channel is within 0.1 of the exact blend of the stored colour (the fog's colour
 * in 16ths of a step) before rounding to the nearest of 255 steps. Every depth z below 2^127 view
 * units gives a finite 1/(1/w), so no covered pixel reads as the background (under exp fog, none while
 * also density·z is under 2^149·16: u = 16/(density·z) stays above 0). One instance per fog: immutable, shared
 * by the threads; each thread brings its {@link Rows}.
 */
public final class FogPass {
    /** The blend's fixed point: f in 4096ths. */
    private static final int ONE = 4096;
    /** 1.5·2^23: a float from 0 to 2^22 added to it is rounded to an integer, held in the sum's low bits. */
    private static final float ROUND = 0x1.8p23f;
    private static final int ROUND_BITS = Float.floatToRawIntBits(ROUND);

    private final Fog fog;
    /** Linear: end and 4096/(end - start); exp: 16/density, 0; exp2: density/4, 0. */
    private final float a;
    private final float b;
    /** The fog colour in 16ths of a step of 1/255. */
    private final int fr;
    private final int fg;
    private final int fb;

    /** A thread's working rows: one frame row's depths (then sums), factors, colours and fogged colours. */
    public static final class Rows {
        private float[] depths = new float[0];
        /** One row of bytes in the platform's order, seen as floats and as ints. */
        private FloatBuffer floats;
        private IntBuffer ints;
        /** A row of zeros, to find a row's first covered pixel against. */
        private float[] zeros = new float[0];
        /** A row of linear fog's sums for pixels nearer than its start, 4096 + 1.5·2^23. */
        private float[] near = new float[0];
        private int[] factors = new int[0];
        private int[] colours = new int[0];
        private int[] out = new int[0];

        /** Empty rows; they grow to the frame's width on first use. */
        public Rows() {
        }

        private void fit(int width) {
            if (zeros.length < width) {
                depths = new float[width];
                ByteBuffer bytes = ByteBuffer.allocateDirect(width * Float.BYTES).order(ByteOrder.nativeOrder());
                floats = bytes.asFloatBuffer();
                ints = bytes.asIntBuffer();
                zeros = new float[width];
                near = new float[width];
                Arrays.fill(near, ONE + ROUND);
                factors = new int[width];
                colours = new int[width];
                out = new int[width];
            }
        }
    }

    /** Prepares the pass of {@code fog}. */
    public FogPass(Fog fog) {
        this.fog = fog;
        Colour c = fog.colour();
        fr = channel(c.r());
        fg = channel(c.g());
        fb = channel(c.b());
        switch (fog.mode()) {
            case LINEAR -> {
                a = (float) fog.end();
                b = (float) (ONE / (fog.end() - fog.start()));
            }
            case EXP -> {
                a = (float) (16 / fog.density());
                b = 0;
            }
            default -> {
                a = (float) (fog.density() / 4);
                b = 0;
            }
        }
    }

    private static int channel(double v) {
        return (int) Math.round(Math.min(v, 1) * 255 * 16);
    }

    /** The fog this pass applies. */
    public Fog fog() {
        return fog;
    }

    /**
     * The factor this pass applies to a pixel of stored depth {@code q}, in 4096ths (4096 leaves the
     * colour as it is): what the pass finds for one pixel, for a fragment whose depth is known before
     * it is written (a screen-aligned quad's, {@code raster/QuadRaster}).
     *
     * @param q 1/w, the inverse of the eye-space depth; 0 (the background, or no depth) is not fogged
     * @return f in 4096ths, 0..4096
     */
    public int weight(float q) {
        float sum = switch (fog.mode()) {
            case LINEAR -> linear(a, b, q);
            case EXP -> exp(a, q);
            default -> exp2(a, q);
        };
        return factor(Float.floatToRawIntBits(sum));
    }

    /**
     * One colour blended towards the fog by factor {@code k}, exactly as the pass blends a pixel (see
     * {@link #blend}): {@code fogged(C, weight(q))} is the pass's result for colour C at depth q.
     *
     * @param argb the colour; its alpha is kept
     * @param k    the factor in 4096ths, 0..4096 ({@link #weight})
     * @return the fogged colour, ARGB
     */
    public int fogged(int argb, int k) {
        int r = ((((argb >> 12) & 0xFF0) - fr) * k + ONE * 8 + fr * ONE) >> 16;
        int g = ((((argb >> 4) & 0xFF0) - fg) * k + ONE * 8 + fg * ONE) >> 16;
        int b = ((((argb << 4) & 0xFF0) - fb) * k + ONE * 8 + fb * ONE) >> 16;
        return (argb & 0xFF000000) | r << 16 | g << 8 | b;
    }

    /**
     * Fogs rows {@code [y0, y1)} of {@code frame}, with working rows of its own.
     *
     * @param frame the frame, its rows filled
     * @param y0    the first row
     * @param y1    one past the last row
     */
    public void apply(Framebuffer frame, int y0, int y1) {
        apply(frame, y0, y1, new Rows());
    }

    /**
     * Fogs rows {@code [y0, y1)} of {@code frame}.
     *
     * @param frame the frame, its rows filled
     * @param y0    the first row
     * @param y1    one past the last row
     * @param rows  the calling thread's working rows
     */
    public void apply(Framebuffer frame, int y0, int y1, Rows rows) {
        int width = frame.width();
        rows.fit(width);
        int[] color = frame.colour();
        float[] depth = frame.depth();
        int[] k = rows.factors;
        int[] c = rows.colours;
        int[] out = rows.out;
        for (int y = y0; y < y1; y++) {
            // The background at the row's ends (the sky around a scene, empty rows) is skipped.
            int from = y * width;
            int to = from + width;
            int first = Arrays.mismatch(depth, from, to, rows.zeros, 0, width);
            if (first < 0) {
                continue;
            }
            from += first;
            // The last covered pixel: from the right in blocks of 512, 128, 32 and 8 pixels, then one by one.
            for (int block = 512; block >= 8; block >>= 2) {
                while (to - block > from && Arrays.mismatch(depth, to - block, to, rows.zeros, 0, block) < 0) {
                    to -= block;
                }
            }
            while (to > from && depth[to - 1] == 0) { // (a -0 depth, differing in bits only, may end here)
                to--;
            }
            int n = to - from;
            System.arraycopy(depth, from, rows.depths, 0, n);
            sums(rows.depths, n);
            if (fog.mode() == Fog.Mode.LINEAR && Arrays.mismatch(rows.depths, 0, n, rows.near, 0, n) < 0) {
                continue; // Every pixel is nearer than the fog's start (the sums are exactly 4096 + 1.5·2^23).
            }
            // The sums' bits into ints: a float-to-int move that C2 does not vectorize as a loop, done as
            // two bulk copies through a buffer seen as floats and as ints (memory copies in the JDK).
            rows.floats.put(0, rows.depths, 0, n);
            rows.ints.get(0, k, 0, n);
            System.arraycopy(color, from, c, 0, n);
            blend(c, k, out, n);
            System.arraycopy(out, 0, color, from, n);
        }
    }

    /**
     * Replaces depths {@code q[0, n)} by the sums {@code 4096 f + 1.5·2^23} (see the class comment);
     * NaN for the background. One loop per equation, each vectorized.
     */
    private void sums(float[] q, int n) {
        float a = this.a;
        float b = this.b;
        switch (fog.mode()) {
            case LINEAR -> {
                for (int x = 0; x < n; x++) {
                    q[x] = linear(a, b, q[x]);
                }
            }
            case EXP -> {
                for (int x = 0; x < n; x++) {
                    q[x] = exp(a, q[x]);
                }
            }
            default -> {
                for (int x = 0; x < n; x++) {
                    q[x] = exp2(a, q[x]);
                }
            }
        }
    }

    /**
     * Linear fog's sum at depth q, a = end: {@code b·(end - 1/q)} with the difference clamped at 0 by
     * {@code (x + |x|)/2} (so a far pixel's product cannot overflow) and the product at 4096 by
     * {@code (x + 4096 - |x - 4096|)/2}, rounded by adding 1.5·2^23; NaN for q = 0 (1/q infinite).
     */
    private static float linear(float a, float b, float q) {
        float t = a - 1 / q;
        float f = (t + Math.abs(t)) * 0.5f * b;
        return ((f + ONE) - Math.abs(f - ONE)) * 0.5f + ROUND;
    }

    /** Exp fog's sum at depth q, a = 16/density: {@code 4096 (u⁵/(u·Q(u)))^16 + 1.5·2^23}, u = a·q; NaN for q = 0. */
    private static float exp(float a, float q) {
        float u = q * a;
        float u2 = u * u;
        float e = (u2 * u2 * u) / (u * (1 / 24f + u * (1 / 6f + u * (1 / 2f + u * (1 + u)))));
        e *= e;
        e *= e;
        e *= e;
        return ONE * (e * e) + ROUND;
    }

    /**
     * Exp2 fog's sum at depth q, a = density/4: {@code 4096/p(s²)^16 + 1.5·2^23 + (z - z)}, z = 1/q,
     * s = a·z; NaN for q = 0 (z infinite), 0 when only s or p overflows (far pixels).
     */
    private static float exp2(float a, float q) {
        float z = 1 / q;
        float s = a * z;
        float v = s * s;
        float p = 1 + v * (1 + v * (1 / 2f + v * (1 / 6f + v * (1 / 24f))));
        p *= p;
        p *= p;
        p *= p;
        return ONE / (p * p) + ROUND + (z - z);
    }

    /**
     * The factor in 4096ths, 0..4096, from the bits of a sum {@code 4096 f + 1.5·2^23}, by integer
     * operations only: sums from 1.5·2^23 to 1.5·2^23 + 4096 give their integer part, greater sums
     * 4096, and so does NaN (the background), whatever its sign.
     */
    private static int factor(int bits) {
        int k = bits - ROUND_BITS;
        int above = ((ONE - k) | k) >> 31;
        return k ^ ((k ^ ONE) & above);
    }

    /**
     * Blends colours {@code c[0, n)} towards the fog by the factors whose sums' bits are {@code k[0, n)}
     * (the first loop turns them into factors, {@link #factor}, in place) into {@code out[0, n)},
     * per channel {@code (16·C·k + F·(4096 - k) + 2^15) >> 16} with F the fog's channel in 16ths,
     * written as {@code ((16·C - F)·k + F·4096 + 2^15) >> 16}: one multiply a channel; k = 4096 leaves C
     * as it is. One small loop a channel over arrays at one index: C2 (JDK 17) vectorizes each, where
     * it leaves one loop of all three channels scalar once it is inlined into its caller (measured).
     */
    private void blend(int[] c, int[] k, int[] out, int n) {
        int f = fr;
        int half = ONE * 8 + f * ONE;
        for (int x = 0; x < n; x++) {
            int w = factor(k[x]);
            k[x] = w;
            out[x] = (c[x] & 0xFF000000) | ((((c[x] >> 12) & 0xFF0) - f) * w + half) >> 16 << 16;
        }
        f = fg;
        half = ONE * 8 + f * ONE;
        for (int x = 0; x < n; x++) {
            out[x] |= ((((c[x] >> 4) & 0xFF0) - f) * k[x] + half) >> 16 << 8;
        }
        f = fb;
        half = ONE * 8 + f * ONE;
        for (int x = 0; x < n; x++) {
            out[x] |= ((((c[x] << 4) & 0xFF0) - f) * k[x] + half) >> 16;
        }
    }
}
