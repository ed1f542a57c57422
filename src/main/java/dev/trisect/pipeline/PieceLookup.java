package dev.trisect.pipeline;

import dev.trisect.raster.OutlineProbe;
import dev.trisect.raster.PixelState;
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
        return info(chunks, (int) (at >>> 32), (int) at);
    }

    /** Piece i of chunk c as the inspector shows it. */
    private static PieceInfo info(Chunks chunks, int c, int i) {
        int index = i;
        for (int k = 0; k < c; k++) {
            index += chunks.get(k).out.count();
        }
        ScreenTriangles t = chunks.get(c).out;
        int s = i * ScreenTriangles.SCREEN_STRIDE;
        int a = i * t.attributeStride();
        int cs = t.cornerStride();
        // Per corner 1/w, s, t, whatever further varyings the layout carries.
        double[] qst = new double[9];
        for (int k = 0; k < 3; k++) {
            System.arraycopy(t.attributes(), a + k * cs, qst, 3 * k, 3);
        }
        // A frame carrying colours holds r, g, b in varyings 2..4: corner slots 3..5 after 1/w, s, t;
        // or, without a smooth material, once per triangle in a flat value, packed: every corner's.
        double[] rgb = null;
        int fs = t.layout().flats();
        if (t.layout().varyings() > PixelState.COLOUR_SLOT) {
            rgb = new double[9];
            for (int k = 0; k < 3; k++) {
                System.arraycopy(t.attributes(), a + k * cs + 1 + PixelState.COLOUR_SLOT, rgb, 3 * k, 3);
            }
        } else if (fs > PixelState.FLAT_COLOUR) {
            rgb = new double[9];
            double flat = t.attributes()[a + t.flatOffset() + PixelState.FLAT_COLOUR];
            for (int k = 0; k < 9; k++) {
                rgb[k] = PixelState.flatChannel(flat, k % 3);
            }
        }
        return new PieceInfo(index, t.ids()[i], t.levels()[i], t.perPixel()[i],
                Arrays.copyOfRange(t.screen(), s, s + ScreenTriangles.SCREEN_STRIDE), qst, rgb);
    }

    /**
     * The last piece filled per pixel, in drawing order, whose outline lights pixel (x, y) of a frame
     * {@code height} rows high holding 1/w = {@code depth} there ({@link OutlineProbe}); null for none.
     */
    static PieceInfo fallbackOutline(Chunks chunks, int chunkCount, int x, int y, int height, double depth) {
        for (int c = chunkCount - 1; c >= 0; c--) {
            ScreenTriangles t = chunks.get(c).out;
            for (int i = t.count() - 1; i >= 0; i--) {
                if (t.perPixel()[i] && OutlineProbe.lights(t, i, x, y, height, depth)) {
                    return info(chunks, c, i);
                }
            }
        }
        return null;
    }

    /**
     * The knots of row y of the filled triangle of input triangle {@code triangle} that covers pixel
     * (x, y) (by the fill's own coverage, so that a clipped triangle's fan gives the part that drew the
     * pixel), as the span path with knot error {@code knotError} placed them in a frame {@code width}
     * pixels wide; among several, the one whose 1/w plane there is closest to {@code depth}. Null when
     * none covers the pixel.
     */
    static RowKnots knots(Chunks chunks, int chunkCount, int x, int y, int triangle, double depth, int width,
                          double knotError) {
        RowKnots best = null;
        double bestGap = Double.POSITIVE_INFINITY;
        for (int c = 0; c < chunkCount; c++) {
            ScreenTriangles t = chunks.get(c).out;
            for (int i = 0; i < t.count(); i++) {
                if (t.ids()[i] != triangle || y < t.firstRow(i) || y >= t.endRow(i)) {
                    continue;
                }
                RowKnots k = RowKnots.of(t, i, width, y, knotError);
                int[] columns = k.columns();
                if (columns.length == 0 || x < columns[0] || x > columns[columns.length - 1]) {
                    continue;
                }
                double gap = Math.abs(depthAt(t, i, x + 0.5, y + 0.5) - depth);
                if (gap < bestGap) {
                    bestGap = gap;
                    best = k;
                }
            }
        }
        return best;
    }

    /** 1/w of screen triangle i's plane at (x, y), pixels. */
    private static double depthAt(ScreenTriangles t, int i, double x, double y) {
        double[] w = weights(t.screen(), i * ScreenTriangles.SCREEN_STRIDE, x, y);
        double[] at = t.attributes();
        int a = i * t.attributeStride();
        int cs = t.cornerStride();
        return w == null ? Double.NaN : w[0] * at[a] + w[1] * at[a + cs] + w[2] * at[a + 2 * cs];
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
                int a = i * t.attributeStride();
                int cs = t.cornerStride();
                double q = w[0] * at[a] + w[1] * at[a + cs] + w[2] * at[a + 2 * cs];
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
        double[] w = weights(sc, s, x, y);
        double slack = -1e-9;
        return w != null && w[0] >= slack && w[1] >= slack && w[2] >= slack ? w : null;
    }

    /** Barycentric weights of (x, y) on the plane of the screen triangle at {@code s}; null when it has no area. */
    private static double[] weights(double[] sc, int s, double x, double y) {
        double[] e = new double[ScreenTriangles.EDGES];
        if (!ScreenTriangles.edges(sc, s, e)) {
            return null;
        }
        // (x, y) from corner 0, against the edges e[2..3] and e[4..5] and their cross product e[6].
        double dx = x - e[0];
        double dy = y - e[1];
        double b1 = (dx * e[5] - e[4] * dy) / e[6];
        double b2 = (e[2] * dy - dx * e[3]) / e[6];
        return new double[] {1 - b1 - b2, b1, b2};
    }
}
