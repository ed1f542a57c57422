package dev.trisect.texture.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class BitmapFontTest {
    private static final int INK = 0xFFFFFFFF;
    private static final String ALL = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ.,-+:/()%=?\u2265";

    /** Renders text at (x, y) into a fresh buffer and returns it as rows of '#' and '.'. */
    private static String picture(int width, int height, int x, int y, String text, int scale) {
        int[] argb = new int[width * height];
        BitmapFont.drawText(argb, width, height, x, y, text, scale, INK);
        StringBuilder rows = new StringBuilder();
        for (int row = 0; row < height; row++) {
            for (int column = 0; column < width; column++) {
                rows.append(argb[row * width + column] == INK ? '#' : '.');
            }
            rows.append('\n');
        }
        return rows.toString();
    }

    @ParameterizedTest(name = "\"{0}\" at scale {1} is {2} pixels wide")
    @CsvSource(delimiter = '|', value = {
        "''|1|0", "A|1|5", "AB|1|11", "A1|2|22", "'H8 '|3|51", "12.5%|1|29"})
    void textWidthIsSixPixelsAGlyphLessTheLastGap(String text, int scale, int expected) {
        assertEquals(expected, BitmapFont.textWidth(text, scale));
    }

    @Test
    void textHeightIsSevenRowsAtScale() {
        assertEquals(7, BitmapFont.textHeight(1));
        assertEquals(21, BitmapFont.textHeight(3));
    }

    @Test
    void inkedExtentMatchesTextWidthAndHeight() {
        // M and W are inked in their first and last columns and rows, so they span the whole box.
        for (int scale = 1; scale <= 3; scale++) {
            int[] argb = new int[100 * 40];
            BitmapFont.drawText(argb, 100, 40, 4, 5, "MW", scale, INK);
            int minX = Integer.MAX_VALUE;
            int maxX = -1;
            int minY = Integer.MAX_VALUE;
            int maxY = -1;
            for (int i = 0; i < argb.length; i++) {
                if (argb[i] == INK) {
                    minX = Math.min(minX, i % 100);
                    maxX = Math.max(maxX, i % 100);
                    minY = Math.min(minY, i / 100);
                    maxY = Math.max(maxY, i / 100);
                }
            }
            assertEquals(4, minX);
            assertEquals(5, minY);
            assertEquals(BitmapFont.textWidth("MW", scale), maxX - minX + 1, "width at scale " + scale);
            assertEquals(BitmapFont.textHeight(scale), maxY - minY + 1, "height at scale " + scale);
        }
    }

    @Test
    void glyphIsDrawnUprightAndUnmirrored() {
        String expected = ""
                + "#####.\n"
                + "#.....\n"
                + "#.....\n"
                + "####..\n"
                + "#.....\n"
                + "#.....\n"
                + "#.....\n";
        assertEquals(expected, picture(6, 7, 0, 0, "F", 1));
    }

    @Test
    void scaleMakesBlocks() {
        String expected = ""
                + "....##....\n"
                + "....##....\n"
                + "..####....\n"
                + "..####....\n"
                + "....##....\n"
                + "....##....\n"
                + "....##....\n"
                + "....##....\n"
                + "....##....\n"
                + "....##....\n"
                + "....##....\n"
                + "....##....\n"
                + "..######..\n"
                + "..######..\n";
        assertEquals(expected, picture(10, 14, 0, 0, "1", 2));
    }

    @Test
    void everyGlyphIsDistinctAndInked() {
        Map<String, Character> seen = new HashMap<>();
        for (char c : ALL.toCharArray()) {
            assertTrue(BitmapFont.hasGlyph(c), "glyph for " + c);
            String shape = picture(5, 7, 0, 0, String.valueOf(c), 1);
            assertTrue(shape.contains("#"), "glyph " + c + " is blank");
            Character twin = seen.put(shape, c);
            assertEquals(null, twin, "glyphs " + twin + " and " + c + " look the same");
        }
    }

    @Test
    void spaceDrawsNothing() {
        assertTrue(BitmapFont.hasGlyph(' '));
        assertFalse(picture(6, 8, 0, 0, " ", 1).contains("#"));
    }

    @Test
    void lowerCaseIsDrawnAsUpperCaseAndUnknownAsQuestionMark() {
        assertEquals(picture(30, 8, 0, 0, "ABC", 1), picture(30, 8, 0, 0, "abc", 1));
        assertFalse(BitmapFont.hasGlyph('@'));
        assertFalse(BitmapFont.hasGlyph('\u00e9'));
        assertEquals(picture(6, 8, 0, 0, "?", 1), picture(6, 8, 0, 0, "@", 1));
        assertEquals(picture(6, 8, 0, 0, "?", 1), picture(6, 8, 0, 0, "\u4e2d", 1));
    }

    @Test
    void clippingKeepsTheVisiblePart() {
        // "8" drawn three pixels left of the buffer: its last two columns remain, at x = 0 and 1.
        String shifted = picture(4, 7, -3, 0, "8", 1);
        String expected = ""
                + "#...\n"
                + ".#..\n"
                + ".#..\n"
                + "#...\n"
                + ".#..\n"
                + ".#..\n"
                + "#...\n";
        assertEquals(expected, shifted);
        // And four rows above it: the last three rows remain.
        String raised = picture(5, 3, 0, -4, "8", 1);
        assertEquals("#...#\n#...#\n.###.\n", raised);
    }

    @Test
    void drawingAnywhereNeverThrows() {
        int[] positions = {Integer.MIN_VALUE, -1_000_000, -50, -7, -1, 0, 1, 9, 10, 11, 1_000_000, Integer.MAX_VALUE};
        int[] scales = {1, 2, 7, 1 << 20, Integer.MAX_VALUE};
        int[] argb = new int[10 * 10];
        for (int x : positions) {
            for (int y : positions) {
                for (int scale : scales) {
                    assertDoesNotThrow(() -> BitmapFont.drawText(argb, 10, 10, x, y, "W8%", scale, INK),
                            "at (" + x + ", " + y + ") scale " + scale);
                }
            }
        }
        assertDoesNotThrow(() -> BitmapFont.drawText(new int[0], 0, 0, 0, 0, "A", 1, INK));
    }

    @Test
    void hugeScaleFillsTheBufferFromTheGlyphsTopLeftBlock() {
        int[] argb = new int[8 * 8];
        BitmapFont.drawText(argb, 8, 8, 0, 0, "M", Integer.MAX_VALUE, INK);
        int[] full = new int[8 * 8];
        Arrays.fill(full, INK);
        assertArrayEquals(full, argb, "M's top-left font pixel is inked and covers the buffer");
    }

    @Test
    void badArgumentsAreRejected() {
        assertThrows(IllegalArgumentException.class, () -> BitmapFont.textWidth("A", 0));
        assertThrows(IllegalArgumentException.class, () -> BitmapFont.textHeight(-1));
        assertThrows(IllegalArgumentException.class,
                () -> BitmapFont.drawText(new int[10], 4, 4, 0, 0, "A", 1, INK));
        assertThrows(IllegalArgumentException.class,
                () -> BitmapFont.drawText(new int[16], 4, 4, 0, 0, "A", 0, INK));
        assertThrows(ArithmeticException.class, () -> BitmapFont.textWidth("AB", Integer.MAX_VALUE));
    }
}
