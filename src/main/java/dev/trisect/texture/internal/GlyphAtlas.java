package dev.trisect.texture.internal;

import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.RenderingHints;
import java.awt.font.FontRenderContext;
import java.awt.font.GlyphVector;
import java.awt.image.BufferedImage;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The glyphs of one AWT {@link Font}, each rasterized once, on first use, into one texture of alpha:
 * texels {@code 0xFFFFFFFF} where the glyph is inked and 0 elsewhere, as AWT draws the glyph without
 * antialiasing and with integer metrics ({@code KEY_TEXT_ANTIALIASING} and {@code KEY_FRACTIONALMETRICS}
 * off). Any code point the font has a glyph for (its missing-glyph box otherwise). Glyphs are placed
 * in rows of a texture {@link #WIDTH} texels wide whose height doubles when full; a grown texture is a
 * new array, so a {@link Glyph} keeps pointing at texels that never change.
 *
 * <p>Laying out text with {@link Glyph#advance()} from a pen on a whole pixel gives the pixels AWT's
 * {@code Graphics2D.drawString} draws for the same string and font with the same hints (no kerning,
 * no ligatures: AWT applies neither unless asked). Thread-safe: {@link #of} and {@link #glyph} may be
 * called from any thread.
 */
public final class GlyphAtlas {
    /** Width of every atlas texture, texels. */
    public static final int WIDTH = 512;
    private static final Map<Font, GlyphAtlas> ATLASES = new ConcurrentHashMap<>();
    /** Integer metrics, no antialiasing: the context the glyphs are measured and drawn in. */
    private static final FontRenderContext CONTEXT = new FontRenderContext(null, false, false);

    /**
     * One glyph: where its texels are in the atlas and where they go relative to the pen.
     *
     * @param x       first texel column in {@code texels}
     * @param y       first texel row
     * @param width   texels across (0 for a glyph with no ink, such as a space)
     * @param height  texels down
     * @param left    pixels from the pen to the glyph's left column
     * @param top     pixels from the baseline to the glyph's top row (negative: above the baseline)
     * @param advance pixels the pen moves right after the glyph
     * @param texels  the atlas texture holding it, {@link #WIDTH} texels a row, ARGB
     */
    public record Glyph(int x, int y, int width, int height, int left, int top, int advance, int[] texels) {
    }

    private final Font font;
    private final int ascent;
    private final int descent;
    private final int leading;
    private final Map<Integer, Glyph> glyphs = new HashMap<>();
    /** Code points below this have their glyph in {@link #ascii} once rasterized. */
    private static final int ASCII = 128;
    private final Glyph[] ascii = new Glyph[ASCII];
    private int[] texels = new int[WIDTH * 64];
    private int rows = 64;
    /** The shelf being filled: its top row, height so far, and next free column. */
    private int shelfY;
    private int shelfHeight;
    private int shelfX;

    private GlyphAtlas(Font font) {
        this.font = font;
        var metrics = font.getLineMetrics("Hg", CONTEXT);
        this.ascent = (int) Math.ceil(metrics.getAscent());
        this.descent = (int) Math.ceil(metrics.getDescent());
        this.leading = (int) Math.ceil(metrics.getLeading());
    }

    /** Largest font size taken, pixels: a glyph is drawn whole into an image of about its size first. */
    public static final int MAX_FONT_SIZE = WIDTH;

    /**
     * Checks a font for the atlas: its size from 1 to {@link #MAX_FONT_SIZE} pixels.
     *
     * @param font the font
     * @return the font
     * @throws NullPointerException     when {@code font} is null
     * @throws IllegalArgumentException for a size out of range
     */
    public static Font checkFont(Font font) {
        java.util.Objects.requireNonNull(font, "font is null");
        if (!(font.getSize2D() >= 1 && font.getSize2D() <= MAX_FONT_SIZE)) {
            throw new IllegalArgumentException("a font for text must be 1 to " + MAX_FONT_SIZE + " pixels, got "
                    + font.getSize2D() + " (" + font.getName() + ")");
        }
        return font;
    }

    /**
     * The atlas of {@code font}, shared by every caller asking for an equal font.
     *
     * @param font the font, at the pixel size glyphs are drawn at (its point size is pixels here)
     * @return its atlas
     */
    public static GlyphAtlas of(Font font) {
        return ATLASES.computeIfAbsent(font, GlyphAtlas::new);
    }

    /** The font. */
    public Font font() {
        return font;
    }

    /** Pixels from the top of a line to its baseline. */
    public int ascent() {
        return ascent;
    }

    /** Pixels from one line's top to the next one's. */
    public int lineHeight() {
        return ascent + descent + leading;
    }

    /**
     * The glyph of {@code codePoint}, rasterized now if it is the first time.
     *
     * @param codePoint a Unicode code point
     * @return its glyph
     */
    public Glyph glyph(int codePoint) {
        // ASCII without the lock or a boxed key: a label's layout asks for each of its glyphs two or three
        // times a frame. A Glyph's fields are final, so one read here is whole even without the lock.
        if (codePoint >= 0 && codePoint < ASCII) {
            Glyph g = ascii[codePoint];
            if (g != null) {
                return g;
            }
        }
        return rasterized(codePoint);
    }

    private synchronized Glyph rasterized(int codePoint) {
        Glyph g = glyphs.get(codePoint);
        if (g == null) {
            g = rasterize(codePoint);
            glyphs.put(codePoint, g);
        }
        if (codePoint >= 0 && codePoint < ASCII) {
            ascii[codePoint] = g;
        }
        return g;
    }

    /** The number of glyphs rasterized so far. */
    public synchronized int size() {
        return glyphs.size();
    }

    private Glyph rasterize(int codePoint) {
        String s = new String(Character.toChars(codePoint));
        GlyphVector vector = font.createGlyphVector(CONTEXT, s);
        int advance = Math.round(vector.getGlyphMetrics(0).getAdvanceX());
        Rectangle bounds = vector.getPixelBounds(CONTEXT, 0, 0);
        if (bounds.isEmpty()) {
            return new Glyph(0, 0, 0, 0, 0, 0, advance, texels);
        }
        // One pixel of margin each side: pixel bounds are AWT's estimate of the ink, not a promise.
        int w = bounds.width + 2;
        int h = bounds.height + 2;
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_OFF);
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_OFF);
            g.setRenderingHint(RenderingHints.KEY_FRACTIONALMETRICS, RenderingHints.VALUE_FRACTIONALMETRICS_OFF);
            g.setFont(font);
            g.setColor(java.awt.Color.WHITE);
            g.drawString(s, 1 - bounds.x, 1 - bounds.y);
        } finally {
            g.dispose();
        }
        int[] argb = image.getRGB(0, 0, w, h, null, 0, w);
        // The ink's own bounds (AWT's pixel bounds are an estimate, hence the margin drawn above).
        int c0 = w;
        int c1 = -1;
        int r0 = h;
        int r1 = -1;
        for (int r = 0; r < h; r++) {
            for (int c = 0; c < w; c++) {
                if ((argb[r * w + c] >>> 24) >= 128) {
                    c0 = Math.min(c0, c);
                    c1 = Math.max(c1, c);
                    r0 = Math.min(r0, r);
                    r1 = Math.max(r1, r);
                }
            }
        }
        if (c1 < 0) {
            return new Glyph(0, 0, 0, 0, 0, 0, advance, texels);
        }
        // A glyph wider than the atlas (a wide ligature-like glyph of a large font) keeps its left WIDTH
        // columns: the text is drawn, cut, rather than the frame failing.
        int iw = Math.min(c1 - c0 + 1, WIDTH);
        int ih = r1 - r0 + 1;
        place(iw, ih);
        for (int r = 0; r < ih; r++) {
            for (int c = 0; c < iw; c++) {
                texels[(shelfY + r) * WIDTH + shelfX + c] = (argb[(r0 + r) * w + c0 + c] >>> 24) >= 128 ? 0xFFFFFFFF : 0;
            }
        }
        Glyph glyph = new Glyph(shelfX, shelfY, iw, ih, bounds.x - 1 + c0, bounds.y - 1 + r0, advance, texels);
        shelfX += iw;
        return glyph;
    }

    /** Makes room for a w x h glyph at (shelfX, shelfY): on this shelf, a new one, a taller texture. */
    private void place(int w, int h) {
        if (shelfX + w > WIDTH) {
            shelfY += shelfHeight;
            shelfX = 0;
            shelfHeight = 0;
        }
        shelfHeight = Math.max(shelfHeight, h);
        while (shelfY + shelfHeight > rows) {
            rows *= 2;
        }
        if (texels.length < rows * WIDTH) {
            // A new array: glyphs handed out before keep the old one, whose texels never change again.
            texels = Arrays.copyOf(texels, rows * WIDTH);
        }
    }
}
