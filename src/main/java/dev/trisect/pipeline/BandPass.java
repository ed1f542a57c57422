package dev.trisect.pipeline;

import dev.trisect.light.FogPass;
import dev.trisect.raster.BandBins;
import dev.trisect.raster.BandFill;
import dev.trisect.raster.Commands;
import dev.trisect.raster.LitTextures;
import dev.trisect.raster.Rasterizer;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.texture.Texture;

/**
 * The fill half of a frame: one task per band of {@link FrameRenderer#BAND_ROWS} rows, which clears
 * its rows, then draws the band's commands of every chunk ({@link Chunk#commands}: triangles, split
 * trees), chunk by chunk, so that every pixel sees its triangles in input order whatever the number of
 * threads; then fogs the band, outlines it when the borders are on (the tasks of an {@link Outlines}
 * pass come first), and draws the band's commands of the lists that come after the triangles — the
 * frame's lines ({@link LineGeometry}), then its quads ({@link QuadGeometry}) — all while its rows are
 * in cache. One {@link BandFill} per thread dispatches each command by its kind.
 */
final class BandPass {
    /**
     * What a band pass did.
     *
     * @param pixels       pixels written by the fill (depth test passed)
     * @param fillNanos    processor time of all threads clearing and filling bands
     * @param overlayNanos processor time of all threads preparing outlines and outlining bands, not
     *                     waiting for the preparations
     * @param afterPixels  per list drawn after the triangles (the lines, the quads), pixels it wrote
     * @param afterNanos   per such list, processor time of all threads drawing it
     */
    record Result(long pixels, long fillNanos, long overlayNanos, long[] afterPixels, long[] afterNanos) {
    }

    /** Per-thread scratch and counters. */
    private static final class Lane {
        final BandFill fill = new BandFill();
        final FogPass.Rows fogRows = new FogPass.Rows();
        long pixels;
        long fillNanos;
        long overlayNanos;
        long[] afterPixels = new long[0];
        long[] afterNanos = new long[0];
    }

    private final Lane[] lanes;
    /** The frame pixel whose last writer among the after-lists is noted ({@link #probe}), or -1. */
    private int probe = -1;
    /** After a draw: the after-list and command that wrote {@link #probe} last, or -1. Written by its band's task. */
    private int probeList = -1;
    private int probeCommand = -1;

    /** @param threads the threads of the pool that will run it */
    BandPass(int threads) {
        lanes = new Lane[threads];
        for (int i = 0; i < threads; i++) {
            lanes[i] = new Lane();
        }
    }

    /**
     * Draws band {@code b}'s commands of list {@code l} of {@code after}, noting which of them writes the
     * probed pixel last ({@link #probe}); returns the time it took, ns.
     */
    private long drawAfter(Lane lane, BandFill fill, Framebuffer frame, Commands[] after, int l, int b,
                           Texture[] textures, boolean perspective, int width, int y0, int y1) {
        if (after[l].count() == 0) {
            return 0;
        }
        boolean probed = probe >= y0 * width && probe < y1 * width;
        fill.probe(probed ? probe : -1);
        long t = System.nanoTime();
        lane.afterPixels[l] += fill.fill(frame, after[l], b, textures, perspective, 0, y0, width, y1);
        long nanos = System.nanoTime() - t;
        lane.afterNanos[l] += nanos;
        if (fill.probeWriter() >= 0) {
            probeList = l;
            probeCommand = fill.probeWriter();
        }
        fill.probe(-1);
        return nanos;
    }

