package dev.trisect.raster;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The line rasterizer's rules (OpenGL 1.x, section 3.4) on hand-made segments. */
class LineRasterTest {
    private static final int W = 32;
    private static final int H = 32;
    private static final int RED = 0xFF0000;

    private final int[] color = new int[W * H];
    private final float[] depth = new float[W * H];

    private long draw(double x1, double y1, double x2, double y2, int width) {
        LineRaster r = new LineRaster();
        r.begin(W, H);
        r.add(x1, y1, 0.5, x2, y2, 0.5, width, RED);
        return r.draw(color, depth, 0, H);
    }

    private boolean lit(int x, int y) {
        return color[y * W + x] == (RED | 0xFF000000);
    }

    @Test
    void aSegmentFromCentreToCentreLightsItsStartAndLeavesItsEndToTheNext() {
        assertEquals(4, draw(0.5, 2.5, 4.5, 2.5, 1));
        for (int x = 0; x < 4; x++) {
            assertTrue(lit(x, 2), "column " + x);
        }
        assertFalse(lit(4, 2), "the end's pixel: the segment does not leave its diamond");
    }

    @Test
    void aClosedPolylineLightsEachOfItsPixelsOnce() {
        double[][] corners = {{0.5, 0.5}, {9.5, 1.5}, {10.2, 9.7}, {1.3, 8.6}};
        int[] count = new int[W * H];
        int total = 0;
        for (int i = 0; i < corners.length; i++) {
            java.util.Arrays.fill(color, 0);
            java.util.Arrays.fill(depth, 0);
            double[] a = corners[i];
            double[] b = corners[(i + 1) % corners.length];
            total += (int) draw(a[0], a[1], b[0], b[1], 1);
            for (int p = 0; p < W * H; p++) {
                count[p] += color[p] != 0 ? 1 : 0;
            }
        }
        int distinct = 0;
        for (int c : count) {
            assertTrue(c <= 1, "a pixel lit twice");
            distinct += c;
        }
        assertEquals(total, distinct);
    }

    @Test
    void aWidth1XMajorSegmentLightsOnePixelPerColumnAndAYMajorOnePerRow() {
        Random random = new Random(7);
        for (int n = 0; n < 500; n++) {
            java.util.Arrays.fill(color, 0);
            java.util.Arrays.fill(depth, 0);
            double x1 = 2 + 28 * random.nextDouble();
            double y1 = 2 + 28 * random.nextDouble();
            double x2 = 2 + 28 * random.nextDouble();
            double y2 = 2 + 28 * random.nextDouble();
            draw(x1, y1, x2, y2, 1);
            boolean xMajor = Math.abs(x2 - x1) >= Math.abs(y2 - y1);
            for (int i = 0; i < (xMajor ? W : H); i++) {
                int inLine = 0;
                for (int j = 0; j < (xMajor ? H : W); j++) {
                    inLine += lit(xMajor ? i : j, xMajor ? j : i) ? 1 : 0;
                }
                assertTrue(inLine <= 1, "segment " + n + ": " + inLine + " pixels in one " + (xMajor ? "column" : "row"));
            }
            // Every pixel lit lies within half a pixel of the segment along the minor axis (and the
            // snapping of the parallelogram's corners to 1/256 pixel).
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    if (lit(x, y)) {
                        double cx = x + 0.5;
                        double cy = y + 0.5;
                        double off = xMajor ? Math.abs(y1 + (cx - x1) * (y2 - y1) / (x2 - x1) - cy)
                                : Math.abs(x1 + (cy - y1) * (x2 - x1) / (y2 - y1) - cx);
                        assertTrue(off <= 0.5 + 1.0 / 128, "segment " + n + " pixel " + x + "," + y + " off by " + off);
                    }
                }
            }
        }
    }

    @Test
    void aWideLineIsAColumnOfWidthPixelsPerColumn() {
        draw(2.5, 10.5, 12.5, 10.5, 3);
        for (int x = 2; x < 12; x++) {
            for (int y = 0; y < H; y++) {
                assertEquals(y >= 9 && y <= 11, lit(x, y), x + "," + y);
            }
        }
        assertFalse(lit(12, 10));
    }

    @Test
    void depthIsInterpolatedAlongTheSegmentAndTestedAsLequal() {
        LineRaster r = new LineRaster();
        r.begin(W, H);
        r.add(0.5, 4.5, 1.0, 10.5, 4.5, 0.0, 1, RED);
        java.util.Arrays.fill(depth, 4 * W, 5 * W, 0.5f);
        r.draw(color, depth, 0, H);
        for (int x = 0; x < 10; x++) {
            double q = 1 - x / 10.0;
            // Passes where it is at least the stored 0.5 (x = 5 is the tie: drawn, as GL_LEQUAL draws).
            assertEquals(q >= 0.5, lit(x, 4), "column " + x);
            assertEquals(q >= 0.5 ? (float) q : 0.5f, depth[4 * W + x], 1e-7, "column " + x);
        }
    }

    @Test
    void bandsDrawTheSamePixelsAsTheWholeFrame() {
        Random random = new Random(3);
        LineRaster r = new LineRaster();
        r.begin(W, H);
        for (int i = 0; i < 40; i++) {
            r.add(40 * random.nextDouble() - 4, 40 * random.nextDouble() - 4, random.nextDouble(),
                    40 * random.nextDouble() - 4, 40 * random.nextDouble() - 4, random.nextDouble(), 1 + i % 4,
                    random.nextInt(0xFFFFFF));
        }
        int[] whole = new int[W * H];
        r.draw(whole, new float[W * H], 0, H);
        float[] d = new float[W * H];
        for (int y = 0; y < H; y += 5) {
            r.draw(color, d, y, Math.min(H, y + 5));
        }
        assertArrayEquals(whole, color);
    }

    @Test
    void aSegmentOfNoLengthDrawsNothing() {
        LineRaster r = new LineRaster();
        r.begin(W, H);
        assertFalse(r.add(3.2, 3.2, 1, 3.2, 3.2, 1, 1, RED));
        assertEquals(0, r.count());
    }
}
