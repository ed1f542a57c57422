package dev.trisect.raster;

import dev.trisect.light.FogPass;
import java.util.Arrays;

/**
 * The {@link Commands#QUAD QUAD} commands' store, setup and loop: screen-aligned textured rectangles —
 * billboards, the glyphs of labels and of screen text, the backdrops behind them — added once per
 * frame ({@link #add}), set up for the frame ({@link #setUp}: the columns and rows each covers), listed
 * as commands in the order added and drawn band by band ({@link #rows}) over what the frame holds.
 *
 * <p>A quad is a rectangle of screen space (pixels, y down) at one depth: a surface parallel to the
 * image plane has the same 1/w at every point, so its texture maps affinely onto the rectangle and
 * that is exact. It covers the pixels whose centre lies in {@code [left, right) x [top, bottom)} (the
 * triangles' top-left rule for a rectangle). The texel of a pixel is the nearest one to its centre's
 * place on the texture, {@code floor(s)}, {@code floor(t)} in texels with s and t running from the
 * rectangle's left and top edges (0) to its right and bottom ones (the texture's width and height),
 * clamped to the texture.
 *
 * <p>What a covered pixel gets, by the quad's mode ({@link #TEST}, {@link #BLEND}, and
 * {@link #ON_TOP} with either):
 * <ul>
 *   <li>{@link #TEST}: drawn where the texel's alpha is at least 128 (as {@code GL_ALPHA_TEST} with
 *       {@code GL_GEQUAL 0.5}, OpenGL 1.x section 4.1.4) and the quad's 1/w is not behind the frame's
 *       ({@code GL_LEQUAL}); then colour and depth are written;</li>
 *   <li>{@link #BLEND}: where the depth test passes, colour = src·a + dst·(1 − a) per channel, a the
 *       texel's alpha times the tint's ({@code GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA}, section 4.1.7),
 *       rounded to nearest; depth is not written;</li>
 *   <li>{@link #ON_TOP}: no depth test and no depth write (text over the frame).</li>
 * </ul>
 * With {@link #TINT} the texel gives only alpha and the quad's tint the colour (glyphs: one atlas, any
 * colour). The frame's alpha stays 255.
 *
 * <p>With {@link #FOG}, when the frame has fog ({@link #setUp(int, int, FogPass)}), each fragment's
 * colour (texel or tint) is blended towards the fog by the factor of the quad's own depth before the
 * alpha test and the blend, as OpenGL fogs every fragment (OpenGL 2.1, section 3.10, ahead of the
 * per-fragment operations of chapter 4): a blended quad is fogged by its depth, not by the surface
 * behind it. Factor and blend are the fog pass's ({@link FogPass#weight}, {@link FogPass#fogged}), so
 * an opaque fogged quad's pixels are what the pass would make of them. The factor is one per quad (its
 * 1/w is), found at set-up.
 *
 * <p>Not thread-safe to set up; {@link #rows} may run on many threads at once over distinct rows.
 */
public final class QuadRaster {
    /** Mode: alpha-tested, depth-tested and depth-writing. */
    public static final int TEST = 0;
    /** Mode: blended over the frame, depth-tested, no depth write. */
    public static final int BLEND = 1;
    /** Flag: neither depth test nor depth write. */
    public static final int ON_TOP = 2;
    /** Flag: colour from the tint, alpha from the texel (times the tint's). */
    public static final int TINT = 4;
    /** Flag: fogged by its depth when the frame has fog (billboards: scene content). */
    public static final int FOG = 8;
    /** The fog factor of an unfogged quad, in 4096ths ({@link FogPass#weight}). */
    private static final int UNFOGGED = 4096;
    /** Kind of quad, for the statistics: a billboard. */
    public static final int BILLBOARD = 0;
    /** Kind: a glyph. */
    public static final int GLYPH = 1;
    /** Kind: anything else (a backdrop). */
    public static final int OTHER = 2;

    /** Ints per quad: flags, tint, texture width, texture height, texture row stride, first texel, kind. */
    private static final int ISTRIDE = 7;
    /** Doubles per quad: left, top, right, bottom, 1/w. */
    private static final int DSTRIDE = 5;

