package dev.trisect.light;

import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.Framebuffer;

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
 * <p>A row at a time, in two steps. The first finds each pixel's f in 4096ths into a row of
 * factors; the second blends a copy of the row's colours by them in three small loops of integer
 * arithmetic over arrays at one index, which C2 (JDK 17) compiles to vector instructions (it
 * vectorizes no float-to-int conversion and no table look-up, so the first step stays scalar). Linear
 * fog divides: 4096 f = 4096 (end - z)/(end - start) = a - b/(1/w) in floats (z = w, the eye depth),
 * rounded to the nearest 4096th and clamped; with E = end/(end - start), a's rounding is at most
 * E·2^-12 of a 4096th and the quotient's (b's and the division's) at most E·2^-11, so the floats move
 * it by at most 1.5·E·2^-11 of a 4096th (under 0.5 of one while E is under 680). Exp and exp2 look f up in a table
 * indexed by the stored 1/w's float bits, {@link #STEPS_PER_OCTAVE} entries for each doubling of 1/w,
 * holding round(4096 f) at the middle of each entry, in chars (120 KB, of which a scene's depths touch
 * a few octaves, 4 KB each). An entry spans at most 2^-11 of its 1/w, so at most 2^-12 of ln z from
 * its middle, and f changes with ln z by at most 1/e (exp: zd·e^(-zd)) or 2/e (exp2:
 * 2(zd)²·e^(-(zd)²)): f is within 0.74/4096 of exact, 1.24/4096 with the entry's rounding. Every
 * channel is then within 0.1 of the exact blend of the stored colour (the fog's colour in 16ths of a
 * step) before rounding to the nearest of 255 steps. 1/w outside the table (z below 2^-10 or above
 * 2^20 view-space units) is taken at the table's nearest end. One instance per fog: immutable, shared
 * by the threads; each thread brings its {@link Rows}.
 */
public final class FogPass {
    /** Table entries per doubling of 1/w (exp, exp2). */
    static final int STEPS_PER_OCTAVE = 2048;
    /** Float bits below the table's index: 23 mantissa bits less log2 of the steps. */
    private static final int SHIFT = 23 - 11;
    /** The smallest 1/w in the table, 2^-20 (z = 2^20), and the largest, 2^10 (z = 2^-10). */
    private static final int FIRST = Float.floatToRawIntBits(0x1p-20f) >> SHIFT;
    private static final int LAST = Float.floatToRawIntBits(0x1p10f) >> SHIFT;
    /** The blend's fixed point: f in 4096ths. */
    private static final int ONE = 4096;

    private final Fog fog;
    /** Exp, exp2: round(4096 f) at the middle of each entry; null for linear fog. */
    private final char[] table;
    /** Linear fog: 4096 f + 1/2 = near - far / (1/w). */
    private final float near;
    private final float far;
    /** The fog colour in 16ths of a step of 1/255. */
    private final int fr;
    private final int fg;
    private final int fb;

    /** A thread's working rows: the factors, the colours and the fogged colours of one frame row. */
    public static final class Rows {
        private int[] factors = new int[0];
        private int[] colours = new int[0];
        private int[] out = new int[0];

        /** Empty rows; they grow to the frame's width on first use. */
        public Rows() {
        }

        private void fit(int width) {
            if (factors.length < width) {
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
        if (fog.mode() == Fog.Mode.LINEAR) {
            table = null;
            near = (float) (ONE * fog.end() / (fog.end() - fog.start()) + 0.5);
            far = (float) (ONE / (fog.end() - fog.start()));
        } else {
            table = new char[LAST - FIRST + 1];
            for (int k = 0; k < table.length; k++) {
                double q0 = Float.intBitsToFloat((FIRST + k) << SHIFT);
                double q1 = Float.intBitsToFloat((FIRST + k + 1) << SHIFT);
                table[k] = (char) Math.round(ONE * fog.factor(2 / (q0 + q1)));
            }
            near = 0;
            far = 0;
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
        int[] k = new int[1];
        factors(new float[] {q}, 0, 1, k);
        return k[0];
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
            while (from < to && depth[from] == 0) {
                from++;
            }
            while (to > from && depth[to - 1] == 0) {
                to--;
            }
            int n = to - from;
            if (n > 0) {
                factors(depth, from, n, k);
                System.arraycopy(color, from, c, 0, n);
                blend(c, k, out, n);
                System.arraycopy(out, 0, color, from, n);
            }
        }
    }

    /** The factors of depths {@code [from, from + n)}, in 4096ths, into {@code k[0, n)}; 1 for the background. */
    private void factors(float[] depth, int from, int n, int[] k) {
        if (table == null) {
            float a = near;
            float b = far;
            for (int x = 0; x < n; x++) {
                float q = depth[from + x];
                if (q > 0) {
                    k[x] = Math.min(Math.max((int) (a - b / q), 0), ONE);
                } else {
                    k[x] = ONE;
                }
            }
        } else {
            char[] t = table;
            int last = t.length - 1;
            for (int x = 0; x < n; x++) {
                float q = depth[from + x];
                int e = Math.min(Math.max((Float.floatToRawIntBits(q) >> SHIFT) - FIRST, 0), last);
                k[x] = q > 0 ? t[e] : ONE;
            }
        }
    }

    /**
     * Blends colours {@code c[0, n)} towards the fog by factors {@code k[0, n)} into {@code out[0, n)},
     * per channel {@code (16·C·k + F·(4096 - k) + 2^15) >> 16} with F the fog's channel in 16ths,
     * written as {@code ((16·C - F)·k + F·4096 + 2^15) >> 16}: one multiply a channel; k = 4096 leaves C
     * as it is. One small loop a channel over arrays at one index: C2 (JDK 17) vectorizes each, where
     * it leaves one loop of all three channels scalar once it is inlined into its caller (measured).
     */
    private void blend(int[] c, int[] k, int[] out, int n) {
        int f = fr;
        int half = ONE * 8 + f * ONE;
        for (int x = 0; x < n; x++) {
            out[x] = (c[x] & 0xFF000000) | ((((c[x] >> 12) & 0xFF0) - f) * k[x] + half) >> 16 << 16;
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
