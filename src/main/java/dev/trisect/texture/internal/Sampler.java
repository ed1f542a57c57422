package dev.trisect.texture.internal;

/**
 * Bilinear and trilinear sampling with repeat on the int texels of a level, with exact 16-bit weights:
 * the rule the pixel loops used until issue 16, kept as the reference that {@link LaneSampler}'s packed
 * blend with 8-bit weights is tested against (each channel within 1/255 of it) and as the "before" of
 * {@code SampleCostBenchmark}. The pixel loops sample through {@link LaneSampler}; {@link #position}
 * and the fixed-point constants here are shared by both.
 *
 * <p>Bilinear is OpenGL's {@code GL_LINEAR} with {@code GL_REPEAT} (OpenGL 4.6 core spec, §8.14.2,
 * eq. 8.9–8.10): on a level of {@code W x H} texels, the sample point in texel coordinates
 * {@code (s, t) = (u W, v H)} is moved by half a texel, {@code i0 = floor(s - 1/2)},
 * {@code alpha = frac(s - 1/2)} (likewise {@code j0}, {@code beta} for t), the four texels
 * {@code (i0, j0), (i0 + 1, j0), (i0, j0 + 1), (i0 + 1, j0 + 1)} are wrapped with {@code floorMod}, and
 * their colours weighted by {@code (1 - alpha)(1 - beta)}, {@code alpha (1 - beta)},
 * {@code (1 - alpha) beta} and {@code alpha beta}. Columns count from the left, rows from the bottom
 * (image row {@code H - 1 - j}).
 *
 * <p>Positions are in fixed point with {@link #FRACTION_BITS} = 8 fraction bits, so each weight is a
 * multiple of 1/256 and the blend is exact integer arithmetic rounded once to nearest. OpenGL leaves
 * the precision of the weights to the implementation; 8 bits is what llvmpipe's path for 8-bit
 * textures uses too (docs/opengl.md). Alpha is not filtered: the result is opaque, as every fill in
 * Trisect is.
 */
public final class Sampler {
    /** Fraction bits of a fixed-point sample position: weights are multiples of 1/256. */
    public static final int FRACTION_BITS = 8;
    /** One texel in fixed point. */
    public static final int ONE = 1 << FRACTION_BITS;

    private Sampler() {
    }

    /**
     * The fixed-point bilinear position for texel coordinate {@code s} of a level: {@code floor((s - 1/2)
     * * 256)}. Integer part (arithmetic shift by 8) is {@code i0}, the low 8 bits the weight of
     * {@code i0 + 1}.
     *
     * @param s texel coordinate on the level ({@code u * width}), any finite value
     */
    public static long position(double s) {
        return (long) Math.floor(s * ONE - ONE / 2.0);
    }

    /**
     * The bilinear sample of one level at a fixed-point position (see {@link #position}), with repeat.
     *
     * @param texels level texels, ARGB, row 0 at the top
     * @param w      level width, texels
     * @param h      level height, texels
     * @param px     {@code floor((s - 1/2) * 256)}, s the texel coordinate on this level
     * @param py     {@code floor((t - 1/2) * 256)}, t from the bottom
     * @return opaque ARGB
     */
    public static int bilinear(int[] texels, int w, int h, long px, long py) {
        int fx = (int) px & (ONE - 1);
        int fy = (int) py & (ONE - 1);
        int i0 = (int) (px >> FRACTION_BITS);
        int j0 = (int) (py >> FRACTION_BITS);
        int i1;
        int j1;
        if ((w & (w - 1)) == 0) {
            i0 &= w - 1;
            i1 = (i0 + 1) & (w - 1);
        } else {
            i0 = Math.floorMod(i0, w);
            i1 = i0 + 1 == w ? 0 : i0 + 1;
        }
        if ((h & (h - 1)) == 0) {
            j0 &= h - 1;
            j1 = (j0 + 1) & (h - 1);
        } else {
            j0 = Math.floorMod(j0, h);
            j1 = j0 + 1 == h ? 0 : j0 + 1;
        }
        int row0 = (h - 1 - j0) * w;
        int row1 = (h - 1 - j1) * w;
        return blend(texels[row0 + i0], texels[row0 + i1], texels[row1 + i0], texels[row1 + i1], fx, fy);
    }