    private int[] ints = new int[ISTRIDE * 64];
    private double[] doubles = new double[DSTRIDE * 64];
    private int[][] textures = new int[64][];
    private int count;
    private final int[] kinds = new int[3];
    /** Per quad, the frame columns and rows it covers (first and last), set by {@link #setUp}. */
    private int[] bounds = new int[4 * 64];
    /** Per quad, set by {@link #setUp}: the texel column at its first column's centre and per pixel, 32.32. */
    private long[] steps = new long[2 * 64];
    /** Per quad, set by {@link #setUp}: its fog factor in 4096ths, {@link #UNFOGGED} when not fogged. */
    private int[] fogFactors = new int[64];
    /** The frame's fog as last set up, or null. */
    private FogPass fog;
    private int width;

    /** Forgets every quad. */
    public void clear() {
        Arrays.fill(textures, 0, count, null);
        count = 0;
        Arrays.fill(kinds, 0);
    }

    /** Quads added since {@link #clear}. */
    public int count() {
        return count;
    }

    /**
     * The kind of quad {@code s}.
     *
     * @return {@link #BILLBOARD}, {@link #GLYPH} or {@link #OTHER}
     */
    public int kind(int s) {
        return ints[ISTRIDE * s + 6];
    }

    /**
     * Quads of one kind added since {@link #clear}.
     *
     * @param kind {@link #BILLBOARD}, {@link #GLYPH} or {@link #OTHER}
     * @return how many
     */
    public int count(int kind) {
        return kinds[kind];
    }

    /**
     * Adds a quad showing a region of a texture.
     *
     * @param left    screen x of the left edge, pixels
     * @param top     screen y of the top edge (y down)
     * @param right   screen x of the right edge, above {@code left}
     * @param bottom  screen y of the bottom edge, below {@code top}
     * @param q       1/w of the quad (its eye depth's inverse), for the depth test and write
     * @param texels  ARGB texels, {@code stride} a row; kept, not copied
     * @param stride  texels per row of {@code texels}
     * @param first   index of the region's top-left texel
     * @param texW    texels across the region
     * @param texH    texels down the region
     * @param mode    {@link #TEST} or {@link #BLEND}, with {@link #ON_TOP}, {@link #TINT} and {@link #FOG} as wanted
     * @param tint    ARGB: the colour under {@link #TINT}; its alpha multiplies the texels' under {@link #BLEND}
     * @param kind    {@link #BILLBOARD}, {@link #GLYPH} or {@link #OTHER}
     */
    public void add(double left, double top, double right, double bottom, double q, int[] texels, int stride,
                    int first, int texW, int texH, int mode, int tint, int kind) {
        if (!(right > left && bottom > top) || texW <= 0 || texH <= 0) {
            return;
        }
        if (count == textures.length) {
            textures = Arrays.copyOf(textures, 2 * count);
            ints = Arrays.copyOf(ints, ISTRIDE * 2 * count);
            doubles = Arrays.copyOf(doubles, DSTRIDE * 2 * count);
        }
        int i = ISTRIDE * count;
        ints[i] = mode;
        ints[i + 1] = tint;
        ints[i + 2] = texW;
        ints[i + 3] = texH;
        ints[i + 4] = stride;
        ints[i + 5] = first;
        ints[i + 6] = kind;
        int d = DSTRIDE * count;
        doubles[d] = left;
        doubles[d + 1] = top;
        doubles[d + 2] = right;
        doubles[d + 3] = bottom;
        doubles[d + 4] = q;
        textures[count++] = texels;
        kinds[kind]++;
    }

    /** As {@link #setUp(int, int, FogPass)} without fog. */
    public int setUp(int width, int height) {
        return setUp(width, height, null);
    }

