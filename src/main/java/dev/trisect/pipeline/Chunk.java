package dev.trisect.pipeline;

import dev.trisect.raster.Commands;
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
     * leaves are the pieces in {@link #out}.
     */
    final SplitTrees trees = new SplitTrees();
    /**
     * What the fill draws, in input order, binned into bands of {@link FrameRenderer#BAND_ROWS} rows: a
     * {@link Commands#TRIANGLE} per screen triangle of {@link #out}, or in the tessellated path a
     * {@link Commands#TREE} per input triangle of {@link #trees} and a {@link Commands#TRIANGLE} per one
     * that was not split (its one piece).
     */
    final Commands commands = new Commands().triangles(out).trees(trees);
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
        commands.clear();
        culledBack = culledFrustum = culledDegenerate = invalid = clipped = 0;
        clipNanos = tessellateNanos = 0;
    }

    /** Sorts the commands into bands of rows of a frame {@code height} rows high, in order. */
    void bin(int height) {
        commands.bin(height, FrameRenderer.BAND_ROWS);
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
            commands.shrink(n, Math.max(2 * commands.bins().entries(), n));
        }
    }
}
