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
 * in cache. With fog, a thread fogs (and then outlines and finishes) its bands {@link #FOG_GROUP} at a
 * time, after filling them, and the bands left at the end in one more run of the pool. One
 * {@link BandFill} per thread dispatches each command by its kind.
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
        /** With fog: this thread's filled bands not yet fogged, in the order filled. */
        int[] unfogged = new int[0];
        int unfoggedCount;
    }

    /**
     * With fog, how many bands a thread fills before it fogs them (then each in turn). The fog pass's
     * wide vector arithmetic lowers the core's clock for a while after it on processors with AVX-512
     * frequency licences, so fogging each band as soon as it was filled slowed the fill of every band
     * after it. 16 bands are 256 rows, 4 MB of colour and depth at 1920 pixels: still in a last-level
     * cache when fogged. (Fogging the whole frame at its end saved a little more on this machine, but
     * rereads from memory the rows of any frame larger than the cache; docs/performance/fog.md, "Fog".)
     */
    private static final int FOG_GROUP = 16;

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
            int bandCount = BandBins.bandCount(frame.height(), FrameRenderer.BAND_ROWS);
            if (lane.unfogged.length < bandCount) {
                lane.unfogged = new int[bandCount];
            }
            lane.unfoggedCount = 0;
        }
        probeList = -1;
        probeCommand = -1;
        double knotError = settings.mode().knots() ? settings.knotError() : 0;
        int height = frame.height();
        boolean borders = settings.borders();
        if (borders) {
            outlines.begin(chunkCount);
            outlines.ticks(chunks, knotError, settings.borderStyle());
        }
        int prepTasks = borders ? chunkCount : 0;
        int bands = BandBins.bandCount(height, FrameRenderer.BAND_ROWS);
        Band band = new Band(frame, chunks, chunkCount, textures, states, lit, settings, fog, outlines, after,
                foggedLists, pool);
        pool.run(prepTasks + bands, (thread, task) -> {
            Lane lane = lanes[thread];
            if (task < prepTasks) {
                long t0 = System.nanoTime();
                outlines.prepare(task, chunks.get(task).out, settings.borderStyle(), settings.tessellation(), height);
                lane.overlayNanos += System.nanoTime() - t0;
                return;
            }
            int b = task - prepTasks;
            band.fill(lane, thread, b);
            if (fog == null) {
                band.finish(lane, thread, b);
                return;
            }
            lane.unfogged[lane.unfoggedCount++] = b;
            if (lane.unfoggedCount == FOG_GROUP) {
                band.fogAndFinish(lane, thread);
            }
        });
        if (fog != null) {
            // The bands left unfogged at the end, fogged and finished each by any thread.
            int left = 0;
            for (Lane lane : lanes) {
                left += lane.unfoggedCount;
            }
            if (left > 0) {
                int[] rest = new int[left];
                int n = 0;
                for (Lane lane : lanes) {
                    System.arraycopy(lane.unfogged, 0, rest, n, lane.unfoggedCount);
                    n += lane.unfoggedCount;
                    lane.unfoggedCount = 0;
                }
                pool.run(left, (thread, i) -> {
                    Lane lane = lanes[thread];
                    lane.unfogged[0] = rest[i];
                    lane.unfoggedCount = 1;
                    band.fogAndFinish(lane, thread);
                });
            }
        }
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

    /** One frame's draw: what every band task needs. */
    private final class Band {
        private final Framebuffer frame;
        private final Chunks chunks;
        private final int chunkCount;
        private final Texture[] textures;
        private final int[] states;
        private final LitTextures lit;
        private final RenderSettings settings;
        private final FogPass fog;
        private final Outlines outlines;
        private final Commands[] after;
        private final int foggedLists;
        private final WorkerPool pool;
        private final boolean perspective;
        private final double knotError;
        private final int width;
        private final int height;

        Band(Framebuffer frame, Chunks chunks, int chunkCount, Texture[] textures, int[] states, LitTextures lit,
             RenderSettings settings, FogPass fog, Outlines outlines, Commands[] after, int foggedLists,
             WorkerPool pool) {
            this.frame = frame;
            this.chunks = chunks;
            this.chunkCount = chunkCount;
            this.textures = textures;
            this.states = states;
            this.lit = lit;
            this.settings = settings;
            this.fog = fog;
            this.outlines = outlines;
            this.after = after;
            this.foggedLists = foggedLists;
            this.pool = pool;
            perspective = settings.mode().divides();
            knotError = settings.mode().knots() ? settings.knotError() : 0;
            width = frame.width();
            height = frame.height();
        }

        /** Sets thread {@code thread}'s rasterizer to this frame's state. */
        private BandFill setUp(Lane lane, int thread) {
            BandFill fill = lane.fill;
            Rasterizer rasterizer = fill.rasterizer();
            rasterizer.filter(settings.filter());
            rasterizer.spans(knotError);
            rasterizer.states(states);
            rasterizer.lit(lit == null ? null : lit.lane(thread));
            return fill;
        }

        /**
         * Clears band {@code b} and fills the commands of every chunk into it; with fog, then the lists
         * fogged with the triangles (the lines), so that each of their pixels is fogged by its own depth.
         */
        void fill(Lane lane, int thread, int b) {
            long t0 = System.nanoTime();
            int y0 = firstRow(b);
            int y1 = endRow(b, height);
            frame.clearRows(y0, y1, settings.background());
            BandFill fill = setUp(lane, thread);
            for (int c = 0; c < chunkCount; c++) {
                lane.pixels += fill.fill(frame, chunks.get(c).commands, b, textures, perspective, 0, y0, width, y1);
            }
            long foggedNanos = 0;
            if (fog != null) {
                for (int l = 0; l < foggedLists; l++) {
                    foggedNanos += drawAfter(lane, fill, frame, after, l, b, textures, perspective, width, y0, y1);
                }
            }
            lane.fillNanos += System.nanoTime() - t0 - foggedNanos;
        }

        /** Fogs the bands {@code lane} holds unfogged, then finishes each ({@link #finish}). */
        void fogAndFinish(Lane lane, int thread) {
            setUp(lane, thread);
            for (int i = 0; i < lane.unfoggedCount; i++) {
                int b = lane.unfogged[i];
                long t0 = System.nanoTime();
                fog.apply(frame, firstRow(b), endRow(b, height), lane.fogRows);
                lane.fillNanos += System.nanoTime() - t0;
                finish(lane, thread, b);
            }
            lane.unfoggedCount = 0;
        }

        /**
         * Outlines band {@code b} when the borders are on, then draws its commands of the lists that come
         * after the triangles, fog and outlines (with fog, the lines came before it), as submitted.
         */
        void finish(Lane lane, int thread, int b) {
            int y0 = firstRow(b);
            int y1 = endRow(b, height);
            // The wait for the preparations is neither filling nor outlining: it is left out of both measures.
            if (settings.borders() && outlines.awaitPrepared(pool)) {
                long t2 = System.nanoTime();
                outlines.drawBand(thread, frame, b, y0, y1);
                lane.overlayNanos += System.nanoTime() - t2;
            }
            for (int l = fog != null ? foggedLists : 0; l < after.length; l++) {
                drawAfter(lane, lane.fill, frame, after, l, b, textures, perspective, width, y0, y1);
            }
        }
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

    /** Band {@code b}'s first row, frame pixels. */
    private static int firstRow(int b) {
        return b * FrameRenderer.BAND_ROWS;
    }

    /** One past band {@code b}'s last row in a frame {@code height} rows tall. */
    private static int endRow(int b, int height) {
        return Math.min(height, firstRow(b) + FrameRenderer.BAND_ROWS);
    }

    /**
     * Counts, per pixel of a {@code width x height} frame, how many screen triangles of chunks
     * 0..chunkCount-1 cover its centre, ignoring depth (see {@link FrameRecord#coverage}).
     */
    int[] coverage(Chunks chunks, int chunkCount, int width, int height, WorkerPool pool) {
        int[] counts = new int[width * height];
        int bands = BandBins.bandCount(height, FrameRenderer.BAND_ROWS);
        pool.run(bands, (thread, b) -> {
            int y0 = firstRow(b);
            int y1 = endRow(b, height);
            BandFill fill = lanes[thread].fill;
            for (int c = 0; c < chunkCount; c++) {
                fill.count(counts, width, chunks.get(c).commands, b, 0, y0, width, y1);
            }
        });
        return counts;
    }
}
