package dev.trisect.texture.internal;

/**
 * A tiny built-in bitmap font for labels: 5x7-pixel glyphs in a 6x8-pixel cell, drawn by integer
 * arithmetic only, so the result is identical on every machine (no AWT fonts, no antialiasing).
 *
 * <p>Glyphs exist for {@code 0-9}, {@code A-Z}, space, {@code . , - + : / ( ) % = ?} and "≥" (U+2265,
 * which the heat map legend's top label needs, so that an image says "≥ 2 px" as the view does).
 * Lower-case letters are drawn as upper-case; any other character is drawn as {@code ?}.
 *
 * <p>Positions are in pixels of an ARGB buffer whose row 0 is the top row, y growing downwards. At
 * scale {@code s} every font pixel becomes an {@code s x s} block.
 */
public final class BitmapFont {
    /** Horizontal advance from one glyph to the next at scale 1, in pixels (5 glyph columns + 1 gap). */
    public static final int CELL_WIDTH = 6;
    /** Line height at scale 1, in pixels (7 glyph rows + 1 gap). */
    public static final int CELL_HEIGHT = 8;
    /** Width of the inked part of a glyph at scale 1, in pixels. */
    public static final int GLYPH_WIDTH = 5;
    /** Height of the inked part of a glyph at scale 1, in pixels. */
    public static final int GLYPH_HEIGHT = 7;

    /** The characters beyond ASCII that have a glyph, in the order of their slots after the 128 ASCII ones. */
    private static final String BEYOND_ASCII = "\u2265";
    /**
     * Bit {@code 4 - column} of {@code GLYPHS[slot(c)][row]} is set where the glyph is inked; null: no
     * glyph. Indexed by slot rather than by character, so one sign beyond ASCII costs one slot, not 8,000.
     */
    private static final byte[][] GLYPHS = new byte[128 + BEYOND_ASCII.length()][];

    static {
        // Each glyph is seven rows of five columns, top row first: '#' inked, '.' blank.
        glyph('0', ".###. #...# #..## #.#.# ##..# #...# .###.");
        glyph('1', "..#.. .##.. ..#.. ..#.. ..#.. ..#.. .###.");
        glyph('2', ".###. #...# ....# ...#. ..#.. .#... #####");
        glyph('3', "##### ...#. ..#.. ...#. ....# #...# .###.");
        glyph('4', "...#. ..##. .#.#. #..#. ##### ...#. ...#.");
        glyph('5', "##### #.... ####. ....# ....# #...# .###.");
        glyph('6', "..##. .#... #.... ####. #...# #...# .###.");
        glyph('7', "##### ....# ...#. ..#.. .#... .#... .#...");
        glyph('8', ".###. #...# #...# .###. #...# #...# .###.");
        glyph('9', ".###. #...# #...# .#### ....# ...#. .##..");
        glyph('A', ".###. #...# #...# ##### #...# #...# #...#");
        glyph('B', "####. #...# #...# ####. #...# #...# ####.");
        glyph('C', ".###. #...# #.... #.... #.... #...# .###.");
        glyph('D', "###.. #..#. #...# #...# #...# #..#. ###..");
        glyph('E', "##### #.... #.... ####. #.... #.... #####");
        glyph('F', "##### #.... #.... ####. #.... #.... #....");
        glyph('G', ".###. #...# #.... #.### #...# #...# .####");
        glyph('H', "#...# #...# #...# ##### #...# #...# #...#");
        glyph('I', ".###. ..#.. ..#.. ..#.. ..#.. ..#.. .###.");
        glyph('J', "..### ...#. ...#. ...#. ...#. #..#. .##..");
        glyph('K', "#...# #..#. #.#.. ##... #.#.. #..#. #...#");
        glyph('L', "#.... #.... #.... #.... #.... #.... #####");
        glyph('M', "#...# ##.## #.#.# #.#.# #...# #...# #...#");
        glyph('N', "#...# #...# ##..# #.#.# #..## #...# #...#");
        glyph('O', ".###. #...# #...# #...# #...# #...# .###.");
        glyph('P', "####. #...# #...# ####. #.... #.... #....");
        glyph('Q', ".###. #...# #...# #...# #.#.# #..#. .##.#");
        glyph('R', "####. #...# #...# ####. #.#.. #..#. #...#");
        glyph('S', ".#### #.... #.... .###. ....# ....# ####.");
        glyph('T', "##### ..#.. ..#.. ..#.. ..#.. ..#.. ..#..");
        glyph('U', "#...# #...# #...# #...# #...# #...# .###.");
        glyph('V', "#...# #...# #...# #...# #...# .#.#. ..#..");
        glyph('W', "#...# #...# #...# #.#.# #.#.# #.#.# .#.#.");
        glyph('X', "#...# #...# .#.#. ..#.. .#.#. #...# #...#");
        glyph('Y', "#...# #...# .#.#. ..#.. ..#.. ..#.. ..#..");
        glyph('Z', "##### ....# ...#. ..#.. .#... #.... #####");
        glyph(' ', "..... ..... ..... ..... ..... ..... .....");
        glyph('.', "..... ..... ..... ..... ..... .##.. .##..");
        glyph(',', "..... ..... ..... ..... .##.. ..#.. .#...");
        glyph('-', "..... ..... ..... ##### ..... ..... .....");
        glyph('+', "..... ..#.. ..#.. ##### ..#.. ..#.. .....");
        glyph(':', "..... .##.. .##.. ..... .##.. .##.. .....");
        glyph('/', "..... ....# ...#. ..#.. .#... #.... .....");
        glyph('(', "...#. ..#.. .#... .#... .#... ..#.. ...#.");
        glyph(')', ".#... ..#.. ...#. ...#. ...#. ..#.. .#...");
        glyph('%', "##... ##..# ...#. ..#.. .#... #..## ...##");
        glyph('=', "..... ..... ##### ..... ##### ..... .....");
        glyph('?', ".###. #...# ....# ...#. ..#.. ..... ..#..");
        glyph('\u2265', "#.... .##.. ...## .##.. #.... ..... #####");
    }

