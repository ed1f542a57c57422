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
 * surviving fragment is the pixel's, and its depth is the stored one. No pixel divides or calls
 * {@code exp}: f comes from a table indexed by the stored 1/w's float bits, {@link #STEPS_PER_OCTAVE}
 * entries for each doubling of 1/w, holding f in 4096ths at each entry's first value, and is
 * interpolated linearly between two entries by the next 13 bits, in integers. Within an entry 1/w
 * changes by at most 0.1 %, so the interpolation itself is within 1e-6 of f for every equation (f is
 * smooth in 1/w there: the error is the entry's width squared times f's second derivative, over 8);
 * with the entries' rounding and the integer step, f is within 1/2048. Linear fog is not smooth where
 * it meets its clamps, at its start and its end: the two entries holding those depths are marked, and
 * their pixels divide ({@code f = (end - z)/(end - start)}). Every channel is then within 0.15 of the
 * exact blend of the stored colour (the fog's colour in 16ths of a step) before rounding to the
 * nearest of 255 steps. 1/w outside the
 * table (z below 2^-10 or above 2^20 view-space units) is taken at the table's nearest end. One
 * instance per fog: immutable, shared by the threads.
 */
public final class FogPass {
    /** Table entries per doubling of 1/w. */
    static final int STEPS_PER_OCTAVE = 1024;
    /** Float bits below the table's index: 23 mantissa bits less log2 of the steps. */
    private static final int SHIFT = 23 - 10;
    private static final int FRACTION = (1 << SHIFT) - 1;
    /** The smallest 1/w in the table, 2^-20 (z = 2^20), and the largest, 2^10 (z = 2^-10). */
    private static final int FIRST = Float.floatToRawIntBits(0x1p-20f) >> SHIFT;
    private static final int LAST = Float.floatToRawIntBits(0x1p10f) >> SHIFT;
    /** The blend's fixed point: f in 4096ths. */
    private static final int ONE = 4096;

    private final Fog fog;
    /** round(4096 f) at the first 1/w of each entry, and one entry more to interpolate towards. */
    private final int[] table;
    /** The fog colour in 16ths of a step of 1/255. */
    private final int fr;
    private final int fg;
    private final int fb;
    /** Linear fog: f = a - b·(1/q), for the marked entries. */
    private final double a;
    private final double b;
    /** An entry whose pixels compute f exactly. */
    private static final int EXACT = -1;

    /** Prepares the pass of {@code fog}. */
    public FogPass(Fog fog) {
        this.fog = fog;
        Colour c = fog.colour();
        fr = channel(c.r());
        fg = channel(c.g());
        fb = channel(c.b());
        table = new int[LAST - FIRST + 2];
        for (int k = 0; k < table.length; k++) {
            float q = Float.intBitsToFloat((FIRST + k) << SHIFT);
            table[k] = (int) Math.round(ONE * fog.factor(1.0 / q));
        }
        boolean linear = fog.mode() == Fog.Mode.LINEAR;
        a = linear ? fog.end() / (fog.end() - fog.start()) : 0;
        b = linear ? 1 / (fog.end() - fog.start()) : 0;
        if (linear) {
            mark(fog.start());
            mark(fog.end());
        }
    }

    /** Marks the entry holding depth z, where the linear factor meets a clamp. */
    private void mark(double z) {
        float q = (float) (1 / z);
        if (q > 0 && Float.isFinite(q)) {
            int e = (Float.floatToRawIntBits(q) >> SHIFT) - FIRST;
            if (e >= 0 && e < table.length - 1) {
                table[e] = EXACT;
            }
        }
    }

    private static int channel(double v) {
        return (int) Math.round(Math.min(v, 1) * 255 * 16);
    }

    /** The linear factor at stored depth q, in 4096ths, computed. */
    private int exact(float q) {
        double f = a - b / q;
        return (int) ((f < 0 ? 0 : f > 1 ? 1 : f) * ONE + 0.5);
    }

    /** The fog this pass applies. */
    public Fog fog() {
        return fog;
    }

    /** The factor this pass applies to a pixel of stored depth {@code q} (1/w, positive), in 4096ths. */
    int weight(float q) {
        int bits = Float.floatToRawIntBits(q);
        int e = (bits >> SHIFT) - FIRST;
        int last = table.length - 2;
        if (e < 0 || e > last) {
            int k = table[e < 0 ? 0 : last];
            return k >= 0 ? k : exact(q);
        }
        if (table[e] == EXACT || table[e + 1] == EXACT) {
            return exact(q);
        }
        return table[e] + (((table[e + 1] - table[e]) * (bits & FRACTION)) >> SHIFT);
    }

    /**
     * Fogs rows {@code [y0, y1)} of {@code frame}.
     *
     * @param frame the frame, its rows filled
     * @param y0    the first row
     * @param y1    one past the last row
     */
    public void apply(Framebuffer frame, int y0, int y1) {
        int[] color = frame.colour();
        float[] depth = frame.depth();
        int[] t = table;
        int last = t.length - 2;
        int from = y0 * frame.width();
        int to = y1 * frame.width();
        for (int i = from; i < to; i++) {
            float q = depth[i];
            if (q > 0) {
                int bits = Float.floatToRawIntBits(q);
                int e = (bits >> SHIFT) - FIRST;
                int k;
                if (e >= 0 && e <= last) {
                    int k0 = t[e];
                    int k1 = t[e + 1];
                    k = (k0 | k1) >= 0 ? k0 + (((k1 - k0) * (bits & FRACTION)) >> SHIFT) : exact(q);
                } else {
                    k = t[e < 0 ? 0 : last];
                    k = k >= 0 ? k : exact(q);
                }
                if (k != ONE) {
                    int h = ONE - k;
                    int argb = color[i];
                    int r = (((argb >> 12) & 0xFF0) * k + fr * h + ONE * 8) >> 16;
                    int g = (((argb >> 4) & 0xFF0) * k + fg * h + ONE * 8) >> 16;
                    int bl = (((argb << 4) & 0xFF0) * k + fb * h + ONE * 8) >> 16;
                    color[i] = (argb & 0xFF000000) | (r << 16) | (g << 8) | bl;
                }
            }
        }
    }
}
