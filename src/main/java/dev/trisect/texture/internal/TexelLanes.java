package dev.trisect.texture.internal;

import dev.trisect.texture.MipChain;
import java.util.function.Function;

/**
 * The levels of a {@link MipChain} laid out for fast filtering ({@link LaneSampler}): every texel
 * widened to a {@code long} of four 16-bit lanes, and every level padded by one wrapped column and
 * one wrapped row, so that the four texels of a bilinear sample are at {@code k}, {@code k + 1},
 * {@code k + stride} and {@code k + stride + 1} whatever the sample point — no wrap of the second
 * column and row, and one multiply per texel blends all three colour channels at once.
 *
 * <p><b>Texel format</b> ({@link #lanes(int)}): an ARGB texel {@code 0xAARRGGBB} becomes
 * {@code 0x00AA_00GG_00RR_00BB}: blue in bits 0–7, red in bits 16–23, green in bits 32–39, alpha in
 * bits 48–55, each the low byte of a 16-bit lane, so alpha is filtered exactly as the colour is, in
 * the same multiply. A weighted sum of such texels with integer weights adding up to 256 keeps each
 * channel below 2^16 in its own lane (255 * 256 + 128 &lt; 2^16), so the lanes never carry into each
 * other (the alpha lane's top bit is the long's sign bit: the samplers shift with {@code >>>}).
 *
 * <p><b>Layout</b> ({@link #lanes()}, {@link #levels()}): all levels in one {@code long[]}, level 0
 * first. Level d, {@code w x h} texels, takes {@code (w + 1) x (h + 1)} longs from
 * {@link #offset}(d), {@link #stride}(d) = w + 1 per row; rows count from the <em>bottom</em> (row
 * r holds texel row r of OpenGL's t axis, image row {@code h - 1 - r}, unlike {@link dev.trisect.texture.Texture#argb()}),
 * column w repeats column 0 and row h repeats row 0 (GL_REPEAT). So the texel at column
 * {@code i in [0, w)}, row from the bottom {@code j in [0, h)} is {@code offset + j * stride + i}.
 *
 * <p><b>Level descriptors</b>: {@link #levels()} holds {@link #LEVEL_INTS} ints per level, at
 * {@code d * LEVEL_INTS}: offset, stride, width, height, width mask and height mask (side - 1 for
 * power-of-two sides, else -1), and the right shifts from level 0's texel coordinates to level d's
 * (log2 of level 0's side over level d's; 0 for sides that are not powers of two). A loop that picks
 * its level per pixel reads them from one cache line.
 *
 * <p>Memory: 8 bytes per texel plus the padding, about 2.7 times the int texels of level 0 for the whole
 * chain. Built on first use by {@link MipChain#lanes()}, so textures that are only sampled nearest
 * never pay it. Immutable; the arrays are handed out without copies: read-only.
 */
public final class TexelLanes {
    /** Ints per level in {@link #levels()}. */
    public static final int LEVEL_INTS = 8;
    /** Field of a level descriptor: index of the level's first long (column 0, bottom row). */
    public static final int OFFSET = 0;
    /** Field of a level descriptor: longs per row, width + 1. */
    public static final int STRIDE = 1;
    /** Field of a level descriptor: width, texels. */
    public static final int WIDTH = 2;
    /** Field of a level descriptor: height, texels. */
    public static final int HEIGHT = 3;
    /** Field of a level descriptor: width - 1 for a power-of-two width, else -1. */
    public static final int WIDTH_MASK = 4;
    /** Field of a level descriptor: height - 1 for a power-of-two height, else -1. */
    public static final int HEIGHT_MASK = 5;
    /** Field of a level descriptor: right shift from level-0 s to level d's (power-of-two chains). */
    public static final int SHIFT_S = 6;
    /** Field of a level descriptor: right shift from level-0 t to level d's (power-of-two chains). */
    public static final int SHIFT_T = 7;

    /** Bits of the four lanes of a texel in {@link #lanes()}: blue, red, green, alpha. */
    public static final long CHANNELS = 0x00FF_00FF_00FF_00FFL;

    private final long[] lanes;
    private final int[] levels;
    private final boolean powerOfTwo;

    /** How {@link #of} reaches a chain's kept lanes; set once, by {@link MipChain}'s class initialiser. */
    private static volatile Function<MipChain, TexelLanes> cache;

