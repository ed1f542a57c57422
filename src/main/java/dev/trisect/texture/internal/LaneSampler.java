package dev.trisect.texture.internal;

import dev.trisect.texture.MipChain;

/**
 * Bilinear and trilinear sampling on {@link TexelLanes}: the fast form of OpenGL's {@code GL_LINEAR}
 * and {@code GL_LINEAR_MIPMAP_LINEAR} with {@code GL_REPEAT} that the filtered pixel loops call. Static,
 * allocation-free, primitive arguments only, small enough to inline into any loop: the per-pixel
 * loops, the per-piece (affine, tessellated) loops, and a per-row span loop alike.
 *
 * <p><b>The rule</b> (docs/conventions.md, "Texture filtering"). On a level of {@code w x h} texels, the
 * sample point in that level's texel coordinates {@code (s, t)} (t from the bottom) is moved back half a
 * texel and taken in 24.8 fixed point, {@code px = floor(256 (s - 1/2))}, {@code py} likewise: the
 * four texels are columns {@code i0 = px >> 8} and {@code i0 + 1}, rows {@code j0 = py >> 8} and
 * {@code j0 + 1}, wrapped, with fractions {@code fx = px & 255}, {@code fy = py & 255} in 1/256. The
 * weights are 8-bit, adding up to exactly 256:
 * <pre>
 *   w11 = (fx fy + 128) >> 8,  w10 = fx - w11,  w01 = fy - w11,  w00 = 256 - fx - fy + w11
 * </pre>
 * ({@code w11} is {@code fx fy / 256} rounded to nearest, the others follow exactly from
 * {@code (256 - fx)(256 - fy) / 256} and the rest as OpenGL's eq. 8.10 has them, each within 1/2 of its
 * exact product), and each channel is {@code (w00 c00 + w10 c10 + w01 c01 + w11 c11 + 128) >> 8}: one
 * pass over the four texels, one multiply per texel for all three channels, rounded once. Against the
 * exact products of the fractions ({@link Sampler#blend}) a channel moves by at most 1/255, since the
 * four weight errors are one value {@code e} (|e| &lt;= 1/2) with signs + - - + and
 * {@code |c00 - c10 - c01 + c11| <= 510}. OpenGL leaves the precision of the weights to the
 * implementation; 8-bit weights are what llvmpipe's 8-bit path blends with too.
 *
 * <p>Trilinear blends the two levels' results with weight {@code weight / 256} on the second,
 * {@code (a (256 - weight) + b weight + 128) >> 8} per channel, as {@link Sampler#lerp}.
 *
 * <p>Values returned are in lanes ({@link TexelLanes}: blue, red, green, alpha in the low bytes of
 * 16-bit lanes; alpha is filtered as the colour is); {@link TexelLanes#argb} makes the opaque ARGB
 * pixel, {@link TexelLanes#argbWithAlpha} the pixel with its alpha.
 */
public final class LaneSampler {
    /** Half of 1/256 in every lane: the rounding of a sum weighted in 1/256. */
    private static final long ROUND = 0x0080_0080_0080_0080L;

    private LaneSampler() {
    }

    /**
     * The bilinear blend of four texels in lanes with fractions {@code fx}, {@code fy} in 1/256: see the
     * class comment.
     *
     * @param c00 texel (i0, j0), in lanes
     * @param c10 texel (i0 + 1, j0)
     * @param c01 texel (i0, j0 + 1)
     * @param c11 texel (i0 + 1, j0 + 1)
     * @param fx  weight of column i0 + 1, 0..255 (1/256)
     * @param fy  weight of row j0 + 1, 0..255 (1/256)
     * @return the sample, in lanes
     */
    public static long blend(long c00, long c10, long c01, long c11, int fx, int fy) {
        return blendLong(c00, c10, c01, c11, fx, fy);
    }

    /** {@link #blend} with the fractions as longs, so no weight is widened before its multiply. */
    private static long blendLong(long c00, long c10, long c01, long c11, long fx, long fy) {
        long w11 = fx * fy + 128 >> 8;
        long sum = c00 * (256 - fx - fy + w11) + c10 * (fx - w11) + c01 * (fy - w11) + c11 * w11 + ROUND;
        return sum >>> 8 & TexelLanes.CHANNELS;
    }

    /**
     * The bilinear sample whose first texel is {@code lanes[k]} (column i0, row j0 of a level, already
     * wrapped into the level): the padding of {@link TexelLanes} puts the other three at {@code k + 1},
     * {@code k + stride} and {@code k + stride + 1}.
     *
     * @param k      {@code offset + j0 * stride + i0}, with {@code 0 <= i0 < w}, {@code 0 <= j0 < h}
     * @param stride the level's {@link TexelLanes#stride}
     * @param fx     0..255, 1/256 texel
     * @param fy     0..255, 1/256 texel
     */
    public static long bilinearAt(long[] lanes, int k, int stride, int fx, int fy) {
        return blend(lanes[k], lanes[k + 1], lanes[k + stride], lanes[k + stride + 1], fx, fy);
    }

