package dev.trisect.pipeline;

import dev.trisect.raster.RowKnots;
import dev.trisect.raster.ScreenTriangles;
import java.util.Arrays;

/**
 * Finds which filled triangle (tessellated piece) of a drawn frame shows a given pixel, for the pixel
 * inspector. A query scans every piece of the frame: one query at a time, never per pixel, so it
 * stays out of {@link FrameRenderer}'s per-frame work.
 */
final class PieceLookup {
    private PieceLookup() {
    }

    /**
     * The filled triangle among the chunks' screen triangles that shows pixel (x, y): among
     * those of input triangle {@code triangle} whose area holds the pixel centre, the one whose 1/w
     * plane there is closest to {@code depth} (the frame's depth buffer value). For the pixel inspector;
     * scans every piece, so one query at a time, never per pixel.
     *
     * @return the piece, or null when none holds the pixel
     */
    static PieceInfo find(Chunks chunks, int chunkCount, int x, int y, int triangle, double depth) {
        long at = locate(chunks, chunkCount, x, y, triangle, depth);
        if (at < 0) {
            return null;
        }
        int c = (int) (at >>> 32);
        int i = (int) at;
        int index = i;
        for (int k = 0; k < c; k++) {
            index += chunks.get(k).out.count();
        }
        ScreenTriangles t = chunks.get(c).out;
        int s = i * ScreenTriangles.SCREEN_STRIDE;
        int a = i * ScreenTriangles.ATTRIBUTE_STRIDE;
        return new PieceInfo(index, triangle, t.levels()[i], t.perPixel()[i],
                Arrays.copyOfRange(t.screen(), s, s + ScreenTriangles.SCREEN_STRIDE),
                Arrays.copyOfRange(t.attributes(), a, a + ScreenTriangles.ATTRIBUTE_STRIDE));
    }

    /**
     * The knots of row y of the filled triangle {@link #find} finds, as the span path with max error
     * {@code maxError} placed them in a frame {@code width} pixels wide; null when none holds the pixel.
     */
    static RowKnots knots(Chunks chunks, int chunkCount, int x, int y, int triangle, double depth, int width,
                          double maxError) {
        long at = locate(chunks, chunkCount, x, y, triangle, depth);
        return at < 0 ? null : RowKnots.of(chunks.get((int) (at >>> 32)).out, (int) at, width, y, maxError);
    }

    /** Where {@link #find}'s triangle is: its chunk in the high 32 bits, its index there in the low; -1 for none. */
    private static long locate(Chunks chunks, int chunkCount, int x, int y, int triangle, double depth) {
        double cx = x + 0.5;
        double cy = y + 0.5;
        long best = -1;
        double bestGap = Double.POSITIVE_INFINITY;
        for (int c = 0; c < chunkCount; c++) {
            ScreenTriangles t = chunks.get(c).out;
            double[] sc = t.screen();
            double[] at = t.attributes();
            for (int i = 0; i < t.count(); i++) {
                if (t.ids()[i] != triangle) {
                    continue;
                }
                double[] w = barycentric(sc, i * ScreenTriangles.SCREEN_STRIDE, cx, cy);
                if (w == null) {
                    continue;
                }
                int a = i * ScreenTriangles.ATTRIBUTE_STRIDE;
                double q = w[0] * at[a] + w[1] * at[a + 3] + w[2] * at[a + 6];
                double gap = Math.abs(q - depth);
                if (gap < bestGap) {
                    bestGap = gap;
                    best = (long) c << 32 | i;
                }
            }
        }
        return best;
    }

    /** Barycentric weights of (x, y) in the screen triangle at {@code s}, or null outside (with a hair of slack). */
    private static double[] barycentric(double[] sc, int s, double x, double y) {
        double x0 = sc[s];
        double y0 = sc[s + 1];
        double ex1 = sc[s + 2] - x0;
        double ey1 = sc[s + 3] - y0;
        double ex2 = sc[s + 4] - x0;
        double ey2 = sc[s + 5] - y0;
        double det = ex1 * ey2 - ex2 * ey1;
        if (det == 0 || !Double.isFinite(det)) {
            return null;
        }
        double b1 = ((x - x0) * ey2 - ex2 * (y - y0)) / det;
        double b2 = (ex1 * (y - y0) - (x - x0) * ey1) / det;
        double b0 = 1 - b1 - b2;
        double slack = -1e-9;
        return b0 >= slack && b1 >= slack && b2 >= slack ? new double[] {b0, b1, b2} : null;
    }
}
