package dev.trisect.pipeline;

import dev.trisect.raster.BandBins;
import dev.trisect.raster.BorderOverlay;
import dev.trisect.raster.KnotTicks;
import dev.trisect.raster.OutlinePlan;
import dev.trisect.raster.ScreenTriangles;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.TessellationSettings;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The border overlay of a frame: one {@link OutlinePlan} per chunk of screen triangles, prepared per
 * chunk (on any thread), then drawn band by band in chunk order, so that every pixel sees the
 * outlines in the order of the triangles, whatever the number of threads.
 *
 * <p>A pass of the overlay is tasks on a {@link WorkerPool}: first the {@link #preparations()}
 * (tasks 0..chunks-1, {@link #prepare}), then the bands, each of which {@link #awaitPrepared waits}
 * for all preparations before {@link #drawBand drawing}. The pool hands out indices in order, so all
 * preparations are taken before any band is, and the wait ends. {@link BandPass} interleaves such a
 * pass with the fill; {@link #drawAll} is one on its own.
 *
 * <p>A frame of the span path also shows its knots ({@link KnotTicks}), drawn after the outlines of
 * each band, in the same chunk order.
 */
final class Outlines {
    /** Per-thread scratch. */
    private static final class Lane {
        /** Draws a plan's edges: LINE commands, by the line rasterizer with the overlay's write. */
        final BorderOverlay overlay = new BorderOverlay();
        final KnotTicks ticks = new KnotTicks();
        /** Keeps what {@link Framebuffer#touchRows} read. */
        long touched;
    }

    private final Lane[] lanes;
    private OutlinePlan[] plans = new OutlinePlan[0];
    private int count;
    /** The most chunks a pass outlined since the last {@link #retain}. */
    private int used;
    private final Retention retention = new Retention(0);
    /** Preparations of the current pass that are done (or failed). */
    private final AtomicInteger prepared = new AtomicInteger();
    /** The chunks whose knots the pass ticks, with the span path's knot error, or null for no ticks. */
    private Chunks tickChunks;
    private double tickError;
    private boolean tickByBound;

    /** @param threads the threads of the pool that will run its passes */
    Outlines(int threads) {
        lanes = new Lane[threads];
        for (int i = 0; i < threads; i++) {
            lanes[i] = new Lane();
        }
    }

    /** Starts a pass over {@code chunks} chunks: makes room for their plans; call on one thread, before the pass. */
    void begin(int chunks) {
        if (plans.length < chunks) {
            OutlinePlan[] grown = Arrays.copyOf(plans, chunks);
            for (int i = plans.length; i < chunks; i++) {
                grown[i] = new OutlinePlan();
            }
            plans = grown;
        }
        count = chunks;
        used = Math.max(used, chunks);
        prepared.set(0);
        tickChunks = null;
    }

    /**
     * Closes one frame's account of the plans (the passes since the last call, none when the borders
     * were off) and drops the plans, with all their storage, that recent frames did not use (see
     * {@link Retention}). Call on one thread, before a frame's passes.
     */
    void retain() {
        long keep = retention.keep(used, plans.length);
        if (keep >= 0) {
            plans = Arrays.copyOf(plans, (int) keep);
        }
        used = 0;
    }

    /** Drops every plan with its storage; the next pass makes those it needs. */
    void release() {
        plans = new OutlinePlan[0];
    }

    /** Plans kept, one per chunk outlined lately. */
    int plans() {
        return plans.length;
    }

    /**
     * Makes the pass begun also tick the knots of the span path with knot error {@code knotError} (0: no
     * ticks) in the chunks' triangles, coloured by their segments' bound when the style colours by bound
     * (the outlines are then yellow: the triangles' affine bound says nothing of this path). Call
     * before the pass's preparations run.
     */
    void ticks(Chunks chunks, double knotError, BorderStyle style) {
        tickChunks = knotError > 0 ? chunks : null;
        tickError = knotError;
        tickByBound = style.colouring() == BorderStyle.Colouring.BOUND;
    }

    /** The preparation tasks of the pass: one per chunk. */
    int preparations() {
        return count;
    }

    /** Prepares chunk {@code c}'s outlines for a frame {@code height} pixels high; counted done even if it fails. */
    void prepare(int c, ScreenTriangles triangles, BorderStyle style, TessellationSettings tessellation, int height) {
        try {
            // In the span path the bound is the knots' (coloured on the ticks): the outlines stay yellow.
            BorderStyle outlineStyle = tickChunks != null && tickByBound
                    ? new BorderStyle(BorderStyle.Colouring.YELLOW, style.fade(), style.onlyFallback()) : style;
            plans[c].prepare(triangles, outlineStyle, tessellation.maxDepth(), tessellation.maxError(), height,
                    FrameRenderer.BAND_ROWS);
        } finally {
            prepared.incrementAndGet();
        }
    }

    /**
     * Waits until every preparation of the pass is done. They are all taken before any band is, by
     * threads that are running them, so this ends; it yields rather than spins, so that on a busy
     * machine a preparing thread that lost its core gets it back sooner.
     *
     * @return true when they are done; false when a task of the pass has failed (the frame is lost)
     */
    boolean awaitPrepared(WorkerPool pool) {
        while (prepared.get() < count) {
            if (pool.failed()) {
                return false;
            }
            Thread.yield();
        }
        return true;
    }

    /** Draws every chunk's outlines within band {@code band}, rows [y0, y1), on thread {@code thread}. */
    void drawBand(int thread, Framebuffer frame, int band, int y0, int y1) {
        BorderOverlay overlay = lanes[thread].overlay;
        for (int c = 0; c < count; c++) {
            overlay.draw(frame, plans[c], band, y0, y1);
        }
        if (tickChunks != null) {
            KnotTicks ticks = lanes[thread].ticks;
            for (int c = 0; c < count; c++) {
                Chunk chunk = tickChunks.get(c);
                ticks.draw(frame, chunk.commands, band, plans[c], tickByBound, tickError, y0, y1);
            }
        }
    }

    /**
     * Outlines the screen triangles of chunks 0..chunkCount-1 into {@code frame}, a pass of its own
     * (the frame's fill long done), with the knot ticks of a span-path frame drawn with knot error
     * {@code knotError} (0 for other paths).
     */
    void drawAll(Framebuffer frame, Chunks chunks, int chunkCount, BorderStyle style,
                 TessellationSettings tessellation, double knotError, WorkerPool pool) {
        int height = frame.height();
        begin(chunkCount);
        ticks(chunks, knotError, style);
        int bands = BandBins.bandCount(height, FrameRenderer.BAND_ROWS);
        pool.run(chunkCount + bands, (thread, task) -> {
            if (task < chunkCount) {
                prepare(task, chunks.get(task).out, style, tessellation, height);
                return;
            }
            int band = task - chunkCount;
            int y0 = band * FrameRenderer.BAND_ROWS;
            int y1 = Math.min(height, y0 + FrameRenderer.BAND_ROWS);
            // The frame has long left the cache: fetch the band's rows in order first, which costs
            // less than missing on them at every line pixel.
            lanes[thread].touched += frame.touchRows(y0, y1);
            if (awaitPrepared(pool)) {
                drawBand(thread, frame, band, y0, y1);
            }
        });
    }
}
