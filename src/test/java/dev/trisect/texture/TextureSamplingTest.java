package dev.trisect.texture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Nearest sampling with repeat exactly as conventions.md says (OpenGL's GL_NEAREST + GL_REPEAT): column
 * {@code floorMod(floor(u * W), W)}, row from the bottom {@code floorMod(floor(v * H), H)}, image row
 * {@code H - 1 - rowFromBottom}.
 */
class TextureSamplingTest {
    /** A texture whose texel at index i holds i, so a sample tells where it came from. */
    private static Texture indexed(int width, int height) {
        int[] argb = new int[width * height];
        for (int i = 0; i < argb.length; i++) {
            argb[i] = i;
        }
        return new Texture("indexed", width, height, argb);
    }

    private static int column(Texture texture, double u, double v) {
        return texture.sampleUv(u, v) % texture.width();
    }

    private static int imageRow(Texture texture, double u, double v) {
        return texture.sampleUv(u, v) / texture.width();
    }

    @Test
    void aTextureWithoutANameIsRefused() {
        // A null name would surface only as "null" in some later message.
        NullPointerException e = assertThrows(NullPointerException.class,
                () -> Texture.solid(null, 0xFF112233));
        assertEquals("texture name is null", e.getMessage());
        assertThrows(NullPointerException.class,
                () -> new Texture(null, 1, 1, new int[] {0}));
    }

    @Test
    void uvOriginIsTheBottomLeftOfTheImage() {
        int red = 0xFFFF0000;
        int green = 0xFF00FF00;
        int blue = 0xFF0000FF;
        int white = 0xFFFFFFFF;
        // Image rows as stored: row 0 (the top) is red, green; row 1 (the bottom) is blue, white.
        Texture texture = new Texture("2x2", 2, 2, new int[] {red, green, blue, white});
        assertEquals(blue, texture.sampleUv(0.25, 0.25), "bottom-left");
        assertEquals(white, texture.sampleUv(0.75, 0.25), "bottom-right");
        assertEquals(red, texture.sampleUv(0.25, 0.75), "top-left");
        assertEquals(green, texture.sampleUv(0.75, 0.75), "top-right");
    }

    @Test
    void coordinatesRepeat() {
        Texture texture = indexed(4, 4);
        for (double u : new double[] {1.25, 2.25, -0.75, 1000.25, -1000.75}) {
            assertEquals(texture.sampleUv(0.25, 0.5), texture.sampleUv(u, 0.5), "u = " + u + " repeats 0.25");
            assertEquals(texture.sampleUv(0.5, 0.25), texture.sampleUv(0.5, u), "v = " + u + " repeats 0.25");
        }
    }

    @Test
    void slightlyNegativeCoordinatesWrapToTheFarEdge() {
        // Truncating -0.04 toward zero would give column 0 and the bottom row: the classic (int) bug.
        Texture texture = indexed(4, 3);
        assertEquals(3, column(texture, -0.01, 0.5), "u = -0.01 picks the last column");
        assertEquals(0, imageRow(texture, 0.5, -0.01), "v = -0.01 picks the top image row (last from the bottom)");
        assertEquals(2, column(texture, -0.26, 0.5), "u = -0.26 picks the column before the last");
    }

    @Test
    void vGrowsUpwardsWhileImageRowsGrowDownwards() {
        Texture texture = indexed(3, 5);
        assertEquals(4, imageRow(texture, 0.5, 1e-9), "v just above 0 picks the image's bottom row");
        assertEquals(4, imageRow(texture, 0.5, 0.0), "v = 0 picks the bottom row");
        assertEquals(0, imageRow(texture, 0.5, 1 - 1e-9), "v just below 1 picks the top row");
        assertEquals(4, imageRow(texture, 0.5, 1.0), "v = 1 wraps to the bottom row");
        assertEquals(0, column(texture, 1.0, 0.5), "u = 1 wraps to the first column");
    }

    @ParameterizedTest(name = "{0}x{1}")
    @CsvSource({"3, 5", "300, 7", "7, 300", "1, 1", "2, 3"})
    void texelCentresPickTheirTexelForSizesThatAreNotPowersOfTwo(int width, int height) {
        Texture texture = indexed(width, height);
        for (int c = 0; c < width; c++) {
            assertEquals(c, column(texture, (c + 0.5) / width, 0.5), "column " + c);
        }
        for (int fromBottom = 0; fromBottom < height; fromBottom++) {
            assertEquals(height - 1 - fromBottom, imageRow(texture, 0.5, (fromBottom + 0.5) / height),
                    "row " + fromBottom + " from the bottom");
        }
    }

    @Test
    void aTexelOwnsItsLowerEdgeNotItsUpperOne() {
        Texture texture = indexed(5, 3);
        for (int k = 0; k < 5; k++) {
            assertEquals(k, texture.texelIndex(k, 0.5) % 5, "s = " + k + " exactly picks column " + k);
            assertEquals(Math.floorMod(k - 1, 5), texture.texelIndex(Math.nextDown((double) k), 0.5) % 5,
                    "s just below " + k + " picks the column before");
        }
        for (int k = 0; k < 3; k++) {
            assertEquals(2 - k, texture.texelIndex(0.5, k) / 5, "t = " + k + " picks row " + k + " from the bottom");
        }
        assertEquals(0, texture.texelIndex(-5.0, 0.5) % 5, "s = -W is column 0");
        assertEquals(4, texture.texelIndex(-1.0, 0.5) % 5, "s = -1 is the last column");
    }

    @Test
    void uTimesWidthExactlyIntegerPicksThatColumn() {
        int checked = 0;
        for (int width : new int[] {3, 5, 7, 300}) {
            Texture texture = indexed(width, 1);
            for (int k = 0; k < width; k++) {
                double u = k / (double) width;
                if (u * width == k) { // only where the product is exact in floating point
                    assertEquals(k, column(texture, u, 0.5), "u = " + k + "/" + width);
                    checked++;
                }
            }
        }
        assertEquals(75, column(indexed(300, 1), 0.25, 0.5), "u = 0.25 on 300 texels is column 75");
        assertTrue(checked > 100, "enough exact cases were checked: " + checked);
    }
}