    /**
     * Clears {@code frame} and fills the commands of chunks 0..chunkCount-1 into it, fogs each band
     * when there is fog ({@link FogPass}, before the overlay: the borders are not part of the scene;
     * the first {@code foggedLists} lists of {@code after} are drawn before the fog), outlines it by
     * {@code outlines} when the settings have borders on, then draws its commands of each (other) list
     * of {@code after}, in order.
     *
     * @param fog      the frame's fog, or null for none
     * @param textures the texture of each material, by material index
     * @param states   the pixel state of each material, by material index (see {@link Rasterizer#states})
     * @param lit      the renderer's lit copies of textures, begun for this frame's textures, or null for none
     * @param after    the lists each band draws after its triangles, fog and outlines (the frame's
     *                 lines, then its quads), binned into the same bands
     * @param foggedLists how many of the first lists of {@code after} are fogged (OpenGL fogs lines):
     *                 with fog, each band draws them before its fog pass (so before the outlines)
     */
    Result draw(Framebuffer frame, Chunks chunks, int chunkCount, Texture[] textures, int[] states,
                LitTextures lit, RenderSettings settings, FogPass fog, Outlines outlines, Commands[] after, int foggedLists,
                WorkerPool pool) {
        for (Lane lane : lanes) {
            lane.pixels = 0;
            lane.fillNanos = 0;
            lane.overlayNanos = 0;
            if (lane.afterPixels.length != after.length) {
                lane.afterPixels = new long[after.length];
                lane.afterNanos = new long[after.length];
            }
            java.util.Arrays.fill(lane.afterPixels, 0);
            java.util.Arrays.fill(lane.afterNanos, 0);
        }
        probeList = -1;
        probeCommand = -1;
        boolean perspective = settings.mode().divides();
        double knotError = settings.mode().knots() ? settings.knotError() : 0;
        int width = frame.width();
        int height = frame.height();
        int background = settings.background();
        boolean borders = settings.borders();
        if (borders) {
            outlines.begin(chunkCount);
            outlines.ticks(chunks, knotError, settings.borderStyle());
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
            BandFill fill = lane.fill;
            Rasterizer rasterizer = fill.rasterizer();
            rasterizer.filter(settings.filter());
            rasterizer.spans(knotError);
            rasterizer.states(states);
            rasterizer.lit(lit == null ? null : lit.lane(thread));
            for (int c = 0; c < chunkCount; c++) {
                lane.pixels += fill.fill(frame, chunks.get(c).commands, b, textures, perspective, 0, y0, width, y1);
            }
            long foggedNanos = 0;
            if (fog != null) {
                // The lists fogged with the triangles (the lines) come before the pass: each of their
                // pixels is then fogged by its own depth, which it has written.
                for (int l = 0; l < foggedLists; l++) {
                    foggedNanos += drawAfter(lane, fill, frame, after, l, b, textures, perspective, width, y0, y1);
                }
                fog.apply(frame, y0, y1, lane.fogRows);
            }
            lane.fillNanos += System.nanoTime() - t0 - foggedNanos;
            // The wait for the preparations is neither filling nor outlining: it is left out of both measures.
            if (borders && outlines.awaitPrepared(pool)) {
                long t2 = System.nanoTime();
                outlines.drawBand(thread, frame, b, y0, y1);
                lane.overlayNanos += System.nanoTime() - t2;
            }
            // The lines, then the quads, after the band's triangles, fog and outlines, as they were submitted
            // (with fog, the lines came before it).
            for (int l = fog != null ? foggedLists : 0; l < after.length; l++) {
                drawAfter(lane, fill, frame, after, l, b, textures, perspective, width, y0, y1);
            }
        });
        long pixels = 0;
        long fill = 0;
        long overlay = 0;
        long[] afterPixels = new long[after.length];
        long[] afterNanos = new long[after.length];
        for (Lane lane : lanes) {
            pixels += lane.pixels;
            fill += lane.fillNanos;
            overlay += lane.overlayNanos;
            for (int l = 0; l < after.length; l++) {
                afterPixels[l] += lane.afterPixels[l];
                afterNanos[l] += lane.afterNanos[l];
            }
        }
        return new Result(pixels, fill, overlay, afterPixels, afterNanos);
    }

    /**
     * Notes, in the draws from now on, which command of the lists drawn after the triangles writes frame
     * pixel {@code pixel} last ({@link #probeList}, {@link #probeCommand}); -1 to stop.
     *
     * @param pixel {@code y * width + x} of the frames to be drawn, or -1
     */
    void probe(int pixel) {
        probe = pixel;
    }

    /** After a draw: the index in {@code after} of the list whose command wrote the probed pixel last, or -1. */
    int probeList() {
        return probeList;
    }

    /** After a draw: that command's index in its list, or -1. */
    int probeCommand() {
        return probeCommand;
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
            BandFill fill = lanes[thread].fill;
            for (int c = 0; c < chunkCount; c++) {
                fill.count(counts, width, chunks.get(c).commands, b, 0, y0, width, y1);
            }
        });
        return counts;
    }
}
