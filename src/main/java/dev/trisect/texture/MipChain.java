package dev.trisect.texture;

import dev.trisect.texture.internal.TexelLanes;

/**
 * The mipmap levels of a texture, built once when the texture is created: level 0 is the texture
 * itself (not copied), each further level is half the previous one in each direction (rounded down,
 * at least 1), down to 1x1, so there are {@code floor(log2(max(W, H))) + 1} levels, as OpenGL's
 * mipmap completeness requires (OpenGL 4.6 core spec, §8.14.3 "Mipmapping", eq. 8.11 ff.).
 * The extra levels take at most a third of the texture's memory while both sides halve; once a side is
 * 1 only the other halves, which adds at most the longer side in texels (a 1-texel strip's levels
 * nearly double it, as in OpenGL).
 *
 * <p>Each texel of level d + 1 is the box filter of the texels of level d that its area covers,
 * separably per axis:
 * <ul>
 * <li>an even side halves exactly, and a texel is the average of 2 (per axis; 2x2 together);</li>
 * <li>an odd side {@code 2n + 1} becomes {@code n}, and texel {@code i} covers {@code 2 + 1/n} texels of
 * the level above: texels {@code 2i, 2i + 1, 2i + 2} with weights {@code (n - i), n, (i + 1)} over
 * {@code 2n + 1} — the exact box filter, the polyphase filter of NVIDIA's "Non-Power-of-Two
 * Mipmapping" whitepaper (2001, §3), whose weights sum to 1 and cover each source texel equally in
 * total;</li>
 * <li>a side of 1 stays 1 (only the other side halves).</li>
 * </ul>
 * Every channel, alpha included, is filtered along x and rounded to the nearest integer (half up),
 * then along y and rounded again. OpenGL leaves the filter of {@code glGenerateMipmap} to the
 * implementation (OpenGL 4.6 core spec, §8.14.4); for even sides this is bit for bit what Mesa's
 * llvmpipe generates (a 2x2 average rounded in the same two steps, measured with a probe of
 * {@code glGetTexImage}), and rounding once instead would put about half the texels 1/255 off
 * theirs. For odd sides Mesa samples bilinearly at each new texel's centre, which skips source texels;
 * the box filter here does not (docs/opengl.md).
 *
 * <p>Texels of every level are ARGB, row 0 at the top, as {@link Texture#argb()}. Immutable after
 * construction; the arrays are handed out without copies for the rasterizer: read-only.
 */
public final class MipChain {
    private final int[][] texels;
    private final int[] widths;
    private final int[] heights;
    private final double[] scaleS;
    private final double[] scaleT;
    /** Whether both sides of level 0 are powers of two (then every level's are). */
    private final boolean powerOfTwo;
    /** Per level, for power-of-two chains: see {@link #shape}. */
    private final int[] shapes;
    /** The levels in lanes for the filtered pixel loops, built on first use ({@link #lanes()}). */
    private volatile TexelLanes lanes;

    static {
        // The lanes are internal, so their cache is reached through TexelLanes.of, not a public method here.
        TexelLanes.provideCache(MipChain::lanes);
    }

    /** Builds all levels of {@code width x height} texels {@code argb} (row 0 at the top). */
    MipChain(int width, int height, int[] argb) {
        int count = levelCount(width, height);
        texels = new int[count][];
        widths = new int[count];
        heights = new int[count];
        scaleS = new double[count];
        scaleT = new double[count];
        texels[0] = argb;
        widths[0] = width;
        heights[0] = height;
        for (int d = 1; d < count; d++) {
            widths[d] = Math.max(1, widths[d - 1] / 2);
            heights[d] = Math.max(1, heights[d - 1] / 2);
            texels[d] = reduce(texels[d - 1], widths[d - 1], heights[d - 1], widths[d], heights[d]);
        }
        for (int d = 0; d < count; d++) {
            scaleS[d] = widths[d] / (double) width;
            scaleT[d] = heights[d] / (double) height;
        }
        powerOfTwo = (width & (width - 1)) == 0 && (height & (height - 1)) == 0;
        shapes = new int[count];
        if (powerOfTwo) {
            int logW = Integer.numberOfTrailingZeros(width);
            int logH = Integer.numberOfTrailingZeros(height);
            for (int d = 0; d < count; d++) {
                int lw = Integer.numberOfTrailingZeros(widths[d]);
                int lh = Integer.numberOfTrailingZeros(heights[d]);
                shapes[d] = (logW - lw) | (logH - lh) << 8 | lw << 16 | lh << 24;
            }
        }
    }

