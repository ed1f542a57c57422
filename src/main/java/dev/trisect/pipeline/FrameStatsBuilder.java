package dev.trisect.pipeline;

import dev.trisect.render.FrameStats;

/**
 * Builds a frame's {@link FrameStats} from what its stages returned: the chunks' counters and the
 * geometry's result, the band pass's pixels and processor times, and the wall-clock marks between
 * stages. Stages that run interleaved on all threads share their wall time out in proportion to the
 * processor time each took: clipping and tessellation always, filling and outlining when the
 * borders are drawn with the fill (then flagged as estimates).
 */
final class FrameStatsBuilder {
    private final int threads;
    private final long start;
    private long triangles;
    private long back;
    private long frustum;
    private long degenerate;
    private long invalid;
    private long clipped;
    private long pieces;
    private long offScreen;
    private long splits;
    private int deepest;
    private long caps;
    private long fallback;
    private long clipCpu;
    private long tessellateCpu;
    private long pieceBudget;
    private int budgetDepth = -1;
    private long transformNanos;
    private long geometryDone;

    /**
     * @param threads threads the frame was drawn with
     * @param start   {@link System#nanoTime} when the frame began
     */
    FrameStatsBuilder(int threads, long start) {
        this.threads = threads;
        this.start = start;
    }

    /**
     * The frame's geometry: {@code triangles} input triangles made into chunks 0..result.chunkCount()-1
     * of {@code chunks}, done at {@code done} ({@link System#nanoTime}).
     */
    FrameStatsBuilder geometry(long triangleCount, Chunks chunks, FrameGeometry.Result result, long done) {
        triangles += triangleCount;
        for (int c = 0; c < result.chunkCount(); c++) {
            Chunk k = chunks.get(c);
            back += k.culledBack;
            frustum += k.culledFrustum;
            degenerate += k.culledDegenerate;
            invalid += k.invalid;
            clipped += k.clipped;
            pieces += k.pieces;
            offScreen += k.offScreen;
            splits += k.splits;
            deepest = Math.max(deepest, k.deepest);
            caps += k.caps;
            fallback += k.fallback;
            clipCpu += k.clipNanos;
            tessellateCpu += k.tessellateNanos;
        }
        pieceBudget = result.pieceBudget();
        budgetDepth = result.budgetDepth();
        transformNanos = result.transformNanos();
        geometryDone = done;
        return this;
    }

    /**
     * The band pass, done at {@code end} ({@link System#nanoTime}), which ends the frame, with the
     * overlay drawn in it or not.
     */
    FrameStats bands(BandPass.Result result, long end, boolean borders) {
        return bands(result, end, borders, LineGeometry.Result.NONE, 0, QuadGeometry.Result.NONE);
    }

    /**
     * The set-up of the lines ({@code lines}, with {@code segmentsIn} segments given) and quads
     * ({@code quads}), then the band pass, done at {@code end}, which ends the frame; the band pass drew
     * the lines and the quads as its lists after the triangles (0, 1).
     */
    FrameStats bands(BandPass.Result result, long end, boolean borders, LineGeometry.Result lines, long segmentsIn,
                     QuadGeometry.Result quads) {
        // Filling, outlining and drawing lines and quads run interleaved on all threads, so none has a
        // wall time of its own: the band pass's wall time is shared out in proportion to the time the
        // threads spent on each, an estimate that FrameStats names as such.
        long bandsWall = end - geometryDone - lines.nanos() - quads.nanos();
        long lineCpu = after(result.afterNanos(), 0);
        long quadCpu = after(result.afterNanos(), 1);
        long work = result.fillNanos() + result.overlayNanos() + lineCpu + quadCpu;
        long overlay = !borders || work == 0 ? 0
                : Math.round(bandsWall * (double) result.overlayNanos() / work);
        long lineShare = work == 0 ? 0 : Math.round(bandsWall * (double) lineCpu / work);
        long quadShare = work == 0 ? 0 : Math.round(bandsWall * (double) quadCpu / work);
        long transformed = start + transformNanos;
        long geometryWall = geometryDone - transformed;
        long cpu = clipCpu + tessellateCpu;
        long clipWall = cpu == 0 ? 0 : Math.round(geometryWall * (double) clipCpu / cpu);
        return new FrameStats(triangles, back, frustum, degenerate, invalid, clipped, pieces, offScreen, splits,
                deepest, caps, fallback, pieceBudget, budgetDepth, result.pixels(), threads, transformed - start,
                clipWall, geometryWall - clipWall, bandsWall - overlay - lineShare - quadShare, overlay,
                borders || lines.segments() > 0 || quadCpu > 0, end - start, segmentsIn, lines.segments(),
                after(result.afterPixels(), 0), lines.nanos() + lineShare, quads.billboards(), quads.glyphs(),
                after(result.afterPixels(), 1), quads.nanos() + quadShare);
    }

    /** Entry {@code i} of a band pass's per-list figures, 0 when it drew fewer lists. */
    private static long after(long[] perList, int i) {
        return i < perList.length ? perList[i] : 0;
    }
}