    /**
     * {@link #bilinear} on a level of {@code 2^logW x 2^logH} texels, where wrapping is a mask: the same
     * result, without the per-sample test for a power of two.
     *
     * @param texels level texels, ARGB, row 0 at the top
     * @param logW   log2 of the level's width
     * @param logH   log2 of the level's height
     * @param px     {@code floor((s - 1/2) * 256)}, s the texel coordinate on this level
     * @param py     {@code floor((t - 1/2) * 256)}, t from the bottom
     * @return opaque ARGB
     */
    public static int bilinearPowerOfTwo(int[] texels, int logW, int logH, long px, long py) {
        int wMask = (1 << logW) - 1;
        int hMask = (1 << logH) - 1;
        int i0 = (int) (px >> FRACTION_BITS) & wMask;
        int j0 = (int) (py >> FRACTION_BITS) & hMask;
        int i1 = (i0 + 1) & wMask;
        int j1 = (j0 + 1) & hMask;
        int row0 = (hMask - j0) << logW;
        int row1 = (hMask - j1) << logW;
        return blend(texels[row0 + i0], texels[row0 + i1], texels[row1 + i0], texels[row1 + i1],
                (int) px & (ONE - 1), (int) py & (ONE - 1));
    }

    /**
     * {@code c00 (1 - a)(1 - b) + c10 a (1 - b) + c01 (1 - a) b + c11 a b} per colour channel, with
     * {@code a = fx / 256}, {@code b = fy / 256}, rounded to nearest; opaque.
     */
    static int blend(int c00, int c10, int c01, int c11, int fx, int fy) {
        // Separably and exactly: the weights are (1 - a)(1 - b), a (1 - b), (1 - a) b, a b, so the sum is
        // the blend along x of each row, blended along y, and rounding once at the end gives the same
        // result. Along x each channel is at most 255 * 256 < 2^16: red and blue in 16-bit lanes of an
        // int, green in bits 8..23, with no carry between lanes (the top lane may reach bit 31, so the
        // ints are read unsigned). Along y red and blue go apart (24 bits each); green, still shifted
        // by 8, reaches at most 0xFF000000.
        int kx = ONE - fx;
        int rb0 = (c00 & 0xFF00FF) * kx + (c10 & 0xFF00FF) * fx;
        int rb1 = (c01 & 0xFF00FF) * kx + (c11 & 0xFF00FF) * fx;
        int g0 = (c00 & 0xFF00) * kx + (c10 & 0xFF00) * fx;
        int g1 = (c01 & 0xFF00) * kx + (c11 & 0xFF00) * fx;
        int ky = ONE - fy;
        int r = ((rb0 >>> 16) * ky + (rb1 >>> 16) * fy + 0x8000) >>> 16;
        int b = ((rb0 & 0xFFFF) * ky + (rb1 & 0xFFFF) * fy + 0x8000) >>> 16;
        int g = (g0 * ky + g1 * fy + 0x800000) >>> 24;
        return 0xFF000000 | r << 16 | g << 8 | b;
    }

    /**
     * {@code c0 (1 - f) + c1 f} per colour channel with {@code f = weight / 256}, rounded to nearest;
     * opaque. The blend of two mipmap levels in trilinear filtering.
     *
     * @param weight 0..256
     */
    public static int lerp(int c0, int c1, int weight) {
        int keep = ONE - weight;
        int rb = ((c0 & 0xFF00FF) * keep + (c1 & 0xFF00FF) * weight + 0x800080) >>> FRACTION_BITS;
        int g = ((c0 & 0xFF00) * keep + (c1 & 0xFF00) * weight + 0x8000) >>> FRACTION_BITS;
        return 0xFF000000 | rb & 0xFF00FF | g & 0xFF00;
    }
}
