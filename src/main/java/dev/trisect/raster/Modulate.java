package dev.trisect.raster;

/**
 * GL_MODULATE of an RGBA texel by a fragment colour whose alpha is 1 (OpenGL 1.x section 3.8.13,
 * table 3.22: C = Cf Ct, A = At): each colour channel {@code c} of the texel becomes
 * {@code (int) (c * f + 0.5)}, {@code f} the fragment's channel in [0, 1] — the texel's value
 * {@code c / 255} times {@code f}, converted back to 8 bits by rounding to nearest (section 2.14.9's
 * conversion of a colour component to fixed point). The interpolated colour is clamped into [0, 1]
 * by the result's clamp to [0, 255]: a pixel centre just beyond its triangle's exact edge (coverage is
 * decided on snapped corners) may see a varying a hair outside the corners' range.
 */
final class Modulate {
    private Modulate() {
    }

    /** The texel {@code argb} times the colour (r, g, b), alpha kept. */
    static int argb(int argb, double r, double g, double b) {
        return argb & 0xFF000000 | channel(argb >> 16 & 0xFF, r) << 16 | channel(argb >> 8 & 0xFF, g) << 8
                | channel(argb & 0xFF, b);
    }

    /** One channel, 0..255, times {@code f}, rounded to nearest and kept within 0..255. */
    static int channel(int c, double f) {
        return Math.max(0, Math.min(255, (int) (c * f + 0.5)));
    }
}