    /**
     * Number of levels of a {@code width x height} texture: {@code floor(log2(max(width, height))) + 1}.
     *
     * @param width  level 0's width, texels
     * @param height level 0's height, texels
     * @return {@code floor(log2(max(width, height))) + 1}
     */
    public static int levelCount(int width, int height) {
        return 32 - Integer.numberOfLeadingZeros(Math.max(width, height));
    }

    /**
     * Number of levels, level 0 included.
     *
     * @return the number of levels, level 0 included
     */
    public int levels() {
        return texels.length;
    }

    /**
     * The largest level index, {@code q} in OpenGL's terms.
     *
     * @return the last level's index, {@code levels() - 1}
     */
    public int maxLevel() {
        return texels.length - 1;
    }

    /**
     * Texels of level {@code d}, ARGB, row 0 at the top; read-only.
     *
     * @param d the level, {@code 0..maxLevel()}
     * @return its ARGB texels, row 0 at the top: read-only
     */
    public int[] texels(int d) {
        return texels[d];
    }

    /**
     * Width of level {@code d}, texels.
     *
     * @param d the level, {@code 0..maxLevel()}
     * @return its width, texels
     */
    public int width(int d) {
        return widths[d];
    }

    /**
     * Height of level {@code d}, texels.
     *
     * @param d the level, {@code 0..maxLevel()}
     * @return its height, texels
     */
    public int height(int d) {
        return heights[d];
    }

    /**
     * Level {@code d}'s width over level 0's: multiplies a level-0 texel coordinate s into level d's
     * texel units ({@code u * width(d)}). A power of two {@code 2^-d} for power-of-two sides.
     *
     * @param d the level, {@code 0..maxLevel()}
     * @return {@code width(d) / width(0)}
     */
    public double scaleS(int d) {
        return scaleS[d];
    }

    /**
     * Level {@code d}'s height over level 0's (see {@link #scaleS}).
     *
     * @param d the level, {@code 0..maxLevel()}
     * @return {@code height(d) / height(0)}
     */
    public double scaleT(int d) {
        return scaleT[d];
    }

    /**
     * Whether both sides of level 0 are powers of two, and with them the sides of every level: then
     * {@link #shape} describes each level by shifts and masks.
     *
     * @return true when both sides of level 0 are powers of two
     */
    public boolean powerOfTwo() {
        return powerOfTwo;
    }

    /**
     * Level {@code d} of a {@link #powerOfTwo} chain packed into one int, so a span loop that picks the
     * level per pixel loads one int instead of four values: bits 0–7 {@code log2(W / width(d))}, the
     * right shift taking a level-0 texel coordinate in fixed point to level d's ({@link #scaleS} is
     * 2 to minus that); bits 8–15 the same for heights; bits 16–23 {@code log2(width(d))}; bits 24–31
     * {@code log2(height(d))}. Zero for chains that are not power-of-two. (The pixel loops now read
     * the lanes' level descriptors instead; this stays for the reference samples.)
     *
     * @param d the level, {@code 0..maxLevel()}
     * @return the packed shifts and sizes, or 0
     */
    public int shape(int d) {
        return shapes[d];
    }

