package dev.trisect.pipeline;

import dev.trisect.raster.BandBins;
import dev.trisect.raster.ScreenTriangles;
import dev.trisect.raster.SplitTrees;
import dev.trisect.tessellate.VertexLayout;

/**
 * One contiguous range of input triangles as the geometry stage leaves it for the fill: its screen
 * triangles in input order, their bands of rows, and what its geometry counted. Written by one
 * thread at a time ({@link ChunkGeometry}, then {@link #bin}), read by any number afterwards.
 */
final class Chunk {
    /** Storage for at most this many triangles is never worth giving back. */
    static final int TRIM_FLOOR = 2048;

    final ScreenTriangles out = new ScreenTriangles();
    /**
     * In the tessellated path, the input triangles that were split and their split trees, whose
     * leaves are the pieces in {@link #out}: what the fill fills.
     */
    final SplitTrees trees = new SplitTrees();
    /** Whether the last attempt split its triangles: then the fill takes {@link #trees}, else {@link #out}. */
    boolean split;
    /**
     * What the fill fills in each band of {@link FrameRenderer#BAND_ROWS} rows: the screen triangles
     * of {@link #out}, or in the tessellated path the groups of {@link #trees}.
     */
    final BandBins bins = new BandBins();
    // What the last geometry attempt counted (see FrameStats for their meaning).
    long culledBack;
    long culledFrustum;
    long culledDegenerate;
    long invalid;
    long clipped;
    long pieces;
    long offScreen;
    long splits;
    int deepest;
    long caps;
    long fallback;
    /** Processor time the last attempt spent culling and clipping, and tessellating or projecting. */
    long clipNanos;
    long tessellateNanos;
    private final Retention retention = new Retention(TRIM_FLOOR);

    /** Empties the screen triangles and zeroes the counters, keeping the vertex layout. */
    void clear() {
        clear(out.layout());
    }

    /**
     * Empties the screen triangles and zeroes the counters, for a new attempt at the geometry whose
     * vertices are in {@code layout}.
     */
    void clear(VertexLayout layout) {
        out.layout(layout);
        trees.layout(layout);
        culledBack = culledFrustum = culledDegenerate = invalid = clipped = 0;
        clipNanos = tessellateNanos = 0;
    }

    /**
     * Sorts what the fill fills (the screen triangles, or in the tessellated path the split trees'
     * input triangles) into bands of rows of a frame {@code height} rows high, in order.
     */
    void bin(int bands, int height) {
        int n = split ? trees.count() : out.count();
        int[] refs = trees.refs();
        ScreenTriangles inputs = trees.inputs();
        bins.prepare(n);
        for (int i = 0; i < n; i++) {
            // A group that was split is binned by its input triangle, one that was not by its one piece.
            ScreenTriangles filled = !split ? out : refs[i] >= 0 ? inputs : out;
            int t = !split ? i : refs[i] >= 0 ? refs[i] : -1 - refs[i];
            int r0 = Math.max(0, filled.firstRow(t));
            int r1 = Math.min(height, filled.endRow(t));
            if (r0 >= r1) {
                bins.none(i);
            } else {
                bins.rows(i, r0, r1 - 1, FrameRenderer.BAND_ROWS);
            }
        }
        bins.build(n, bands);
    }

    /**
     * Tells the retention policy what this frame needed (its screen triangles, or its input triangles
     * when more) and gives back what has become far larger than that (see {@link Retention}).
     */
    void trimIfOversized() {
        ScreenTriangles inputs = trees.inputs();
        long keep = retention.keep(Math.max(out.count(), inputs.count()), Math.max(out.capacity(), inputs.capacity()));
        if (keep >= 0) {
            int n = (int) keep;
            out.shrinkTo(n);
            trees.shrinkTo(n);
            bins.shrink(n, Math.max(2 * bins.entries(), n));
        }
    }
}