    /**
     * Called once by {@link MipChain} with its private accessor of the lanes it keeps (built on first
     * use), so the API class has no public method naming this internal one.
     */
    public static void provideCache(Function<MipChain, TexelLanes> accessor) {
        if (cache != null) {
            throw new IllegalStateException("the lanes' cache is provided once, by MipChain");
        }
        cache = accessor;
    }

    /** The lanes of {@code chain}: built on the first call, from any thread, and kept by the chain. */
    public static TexelLanes of(MipChain chain) {
        return cache.apply(chain);
    }

    /** Lays out {@code chain}'s levels; {@link MipChain} calls it once per chain (use {@link #of}). */
    public TexelLanes(MipChain chain) {
        int count = chain.levels();
        levels = new int[count * LEVEL_INTS];
        long total = 0;
        for (int d = 0; d < count; d++) {
            total += (long) (chain.width(d) + 1) * (chain.height(d) + 1);
        }
        if (total > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("texture too large to filter: " + chain.width(0) + "x"
                    + chain.height(0));
        }
        lanes = new long[(int) total];
        powerOfTwo = chain.powerOfTwo();
        int offset = 0;
        for (int d = 0; d < count; d++) {
            int w = chain.width(d);
            int h = chain.height(d);
            int stride = w + 1;
            int o = d * LEVEL_INTS;
            levels[o + OFFSET] = offset;
            levels[o + STRIDE] = stride;
            levels[o + WIDTH] = w;
            levels[o + HEIGHT] = h;
            levels[o + WIDTH_MASK] = (w & (w - 1)) == 0 ? w - 1 : -1;
            levels[o + HEIGHT_MASK] = (h & (h - 1)) == 0 ? h - 1 : -1;
            if (powerOfTwo) {
                levels[o + SHIFT_S] = Integer.numberOfTrailingZeros(chain.width(0)) - Integer.numberOfTrailingZeros(w);
                levels[o + SHIFT_T] = Integer.numberOfTrailingZeros(chain.height(0)) - Integer.numberOfTrailingZeros(h);
            }
            int[] texels = chain.texels(d);
            for (int r = 0; r <= h; r++) {
                int src = (h - 1 - r % h) * w;
                int dst = offset + r * stride;
                for (int i = 0; i < w; i++) {
                    lanes[dst + i] = lanes(texels[src + i]);
                }
                lanes[dst + w] = lanes[dst];
            }
            offset += stride * (h + 1);
        }
    }

    /** An ARGB texel in lanes: {@code 0xAARRGGBB} to {@code 0x00AA_00GG_00RR_00BB}. */
    public static long lanes(int argb) {
        return argb & 0xFF00FFL | (long) (argb & 0xFF00) << 24 | (long) (argb >>> 24) << 48;
    }

    /** The opaque ARGB colour of a value in lanes whose channels are 0..255 ({@link #CHANNELS} only). */
    public static int argb(long lanes) {
        return 0xFF000000 | (int) lanes & 0xFF00FF | (int) (lanes >>> 24) & 0xFF00;
    }

    /** {@link #argb} with the value's own alpha (its filtered texels' alpha) instead of 255. */
    public static int argbWithAlpha(long lanes) {
        return (int) (lanes >>> 24) & 0xFF00FF00 | (int) lanes & 0xFF00FF;
    }

    /** All levels' texels in lanes, padded, rows from the bottom (see the class comment); read-only. */
    public long[] lanes() {
        return lanes;
    }

    /** The level descriptors, {@link #LEVEL_INTS} ints per level (see the class comment); read-only. */
    public int[] levels() {
        return levels;
    }

    /** Whether both sides of level 0 are powers of two, so every level wraps with masks and shifts. */
    public boolean powerOfTwo() {
        return powerOfTwo;
    }

    /** Number of levels. */
    public int levelCount() {
        return levels.length / LEVEL_INTS;
    }

    /** Index in {@link #lanes()} of level d's first texel (column 0, bottom row). */
    public int offset(int d) {
        return levels[d * LEVEL_INTS + OFFSET];
    }

    /** Longs per row of level d: its width + 1. */
    public int stride(int d) {
        return levels[d * LEVEL_INTS + STRIDE];
    }
}