    /**
     * The bilinear sample of a level whose sides are powers of two, at a position on that level.
     *
     * @param offset level's {@link TexelLanes#offset}
     * @param stride level's {@link TexelLanes#stride}
     * @param wMask  level's width - 1
     * @param hMask  level's height - 1
     * @param px     {@code floor(256 (s - 1/2))}, s the texel coordinate on this level (any value: wrapped)
     * @param py     {@code floor(256 (t - 1/2))}, t from the bottom
     * @return the sample, in lanes
     */
    public static long bilinearPowerOfTwo(long[] lanes, int offset, int stride, int wMask, int hMask, long px,
                                          long py) {
        int k = offset + ((int) (py >> 8) & hMask) * stride + ((int) (px >> 8) & wMask);
        return blendLong(lanes[k], lanes[k + 1], lanes[k + stride], lanes[k + stride + 1], px & 255, py & 255);
    }

    /**
     * The bilinear sample of a level of any size (wrapping with {@code floorMod}), at a position on that
     * level; the same result as {@link #bilinearPowerOfTwo} where both apply.
     *
     * @param offset level's {@link TexelLanes#offset}
     * @param stride level's {@link TexelLanes#stride}
     * @param w      level's width
     * @param h      level's height
     * @param px     {@code floor(256 (s - 1/2))}, s the texel coordinate on this level
     * @param py     {@code floor(256 (t - 1/2))}, t from the bottom
     * @return the sample, in lanes
     */
    public static long bilinear(long[] lanes, int offset, int stride, int w, int h, long px, long py) {
        int k = offset + Math.floorMod(py >> 8, h) * stride + Math.floorMod(px >> 8, w);
        return bilinearAt(lanes, k, stride, (int) px & 255, (int) py & 255);
    }

    /**
     * The bilinear sample of level d of a power-of-two chain ({@link TexelLanes#powerOfTwo}) at level-0
     * texel coordinates in 24.8 fixed point: level d's position is {@code (s8 >> shift) - 128}, exactly
     * {@code floor(256 (s 2^-shift - 1/2))} since {@code floor(floor(x) / 2^k) = floor(x / 2^k)}, so one
     * floor per coordinate serves every level.
     *
     * @param levels the chain's {@link TexelLanes#levels}
     * @param d      level, 0..levelCount - 1
     * @param s8     {@code floor(256 s)}, s = u * width of level 0
     * @param t8     {@code floor(256 t)}, t = v * height of level 0, from the bottom
     * @return the sample, in lanes
     */
    public static long levelPowerOfTwo(long[] lanes, int[] levels, int d, long s8, long t8) {
        int o = d * TexelLanes.LEVEL_INTS;
        return bilinearPowerOfTwo(lanes, levels[o + TexelLanes.OFFSET], levels[o + TexelLanes.STRIDE],
                levels[o + TexelLanes.WIDTH_MASK], levels[o + TexelLanes.HEIGHT_MASK],
                (s8 >> levels[o + TexelLanes.SHIFT_S]) - Sampler.ONE / 2,
                (t8 >> levels[o + TexelLanes.SHIFT_T]) - Sampler.ONE / 2);
    }

    /**
     * The bilinear sample of level d of any chain at level-0 texel coordinates (s, t): the position on
     * the level is {@link Sampler#position} of the coordinate scaled to it, wrapped with
     * {@code floorMod} ({@link #bilinear}).
     *
     * @param levels the chain's {@link TexelLanes#levels}
     * @param d      level, 0..levelCount - 1
     * @param s      s = u * width of level 0
     * @param t      t = v * height of level 0, from the bottom
     * @return the sample, in lanes
     */
    public static long level(long[] lanes, int[] levels, MipChain chain, int d, double s, double t) {
        int o = d * TexelLanes.LEVEL_INTS;
        return bilinear(lanes, levels[o + TexelLanes.OFFSET], levels[o + TexelLanes.STRIDE],
                levels[o + TexelLanes.WIDTH], levels[o + TexelLanes.HEIGHT],
                Sampler.position(s * chain.scaleS(d)), Sampler.position(t * chain.scaleT(d)));
    }

    /**
     * The trilinear (or, with weight 0, bilinear) pixel of a power-of-two chain for a level selection
     * ({@link Lod#select}: {@code level << 9 | weight}) at level-0 coordinates in 24.8 fixed point.
     *
     * @param s8 {@code floor(256 s)}, s = u * width of level 0
     * @param t8 {@code floor(256 t)}, from the bottom
     * @return opaque ARGB
     */
    public static int trilinearPowerOfTwo(long[] lanes, int[] levels, int selection, long s8, long t8) {
        int d = Lod.level(selection);
        long c = levelPowerOfTwo(lanes, levels, d, s8, t8);
        int weight = Lod.weight(selection);
        if (weight != 0) {
            c = lerp(c, levelPowerOfTwo(lanes, levels, d + 1, s8, t8), weight);
        }
        return TexelLanes.argb(c);
    }

    /**
     * {@code a (1 - f) + b f} per channel with {@code f = weight / 256}, rounded to nearest: the blend
     * of two levels.
     *
     * @param a      level d's sample, in lanes
     * @param b      level d + 1's sample, in lanes
     * @param weight 0..256
     * @return in lanes
     */
    public static long lerp(long a, long b, int weight) {
        return (a * (256 - weight) + b * weight + ROUND) >>> 8 & TexelLanes.CHANNELS;
    }
}