    /**
     * Sets the quads up for a {@code width x height} frame: the columns and rows whose pixel centres
     * each covers, within the frame (see {@link #firstRow}, {@link #lastRow}), and the fog factor of
     * each {@link #FOG} quad.
     *
     * @param fog the frame's fog pass, or null for none
     * @return quads that cover a pixel of the frame
     */
    public int setUp(int width, int height, FogPass fog) {
        this.width = width;
        this.fog = fog;
        if (bounds.length < 4 * count) {
            bounds = new int[4 * Math.max(count, bounds.length)];
            steps = new long[bounds.length / 2];
            fogFactors = new int[bounds.length / 4];
        }
        int shown = 0;
        for (int s = 0; s < count; s++) {
            int d = DSTRIDE * s;
            // Centres x + 0.5 in [left, right): columns ceil(left - 0.5) .. ceil(right - 0.5) - 1.
            double x0 = Math.max(0, Math.ceil(doubles[d] - 0.5));
            double x1 = Math.min(width - 1, Math.ceil(doubles[d + 2] - 0.5) - 1);
            double y0 = Math.max(0, Math.ceil(doubles[d + 1] - 0.5));
            double y1 = Math.min(height - 1, Math.ceil(doubles[d + 3] - 0.5) - 1);
            if (x0 > x1 || y0 > y1) {
                // Covers nothing: an empty range of rows.
                bounds[4 * s + 2] = 1;
                bounds[4 * s + 3] = 0;
                continue;
            }
            bounds[4 * s] = (int) x0;
            bounds[4 * s + 1] = (int) x1;
            bounds[4 * s + 2] = (int) y0;
            bounds[4 * s + 3] = (int) y1;
            // The depth as the depth buffer would hold it, so that the factor is the fog pass's for it.
            fogFactors[s] = fog != null && (ints[ISTRIDE * s] & FOG) != 0
                    ? fog.weight((float) doubles[d + 4]) : UNFOGGED;
            // The texel column in 32.32 fixed point, stepped per pixel: exact where a texel is a whole number
            // of pixels at whole-pixel edges (glyphs: one texel a pixel), within 2^-32 texel a pixel elsewhere.
            double sPerPixel = ints[ISTRIDE * s + 2] / (doubles[d + 2] - doubles[d]);
            steps[2 * s] = (long) Math.floor((x0 + 0.5 - doubles[d]) * sPerPixel * 0x1p32);
            steps[2 * s + 1] = (long) Math.floor(sPerPixel * 0x1p32);
            shown++;
        }
        return shown;
    }

    /** Quad {@code s}'s first frame row, as {@link #setUp} found it (above {@link #lastRow} when it covers none). */
    public int firstRow(int s) {
        return bounds[4 * s + 2];
    }

    /** Quad {@code s}'s last frame row, inclusive. */
    public int lastRow(int s) {
        return bounds[4 * s + 3];
    }

    /**
     * Draws quad {@code s} (set up) into its rows within {@code [y0, y1)}: the loop of a
     * {@link Commands#QUAD} command.
     *
     * @param colour the frame's colours, ARGB, row 0 at the top
     * @param depths the frame's 1/w
     * @return pixels written (or blended)
     */
    public long rows(int s, int[] colour, float[] depths, int y0, int y1) {
        int from = Math.max(y0, bounds[4 * s + 2]);
        int to = Math.min(y1 - 1, bounds[4 * s + 3]);
        long written = 0;
        if (from <= to) {
            written += span(s, from, to, colour, depths);
        }
        return written;
    }

    /** Rows {@code from..to} of quad s. */
    private int span(int s, int from, int to, int[] colour, float[] depths) {
        int i = ISTRIDE * s;
        int d = DSTRIDE * s;
        int mode = ints[i] & ~FOG;
        int tint = ints[i + 1];
        int k = fogFactors[s];
        // Fogged texels are fogged per fragment in the row; a tint, the colour of every fragment, once here.
        FogPass texelFog = k != UNFOGGED && (mode & TINT) == 0 ? fog : null;
        if (k != UNFOGGED && (mode & TINT) != 0) {
            tint = fog.fogged(tint, k);
        }
        int texW = ints[i + 2];
        int texH = ints[i + 3];
        int stride = ints[i + 4];
        int[] tex = textures[s];
        double top = doubles[d + 1];
        double tPerPixel = texH / (doubles[d + 3] - top);
        float q = (float) doubles[d + 4];
        int x0 = bounds[4 * s];
        int x1 = bounds[4 * s + 1];
        long sFixed = steps[2 * s];
        long sStep = steps[2 * s + 1];
        int written = 0;
        for (int y = from; y <= to; y++) {
            int rowStart = ints[i + 5] + Math.min(texH - 1, (int) ((y + 0.5 - top) * tPerPixel)) * stride;
            int base = y * width;
            written += mode == (TEST | TINT)
                    ? testedTint(tex, rowStart, rowStart + texW - 1, sFixed, sStep, colour, depths, base + x0,
                            base + x1, q, tint | 0xFF000000)
                    : row(mode, tint, tex, rowStart, rowStart + texW - 1, sFixed, sStep, colour, depths, base + x0,
                            base + x1, q, texelFog, k);
        }
        return written;
    }

