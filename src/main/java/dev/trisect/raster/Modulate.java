package dev.trisect.raster;

/**
 * GL_MODULATE of an RGBA texel by a fragment colour whose alpha is 1 (OpenGL 1.x section 3.8.13,
 * table 3.22: C = Cf Ct, A = At): each colour channel {@code c} of the texel becomes {@code c} times
 * the fragment's channel {@code f} in [0, 1], converted back to 8 bits by rounding to nearest
 * (section 2.14.9's conversion of a colour component to fixed point) — in integers: {@code f} is
 * first taken to 16 fractional bits, {@code f16 = (int) (f * 65536 + 0.5)} kept within 0..65536, then
 * the channel is {@code (c * f16 + 32768) >> 16}. That differs from {@code (int) (c * f + 0.5)} only
 * where {@code c * f} lies within {@code c / 131072} (less than 0.002) of a tie, by one; a colour of
 * exactly 0 or 1 gives 0 or {@code c} exactly. Integers, not a double product, because converting the
 * int channel to a double (cvtsi2sd) writes only part of its register: the pixel loops then wait on
 * the register's last writer, in the per-pixel path a division (docs/performance/filtering.md, "The
 * per-pixel loop's false dependency"). The clamp keeps within range a varying a hair outside the
 * corners' range: a pixel centre just beyond its triangle's exact edge (coverage is decided on snapped
 * corners).
 */
final class Modulate {
    /** 1 in 16 fractional bits. */
    static final int ONE = 1 << 16;
    /** A half in 16 fractional bits: rounds the product to nearest. */
    private static final int HALF = ONE >> 1;

    private Modulate() {
    }

    /** The texel {@code argb} times the colour (r, g, b), alpha kept. */
    static int argb(int argb, double r, double g, double b) {
        return argb16(argb, f16(r), f16(g), f16(b));
    }

    /**
     * The texel {@code argb} times the colour (r16, g16, b16) given by {@link #f16}, alpha kept. Each
     * product plus a half, at most 255 * 2^16 + 2^15 &lt; 2^24, is masked into place rather than shifted
     * down and back: fewer operations in the pixel loops.
     */
    static int argb16(int argb, int r16, int g16, int b16) {
        return argb & 0xFF000000 | (argb >>> 16 & 0xFF) * r16 + HALF & 0xFF0000
                | ((argb >>> 8 & 0xFF) * g16 + HALF) >>> 8 & 0xFF00 | ((argb & 0xFF) * b16 + HALF) >>> 16;
    }

    /** One channel, 0..255, times {@code f}, rounded to nearest and kept within 0..255. */
    static int channel(int c, double f) {
        return c * f16(f) + HALF >> 16;
    }

    /** A colour channel {@code f} in [0, 1] in 16 fractional bits, rounded, kept within 0..{@link #ONE}. */
    static int f16(double f) {
        return Math.max(0, Math.min(ONE, (int) (f * ONE + 0.5)));
    }
}