    /**
     * The levels laid out for the filtered pixel loops: texels widened to 16-bit lanes, padded with a
     * wrapped column and row. Built on the first call, from any thread, and kept; about 2.7 times level
     * 0's memory, which textures that are only sampled nearest never pay. Internal code reaches it
     * through {@code TexelLanes.of(chain)}.
     */
    private TexelLanes lanes() {
        TexelLanes l = lanes;
        if (l == null) {
            synchronized (this) {
                l = lanes;
                if (l == null) {
                    l = new TexelLanes(this);
                    lanes = l;
                }
            }
        }
        return l;
    }

    /**
     * Total texels of the levels beyond level 0 (memory check: at most a third of level 0).
     *
     * @return texels of levels 1 and up
     */
    public long extraTexels() {
        long n = 0;
        for (int d = 1; d < texels.length; d++) {
            n += texels[d].length;
        }
        return n;
    }

    /**
     * One box-filtered level from the one above it, separably: each source row is filtered along x
     * and rounded, then those columns along y and rounded (half up, as integers). Per axis,
     * {@code taps} source indices and integer weights for each destination index (see the class
     * comment).
     */
    static int[] reduce(int[] src, int sw, int sh, int dw, int dh) {
        int[] xFirst = new int[dw];
        int[] xWeights = new int[3 * dw];
        int xDenominator = axis(sw, dw, xFirst, xWeights);
        int[] yFirst = new int[dh];
        int[] yWeights = new int[3 * dh];
        int yDenominator = axis(sh, dh, yFirst, yWeights);
        // Pass 1: rows filtered along x, four channels, rows counted from the bottom.
        int[] rows = new int[4 * dw * sh];
        for (int y = 0; y < sh; y++) {
            int srcRow = (sh - 1 - y) * sw;
            for (int i = 0; i < dw; i++) {
                for (int channel = 0; channel < 4; channel++) {
                    int shift = 8 * channel;
                    long sum = 0;
                    for (int k = 0; k < 3; k++) {
                        int w = xWeights[3 * i + k];
                        if (w != 0) {
                            sum += (long) w * (src[srcRow + xFirst[i] + k] >>> shift & 0xFF);
                        }
                    }
                    rows[4 * (y * dw + i) + channel] = (int) ((sum + xDenominator / 2) / xDenominator);
                }
            }
        }
        // Pass 2: along y.
        int[] dst = new int[dw * dh];
        for (int j = 0; j < dh; j++) {
            for (int i = 0; i < dw; i++) {
                int argb = 0;
                for (int channel = 0; channel < 4; channel++) {
                    long sum = 0;
                    for (int k = 0; k < 3; k++) {
                        int w = yWeights[3 * j + k];
                        if (w != 0) {
                            sum += (long) w * rows[4 * ((yFirst[j] + k) * dw + i) + channel];
                        }
                    }
                    argb |= (int) ((sum + yDenominator / 2) / yDenominator) << (8 * channel);
                }
                dst[(dh - 1 - j) * dw + i] = argb;
            }
        }
        return dst;
    }

    /**
     * Filter taps along one axis from {@code n} source texels to {@code m} destination texels: for
     * destination i, source texels {@code first[i] + 0..2} with weights {@code weights[3i + 0..2]};
     * returns the common denominator.
     */
    private static int axis(int n, int m, int[] first, int[] weights) {
        for (int i = 0; i < m; i++) {
            if (n == 1) {
                first[i] = 0;
                weights[3 * i] = 1;
            } else if (n % 2 == 0) {
                first[i] = 2 * i;
                weights[3 * i] = 1;
                weights[3 * i + 1] = 1;
            } else {
                first[i] = 2 * i;
                weights[3 * i] = m - i;
                weights[3 * i + 1] = m;
                weights[3 * i + 2] = i + 1;
            }
        }
        return n == 1 ? 1 : n % 2 == 0 ? 2 : 2 * m + 1;
    }
}
