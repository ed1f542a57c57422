package dev.trisect.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** The quads' coverage rule, nearest texel, alpha test, blend and depth, on hand-worked cases. */
class QuadRasterTest {
    private static final int W = 8;
    private static final int H = 4;

    /** Draws the quads as the frame does: QUAD commands in the order added, band by band. */
    private static int[] draw(QuadRaster quads, int[] colour, float[] depth) {
        quads.setUp(W, H);
        Commands list = new Commands().quads(quads);
        for (int s = 0; s < quads.count(); s++) {
            list.add(Commands.QUAD, s, quads.firstRow(s), quads.lastRow(s) + 1);
        }
        list.bin(H, 2);
        for (int b = 0; b < 2; b++) {
            for (int k = list.bins().start(b); k < list.bins().start(b + 1); k++) {
                quads.rows(Commands.ref(list.command(list.bins().items()[k])), colour, depth, 2 * b, 2 * b + 2);
            }
        }
        return colour;
    }

    @Test
    void coversThePixelsWhoseCentresItHoldsWithTheNearestTexel() {
        QuadRaster quads = new QuadRaster();
        // Columns whose centres are in [1.5, 5.5): 1..4; rows in [0.5, 2.5): 0 and 1 (row 2's centre is 2.5).
        int[] texels = {0xFF000001, 0xFF000002, 0x00000003, 0xFF000004};
        quads.add(1.5, 0.5, 5.5, 2.5, 1, texels, 4, 0, 4, 1, QuadRaster.TEST, 0, QuadRaster.BILLBOARD);
        int[] c = draw(quads, new int[W * H], new float[W * H]);
        int[] row = Arrays.copyOfRange(c, 0, W);
        // Texel of column x: floor((x + 0.5 - 1.5) * 4 / 4); texel 2 has alpha 0 and is not drawn.
        assertEquals(Arrays.toString(new int[] {0, 0xFF000001, 0xFF000002, 0, 0xFF000004, 0, 0, 0}),
                Arrays.toString(row));
        assertEquals(Arrays.toString(row), Arrays.toString(Arrays.copyOfRange(c, W, 2 * W)));
        assertEquals(0, Arrays.stream(c, 2 * W, 4 * W).sum());
        assertEquals(3, quads.count(QuadRaster.BILLBOARD) + 2);
    }

    @Test
    void depthTestsBlendsAndDrawsOnTop() {
        QuadRaster quads = new QuadRaster();
        int[] colour = new int[W * H];
        Arrays.fill(colour, 0xFF000000 | 200 << 16 | 100);
        float[] depth = new float[W * H];
        Arrays.fill(depth, 0.5f);
        int[] half = {0x80FFFFFF};
        // Behind the frame (1/w 0.25 < 0.5): not drawn; in front, blended: 255 * 128/255 + 200 * 127/255.
        quads.add(0, 0, 1, 1, 0.25, half, 1, 0, 1, 1, QuadRaster.BLEND, 0xFFFFFFFF, QuadRaster.OTHER);
        quads.add(1, 0, 2, 1, 1.0, half, 1, 0, 1, 1, QuadRaster.BLEND, 0xFFFFFFFF, QuadRaster.OTHER);
        // On top, behind: drawn anyway, tinted, depth left alone.
        quads.add(2, 0, 3, 1, 0.25, new int[] {0xFFFFFFFF}, 1, 0, 1, 1, QuadRaster.TEST | QuadRaster.ON_TOP
                | QuadRaster.TINT, 0x00FF00, QuadRaster.GLYPH);
        draw(quads, colour, depth);
        assertEquals(0xFF000000 | 200 << 16 | 100, colour[0]);
        int r = (255 * 128 + 200 * 127 + 127) / 255;
        int b = (255 * 128 + 100 * 127 + 127) / 255;
        int g = (255 * 128 + 127) / 255;
        assertEquals(0xFF000000 | r << 16 | g << 8 | b, colour[1]);
        assertEquals(0.5f, depth[1], "a blended quad writes no depth");
        assertEquals(0xFF00FF00, colour[2]);
        assertEquals(0.5f, depth[2]);
    }
}
