package dev.trisect.raster;

import dev.trisect.render.Framebuffer;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.texture.Texture;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class FillRuleTest {
    private static final int W = 64;
    private static final int H = 48;

    private static void add(ScreenTriangles t, double x0, double y0, double x1, double y1, double x2, double y2) {
        t.add(x0, y0, 1, 0, 0, x1, y1, 1, 0, 0, x2, y2, 1, 0, 0, t.count(), 0);
    }

    private static int[] all(ScreenTriangles t) {
        int[] order = new int[t.count()];
        for (int i = 0; i < order.length; i++) {
            order[i] = i;
        }
        return order;
    }

    private static int[] coverage(ScreenTriangles t, int x0, int y0, int x1, int y1) {
        int[] counts = new int[W * H];
        new Rasterizer().countCoverage(counts, W, t, all(t), 0, t.count(), x0, y0, x1, y1);
        return counts;
    }

    /**
     * The definition, pixel by pixel, written independently of the rasterizer's span solving:
     * centre (x + 0.5, y + 0.5) on the 1/256 grid, edge functions on snapped corners, a centre on an
     * edge belongs to the triangle when the edge is a top edge (horizontal, interior below) or a
     * left edge (interior to its right), in image coordinates with y down.
     */
    private static int[] bruteForce(ScreenTriangles t) {
        int[] counts = new int[W * H];
        int[] f = t.fixed();
        for (int i = 0; i < t.count(); i++) {
            long[] x = {f[6 * i], f[6 * i + 2], f[6 * i + 4]};
            long[] y = {f[6 * i + 1], f[6 * i + 3], f[6 * i + 5]};
            long area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
            if (area == 0) {
                continue;
            }
            if (area < 0) {
                long tx = x[1];
                x[1] = x[2];
                x[2] = tx;
                long ty = y[1];
                y[1] = y[2];
                y[2] = ty;
            }
            for (int py = 0; py < H; py++) {
                for (int px = 0; px < W; px++) {
                    long cx = 256L * px + 128;
                    long cy = 256L * py + 128;
                    boolean inside = true;
                    for (int e = 0; e < 3 && inside; e++) {
                        long ax = x[e];
                        long ay = y[e];
                        long bx = x[(e + 1) % 3];
                        long by = y[(e + 1) % 3];
                        long ef = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
                        boolean topLeft = (by - ay) < 0 || ((by - ay) == 0 && (bx - ax) > 0);
                        inside = ef > 0 || (ef == 0 && topLeft);
                    }
                    if (inside) {
                        counts[py * W + px]++;
                    }
                }
            }
        }
        return counts;
    }

    @Test
    void squareWithCornersOnPixelCentresGetsLeftAndTopEdgesOnly() {
        ScreenTriangles t = new ScreenTriangles();
        // Square from centre (10.5, 10.5) to centre (20.5, 20.5), split along a diagonal.
        add(t, 10.5, 10.5, 20.5, 10.5, 20.5, 20.5);
        add(t, 10.5, 10.5, 20.5, 20.5, 10.5, 20.5);
        int[] c = coverage(t, 0, 0, W, H);
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int expected = (x >= 10 && x < 20 && y >= 10 && y < 20) ? 1 : 0;
                assertEquals(expected, c[y * W + x], "pixel " + x + "," + y);
            }
        }
    }

    @ParameterizedTest
    @ValueSource(ints = {3, 4, 5, 8, 13, 32})
    void fanAroundOneVertexCoversEveryPixelOnce(int blades) {
        // Centre exactly on a pixel centre, so many edges pass through pixel centres.
        double cx = 31.5;
        double cy = 23.5;
        ScreenTriangles t = new ScreenTriangles();
        double[] px = new double[blades];
        double[] py = new double[blades];
        for (int k = 0; k < blades; k++) {
            double a = 2 * Math.PI * k / blades + 0.1;
            px[k] = cx + 20 * Math.cos(a);
            py[k] = cy + 20 * Math.sin(a);
        }
        for (int k = 0; k < blades; k++) {
            int n = (k + 1) % blades;
            add(t, cx, cy, px[k], py[k], px[n], py[n]);
        }
        int[] c = coverage(t, 0, 0, W, H);
        int total = 0;
        for (int v : c) {
            assertTrue(v <= 1, "no pixel twice");
            total += v;
        }
        // The centre pixel, whose centre is the shared vertex, belongs to exactly one blade.
        assertEquals(1, c[23 * W + 31]);
        // Every pixel well inside the fan's outline is covered (a regular polygon of radius 20).
        double inner = 20 * Math.cos(Math.PI / blades) - 1;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                if (Math.hypot(x + 0.5 - cx, y + 0.5 - cy) < inner) {
                    assertEquals(1, c[y * W + x], "pixel " + x + "," + y);
                }
            }
        }
        assertArrayEquals(bruteForce(t), c);
        assertTrue(total > 0);
    }

    @Test
    void randomTrianglesCoverExactlyTheCentresTheDefinitionGives() {
        Random rnd = new Random(42);
        for (int round = 0; round < 200; round++) {
            ScreenTriangles t = new ScreenTriangles();
            for (int k = 0; k < 5; k++) {
                double scale = rnd.nextInt(4) == 0 ? 400 : 80;
                double ox = rnd.nextDouble() * W;
                double oy = rnd.nextDouble() * H;
                if (rnd.nextBoolean()) {
                    // Corners on pixel centres and integer positions: edges through centres.
                    add(t, Math.round(ox) + 0.5, Math.round(oy) + 0.5,
                            Math.round(ox + (rnd.nextDouble() - 0.5) * scale) + (rnd.nextBoolean() ? 0.5 : 0),
                            Math.round(oy + (rnd.nextDouble() - 0.5) * scale),
                            Math.round(ox + (rnd.nextDouble() - 0.5) * scale),
                            Math.round(oy + (rnd.nextDouble() - 0.5) * scale) + 0.5);
                } else {
                    add(t, ox, oy, ox + (rnd.nextDouble() - 0.5) * scale, oy + (rnd.nextDouble() - 0.5) * scale,
                            ox + (rnd.nextDouble() - 0.5) * scale, oy + (rnd.nextDouble() - 0.5) * scale);
                }
            }
            assertArrayEquals(bruteForce(t), coverage(t, 0, 0, W, H), "round " + round);
        }
    }

    @Test
    void anyRectangleOfTheFrameCoversExactlyTheDefinitionsCentresInIt() {
        // Small triangles with corners often at pixel-centre heights (the row through a middle corner
        // is the one where the span solver needs all three edges), filled within random rectangles;
        // a few reach far outside the frame, as clipped triangles do (guard band 8192 px).
        Random rnd = new Random(11);
        for (int round = 0; round < 600; round++) {
            ScreenTriangles t = new ScreenTriangles();
            for (int k = 0; k < 6; k++) {
                double[] p = new double[6];
                double ox = rnd.nextDouble() * W;
                double oy = rnd.nextDouble() * H;
                // Mostly piece-sized, some larger than the frame, some reaching across the guard band.
                int kind = rnd.nextInt(8);
                double scale = kind == 0 ? 36000 : kind < 3 ? 120 : 24;
                for (int i = 0; i < 6; i++) {
                    double v = (i % 2 == 0 ? ox : oy) + (rnd.nextDouble() - 0.5) * scale;
                    p[i] = rnd.nextBoolean() ? Math.round(v * 2) / 2.0 : v;
                }
                add(t, p[0], p[1], p[2], p[3], p[4], p[5]);
            }
            int x0 = rnd.nextInt(W);
            int y0 = rnd.nextInt(H);
            int x1 = x0 + 1 + rnd.nextInt(W - x0);
            int y1 = y0 + 1 + rnd.nextInt(H - y0);
            int[] expected = bruteForce(t);
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    if (x < x0 || x >= x1 || y < y0 || y >= y1) {
                        expected[y * W + x] = 0;
                    }
                }
            }
            assertArrayEquals(expected, coverage(t, x0, y0, x1, y1), "round " + round);
        }
    }

    @Test
    void twoTrianglesSharingAnyEdgeCoverTheirUnionOnce() {
        Random rnd = new Random(7);
        for (int round = 0; round < 500; round++) {
            // Quad a, b, c, d split along a-c; corners on the 1/4-pixel grid to hit centres often.
            double[] q = new double[8];
            for (int k = 0; k < 8; k++) {
                q[k] = Math.round(rnd.nextDouble() * (k % 2 == 0 ? W : H) * 4) / 4.0;
            }
            ScreenTriangles t = new ScreenTriangles();
            add(t, q[0], q[1], q[2], q[3], q[4], q[5]);
            add(t, q[0], q[1], q[4], q[5], q[6], q[7]);
            // Only a convex quad is tiled by the two triangles without overlap.
            if (!convex(q)) {
                continue;
            }
            int[] c = coverage(t, 0, 0, W, H);
            for (int v : c) {
                assertTrue(v <= 1, "shared edge drawn twice in round " + round);
            }
        }
    }

    private static boolean convex(double[] q) {
        int sign = 0;
        for (int k = 0; k < 4; k++) {
            double ax = q[2 * k];
            double ay = q[2 * k + 1];
            double bx = q[2 * ((k + 1) % 4)];
            double by = q[2 * ((k + 1) % 4) + 1];
            double cx = q[2 * ((k + 2) % 4)];
            double cy = q[2 * ((k + 2) % 4) + 1];
            double cross = (bx - ax) * (cy - by) - (by - ay) * (cx - bx);
            int s = (int) Math.signum(cross);
            if (s == 0 || (sign != 0 && s != sign)) {
                return false;
            }
            sign = s;
        }
        return true;
    }

    @Test
    void fillingInBandsGivesTheSamePixelsAsFillingWhole() {
        Random rnd = new Random(3);
        ScreenTriangles t = new ScreenTriangles();
        for (int k = 0; k < 60; k++) {
            double x = rnd.nextDouble() * W;
            double y = rnd.nextDouble() * H;
            double q0 = 0.1 + rnd.nextDouble();
            t.add(x, y, q0, 3 * x, 5 * y,
                    x + rnd.nextGaussian() * 30, y + rnd.nextGaussian() * 30, 0.1 + rnd.nextDouble(), 17, -4,
                    x + rnd.nextGaussian() * 30, y + rnd.nextGaussian() * 30, 0.1 + rnd.nextDouble(), -9, 40,
                    k, k % 2);
        }
        Texture[] textures = {checker(16, 16), checker(5, 7)};
        for (boolean perspective : new boolean[] {true, false}) {
            Framebuffer whole = new Framebuffer(W, H);
            whole.recordUv(true);
            whole.clearRows(0, H, 0);
            new Rasterizer().fill(whole, t, all(t), 0, t.count(), textures, perspective, 0, 0, W, H);
            Framebuffer tiled = new Framebuffer(W, H);
            tiled.recordUv(true);
            tiled.clearRows(0, H, 0);
            Rasterizer r = new Rasterizer();
            for (int ty = 0; ty < H; ty += 7) {
                for (int tx = 0; tx < W; tx += 11) {
                    r.fill(tiled, t, all(t), 0, t.count(), textures, perspective, tx, ty,
                            Math.min(W, tx + 11), Math.min(H, ty + 7));
                }
            }
            assertArrayEquals(whole.colour(), tiled.colour());
            assertArrayEquals(whole.depth(), tiled.depth());
            assertArrayEquals(whole.uv(), tiled.uv());
        }
    }

    @Test
    void nearerSurfaceWinsWhateverTheOrderAndTiesGoToTheFirst() {
        Texture red = Texture.solid("red", 0xFFFF0000);
        Texture blue = Texture.solid("blue", 0xFF0000FF);
        for (int order = 0; order < 2; order++) {
            ScreenTriangles t = new ScreenTriangles();
            // Material 0 (red) at w = 2 (q = 0.5); material 1 (blue) at w = 4 (q = 0.25), same place.
            double qNear = 0.5;
            double qFar = 0.25;
            int first = order == 0 ? 0 : 1;
            for (int k = 0; k < 2; k++) {
                int m = k == 0 ? first : 1 - first;
                double q = m == 0 ? qNear : qFar;
                t.add(2, 2, q, 0, 0, 60, 2, q, 0, 0, 2, 40, q, 0, 0, k, m);
            }
            Framebuffer fb = new Framebuffer(W, H);
            fb.clearRows(0, H, 0);
            new Rasterizer().fill(fb, t, all(t), 0, 2, new Texture[] {red, blue}, true, 0, 0, W, H);
            assertEquals(0xFFFF0000, fb.colour()[10 * W + 10], "nearer (red) wins, order " + order);
        }
        ScreenTriangles tie = new ScreenTriangles();
        tie.add(2, 2, 0.5, 0, 0, 60, 2, 0.5, 0, 0, 2, 40, 0.5, 0, 0, 0, 1);
        tie.add(2, 2, 0.5, 0, 0, 60, 2, 0.5, 0, 0, 2, 40, 0.5, 0, 0, 1, 0);
        Framebuffer fb = new Framebuffer(W, H);
        fb.clearRows(0, H, 0);
        new Rasterizer().fill(fb, tie, all(tie), 0, 2, new Texture[] {red, blue}, true, 0, 0, W, H);
        assertEquals(0xFF0000FF, fb.colour()[10 * W + 10], "equal depth: the first drawn stays (less-than)");
    }

    private static Texture checker(int w, int h) {
        int[] px = new int[w * h];
        for (int i = 0; i < px.length; i++) {
            px[i] = 0xFF000000 | (i * 2654435761L > 0 ? 0x123456 * i : 0xABCDEF ^ i);
        }
        return new Texture("checker", w, h, px);
    }

    @Test
    void perPixelFlagFillsAPieceExactlyAsThePerspectivePath() {
        Texture[] tex = {Texture.solid("grey", 0xFF808080)};
        double[][] uv = new double[2][];
        for (int pass = 0; pass < 2; pass++) {
            ScreenTriangles t = new ScreenTriangles();
            // Depths 1 to 8 across the triangle: affine and perspective differ at almost every pixel.
            t.add(3.3, 2.1, 1, 0, 0, 60.7, 9.4, 0.125, 40, 3, 8.2, 45.5, 0.5, 5, 30, 0, 0, pass == 1);
            Framebuffer fb = new Framebuffer(W, H);
            fb.recordUv(true);
            fb.clearRows(0, H, 0);
            // Pass 0: the perspective path; pass 1: the affine path with the piece flagged per pixel.
            new Rasterizer().fill(fb, t, all(t), 0, 1, tex, pass == 0, 0, 0, W, H);
            uv[pass] = fb.uv().clone();
        }
        assertArrayEquals(uv[0], uv[1]);
    }
}
