package dev.trisect.raster;

/**
 * Blending with GL_SRC_ALPHA and GL_ONE_MINUS_SRC_ALPHA (OpenGL 1.x section 4.1.7): each colour
 * channel becomes {@code s * a + d * (1 - a)} with the source's alpha {@code a = A / 255}, in 8 bits
 * rounded to nearest, {@code round((s * A + d * (255 - A)) / 255)}, computed exactly in integers
 * ({@link #divide255}). The frame's alpha stays 255.
 */
final class Blend {
    private Blend() {
    }

    /** The fragment {@code src} (ARGB, its alpha the weight) over the frame's pixel {@code dst}; alpha 255. */
    static int over(int src, int dst) {
        int a = src >>> 24;
        int na = 255 - a;
        int r = divide255((src >> 16 & 0xFF) * a + (dst >> 16 & 0xFF) * na);
        int g = divide255((src >> 8 & 0xFF) * a + (dst >> 8 & 0xFF) * na);
        int b = divide255((src & 0xFF) * a + (dst & 0xFF) * na);
        return 0xFF000000 | r << 16 | g << 8 | b;
    }

    /**
     * {@code v / 255} rounded to nearest, for 0 &lt;= v &lt;= 255 * 255 (no ties: 255 is odd), without a
     * division: the usual shift form, checked against the division for every such v (BlendTest).
     */
    static int divide255(int v) {
        int w = v + 128;
        return (w + (w >> 8)) >> 8;
    }
}
