package dev.trisect.pipeline;

import dev.trisect.light.FogPass;
import dev.trisect.raster.BandBins;
import dev.trisect.raster.Rasterizer;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.texture.Texture;

/**
 * The fill half of a frame: one task per band of {@link FrameRenderer#BAND_ROWS} rows, which clears
 * its rows, then fills the screen triangles of every chunk that fall in the band, chunk by chunk, so
 * that every pixel sees its triangles in input order whatever the number of threads. With the borders
 * on, the tasks of an {@link Outlines} pass come first and each band is outlined right after it is
 * filled, while its rows are in cache. One {@link Rasterizer} per thread.
 */
final class BandPass {
    /**
     * What a band pass did.
     *
     * @param pixels       pixels written by the fill (depth test passed)
     * @param fillNanos    processor time of all threads clearing and filling bands
     * @param overlayNanos processor time of all threads preparing outlines and outlining bands, not
     *                     waiting for the preparations
     */
    record Result(long pixels, long fillNanos, long overlayNanos) {
    }

    /** Per-thread scratch and counters. */
    private static final class Lane {
        final Rasterizer rasterizer = new Rasterizer();
        long pixels;
        long fillNanos;
        long overlayNanos;
    }

    private final Lane[] lanes;

    /** @param threads the threads of the pool that will run it */
    BandPass(int threads) {
        lanes = new Lane[threads];
        for (int i = 0; i < threads; i++) {
            lanes[i] = new Lane();
        }
    }

    /**
     * Clears {@code frame} and fills the screen triangles of chunks 0..chunkCount-1 into it, fogs each
     * band when there is fog ({@link FogPass}, before the overlay: the borders are not part of the
     * scene), and outlines it by {@code outlines} when the settings have borders on.
     *
     * @param fog      the frame's fog, or null for none
     * @param textures the texture of each material, by material index
     */
    Result draw(Framebuffer frame, Chunks chunks, int chunkCount, Texture[] textures, RenderSettings settings,
                FogPass fog, Outlines outlines, WorkerPool pool) {
        for (Lane lane : lanes) {
            lane.pixels = 0;
            lane.fillNanos = 0;
            lane.overlayNanos = 0;
        }
        boolean perspective = settings.mode().divides();
        double spanError = settings.mode().knots() ? settings.knotError() : 0;
        int width = frame.width();
        int height = frame.height();
        int background = settings.background();
        boolean borders = settings.borders();
        if (borders) {
            outlines.begin(chunkCount);
            outlines.ticks(chunks, spanError, settings.borderStyle());
        }
        int prepTasks = borders ? chunkCount : 0;
        int bands = BandBins.bandCount(height, FrameRenderer.BAND_ROWS);
        pool.run(prepTasks + bands, (thread, task) -> {
            Lane lane = lanes[thread];
            long t0 = System.nanoTime();
            if (task < prepTasks) {
                outlines.prepare(task, chunks.get(task).out, settings.borderStyle(), settings.tessellation(), height);
                lane.overlayNanos += System.nanoTime() - t0;
                return;
            }
            int b = task - prepTasks;
            int y0 = b * FrameRenderer.BAND_ROWS;
            int y1 = Math.min(height, y0 + FrameRenderer.BAND_ROWS);
            frame.clearRows(y0, y1, background);
            Rasterizer rasterizer = lane.rasterizer;
            rasterizer.filter(settings.filter());
            rasterizer.spans(spanError);
            for (int c = 0; c < chunkCount; c++) {
                Chunk chunk = chunks.get(c);
                lane.pixels += chunk.split
                        ? rasterizer.fillTrees(frame, chunk.trees, chunk.out, chunk.bins.items(), chunk.bins.start(b),
                        chunk.bins.start(b + 1), textures, 0, y0, width, y1)
                        : rasterizer.fill(frame, chunk.out, chunk.bins.items(), chunk.bins.start(b),
                        chunk.bins.start(b + 1), textures, perspective, 0, y0, width, y1);
            }
            if (fog != null) {
                fog.apply(frame, y0, y1);
            }
            lane.fillNanos += System.nanoTime() - t0;
            // The wait for the preparations is neither filling nor outlining: it is left out of both measures.
            if (borders && outlines.awaitPrepared(pool)) {
                long t2 = System.nanoTime();
                outlines.drawBand(thread, frame, b, y0, y1);
                lane.overlayNanos += System.nanoTime() - t2;
            }
        });
        long pixels = 0;
        long fill = 0;
        long overlay = 0;
        for (Lane lane : lanes) {
            pixels += lane.pixels;
            fill += lane.fillNanos;
            overlay += lane.overlayNanos;
        }
        return new Result(pixels, fill, overlay);
    }

    /**
     * Counts, per pixel of a {@code width x height} frame, how many screen triangles of chunks
     * 0..chunkCount-1 cover its centre, ignoring depth (see {@link FrameRecord#coverage}).
     */
    int[] coverage(Chunks chunks, int chunkCount, int width, int height, WorkerPool pool) {
        int[] counts = new int[width * height];
        int bands = BandBins.bandCount(height, FrameRenderer.BAND_ROWS);
        pool.run(bands, (thread, b) -> {
            int y0 = b * FrameRenderer.BAND_ROWS;
            int y1 = Math.min(height, y0 + FrameRenderer.BAND_ROWS);
            Rasterizer rasterizer = lanes[thread].rasterizer;
            for (int c = 0; c < chunkCount; c++) {
                Chunk chunk = chunks.get(c);
                if (chunk.split) {
                    rasterizer.countTreeCoverage(counts, width, chunk.trees, chunk.out, chunk.bins.items(),
                            chunk.bins.start(b), chunk.bins.start(b + 1), 0, y0, width, y1);
                } else {
                    rasterizer.countCoverage(counts, width, chunk.out, chunk.bins.items(), chunk.bins.start(b),
                            chunk.bins.start(b + 1), 0, y0, width, y1);
                }
            }
        });
        return counts;
    }
}