    /**
     * A row of any mode, from frame index {@code from} to {@code to}; with {@code fog}, each texel's
     * colour is fogged by factor {@code k} (its alpha is not, so the tests and the blend are unchanged).
     */
    private static int row(int mode, int tint, int[] tex, int rowStart, int last, long sFixed, long sStep,
                           int[] colour, float[] depths, int from, int to, float q, FogPass fog, int k) {
        boolean depthTest = (mode & ON_TOP) == 0;
        boolean tinted = (mode & TINT) != 0;
        int written = 0;
        // The texel last fogged and its fogged colour: a magnified texture repeats each texel over pixels.
        int seen = 0;
        int seenFogged = fog == null ? 0 : fog.fogged(0, k);
        if ((mode & BLEND) == 0) {
            int rgb = tint | 0xFF000000;
            for (int at = from; at <= to; at++, sFixed += sStep) {
                int texel = tex[Math.min(last, rowStart + (int) (sFixed >>> 32))];
                if (texel >>> 24 >= 128 && (!depthTest || q >= depths[at])) {
                    if (fog != null && texel != seen) {
                        seen = texel;
                        seenFogged = fog.fogged(texel, k);
                    }
                    colour[at] = tinted ? rgb : (fog == null ? texel : seenFogged) | 0xFF000000;
                    if (depthTest) {
                        depths[at] = q;
                    }
                    written++;
                }
            }
        } else {
            int tintAlpha = tint >>> 24;
            for (int at = from; at <= to; at++, sFixed += sStep) {
                int texel = tex[Math.min(last, rowStart + (int) (sFixed >>> 32))];
                int a = ((texel >>> 24) * tintAlpha + 127) / 255;
                if (a > 0 && (!depthTest || q >= depths[at])) {
                    if (fog != null && texel != seen) {
                        seen = texel;
                        seenFogged = fog.fogged(texel, k);
                    }
                    colour[at] = blend(tinted ? tint : fog == null ? texel : seenFogged, colour[at], a);
                    written++;
                }
            }
        }
        return written;
    }

    /** The common row: a depth-tested glyph, alpha-tested, in one colour. */
    private static int testedTint(int[] tex, int rowStart, int last, long sFixed, long sStep, int[] colour,
                                  float[] depths, int from, int to, float q, int rgb) {
        int written = 0;
        for (int at = from; at <= to; at++, sFixed += sStep) {
            if (tex[Math.min(last, rowStart + (int) (sFixed >>> 32))] < 0 && q >= depths[at]) {
                // A texel below 0 has alpha 128 or more: the sign bit is alpha's top bit.
                colour[at] = rgb;
                depths[at] = q;
                written++;
            }
        }
        return written;
    }

    /**
     * src·a + dst·(1 − a) per channel, a in 0..255, rounded to nearest; alpha 255.
     *
     * @param src ARGB (its alpha ignored)
     * @param dst ARGB (its alpha ignored)
     * @param a   src's weight, 0..255
     * @return the blend, ARGB
     */
    public static int blend(int src, int dst, int a) {
        int b = 255 - a;
        int r = (((src >> 16) & 0xFF) * a + ((dst >> 16) & 0xFF) * b + 127) / 255;
        int g = (((src >> 8) & 0xFF) * a + ((dst >> 8) & 0xFF) * b + 127) / 255;
        int bl = ((src & 0xFF) * a + (dst & 0xFF) * b + 127) / 255;
        return 0xFF000000 | r << 16 | g << 8 | bl;
    }
}
