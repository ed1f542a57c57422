package dev.trisect.pipeline;

import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;

/**
 * One frame as its {@link FramePass passes} draw it: what to draw and with which settings, into which
 * framebuffer, on which threads, and what each pass has left for the ones after it and for the
 * statistics. Made by {@link FrameRenderer} for each frame and dropped after it.
 */
final class FrameJob {
    /** What to draw. */
    final Draws draws;
    /** How. */
    final RenderSettings settings;
    /** Into what: colour, depth and UV output, cleared by the fill. */
    final Framebuffer frame;
    /** On which threads. */
    final WorkerPool pool;
    /** The renderer's storage of screen triangles, chunk by chunk, reused from frame to frame. */
    final Chunks chunks;
    /** {@link System#nanoTime()} when the frame began. */
    final long start;

    /** What the geometry pass made: the chunks filled, pieces, budgets, times. */
    FrameGeometry.Result geometry;
    /** {@link System#nanoTime()} when the geometry pass ended. */
    long geometryDone;
    /** What the fill pass did: pixels written by the triangles and the lines, fill, overlay and line times. */
    BandPass.Result bands;
    /** {@link System#nanoTime()} when the fill pass ended. */
    long bandsDone;
    /** What the lines' geometry did: segments set up, time. */
    LineGeometry.Result lines = LineGeometry.Result.NONE;
    /** What the quads' set-up did: billboards, glyphs, time. */
    QuadGeometry.Result quads = QuadGeometry.Result.NONE;

    FrameJob(Draws draws, RenderSettings settings, Framebuffer frame, WorkerPool pool, Chunks chunks, long start) {
        this.draws = draws;
        this.settings = settings;
        this.frame = frame;
        this.pool = pool;
        this.chunks = chunks;
        this.start = start;
    }

    /** The chunks of screen triangles the geometry pass filled. */
    int chunkCount() {
        return geometry.chunkCount();
    }
}