    private BitmapFont() {
    }

    private static void glyph(char c, String picture) {
        String[] rows = picture.split(" ");
        if (rows.length != GLYPH_HEIGHT) {
            throw new IllegalStateException("glyph '" + c + "' has " + rows.length + " rows");
        }
        byte[] bits = new byte[GLYPH_HEIGHT];
        for (int row = 0; row < GLYPH_HEIGHT; row++) {
            if (rows[row].length() != GLYPH_WIDTH) {
                throw new IllegalStateException("glyph '" + c + "' row " + row + " is not " + GLYPH_WIDTH + " wide");
            }
            for (int column = 0; column < GLYPH_WIDTH; column++) {
                if (rows[row].charAt(column) == '#') {
                    bits[row] |= (byte) (1 << (GLYPH_WIDTH - 1 - column));
                }
            }
        }
        GLYPHS[slot(c)] = bits;
    }

    /** The index of {@code c}'s glyph in GLYPHS, or -1 when it has none. */
    private static int slot(char c) {
        return c < 128 ? c : BEYOND_ASCII.indexOf(c) < 0 ? -1 : 128 + BEYOND_ASCII.indexOf(c);
    }

    /** Whether {@code c} has a glyph of its own (after lower-case letters are taken as upper-case). */
    public static boolean hasGlyph(char c) {
        int slot = slot(Character.toUpperCase(c));
        return slot >= 0 && GLYPHS[slot] != null;
    }

    private static byte[] glyphOf(char c) {
        return hasGlyph(c) ? GLYPHS[slot(Character.toUpperCase(c))] : GLYPHS['?'];
    }

    /**
     * Width of {@code text} at the given scale, in pixels: from the left edge of the first glyph to the
     * right edge of the last one, without the gap after it, i.e. {@code (6 * length - 1) * scale}, and 0
     * for the empty string. Use it to centre or right-align a label.
     *
     * @throws ArithmeticException if the width does not fit in an int
     */
    public static int textWidth(String text, int scale) {
        requireScale(scale);
        if (text.isEmpty()) {
            return 0;
        }
        return Math.multiplyExact(Math.addExact(Math.multiplyExact(CELL_WIDTH, text.length()), -1), scale);
    }

    /** Height of a line of text at the given scale, in pixels: the 7 glyph rows, {@code 7 * scale}. */
    public static int textHeight(int scale) {
        requireScale(scale);
        return Math.multiplyExact(GLYPH_HEIGHT, scale);
    }

    /**
     * Draws {@code text} into an ARGB buffer, clipped to it: pixels that would fall outside are skipped,
     * so any position (negative or far off) is safe. Inked pixels are set to {@code argbColour} as it is
     * (no blending); the others are left alone.
     *
     * @param argb      {@code width * height} pixels (or more), row-major, row 0 at the top
     * @param width     buffer width in pixels
     * @param height    buffer height in pixels
     * @param x         left edge of the first glyph, in pixels
     * @param y         top edge of the glyphs, in pixels (y grows downwards)
     * @param text      one line of text
     * @param scale     size of one font pixel in buffer pixels, at least 1
     * @param argbColour the colour of the inked pixels
     */
    public static void drawText(int[] argb, int width, int height, int x, int y, String text, int scale,
            int argbColour) {
        requireScale(scale);
        if (width < 0 || height < 0 || (long) width * height > argb.length) {
            throw new IllegalArgumentException("buffer of " + argb.length + " pixels is too small for "
                    + width + "x" + height);
        }
        long s = scale;
        for (int i = 0; i < text.length(); i++) {
            long left = x + i * (CELL_WIDTH * s);
            if (left >= width) {
                break; // every later glyph is further right
            }
            if (left + GLYPH_WIDTH * s <= 0) {
                continue;
            }
            byte[] bits = glyphOf(text.charAt(i));
            for (int row = 0; row < GLYPH_HEIGHT; row++) {
                long top = y + row * s;
                for (int column = 0; column < GLYPH_WIDTH; column++) {
                    if ((bits[row] >> (GLYPH_WIDTH - 1 - column) & 1) != 0) {
                        long px = left + column * s;
                        Pixels.fillRect(argb, width, height, px, top, px + s, top + s, argbColour);
                    }
                }
            }
        }
    }

    private static void requireScale(int scale) {
        if (scale < 1) {
            throw new IllegalArgumentException("font scale must be at least 1, got " + scale);
        }
    }
}
