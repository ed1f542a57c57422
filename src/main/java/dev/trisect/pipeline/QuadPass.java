package dev.trisect.pipeline;

import dev.trisect.raster.QuadRaster;
import dev.trisect.render.Framebuffer;

/**
 * The quad pass, last: the frame's screen-aligned quads ({@link Draws#quads()}: billboards, the glyphs
 * of labels and of screen text) over everything before them, band by band in parallel, every band
 * taking the quads in the order they were added, so the image does not depend on the thread count.
 * The quads' own depth test, alpha test and blending are {@link QuadRaster}'s.
 */
final class QuadPass {
    /**
     * What a quad pass did.
     *
     * @param billboards billboard quads in the frame's draws
     * @param glyphs     glyph quads in them
     * @param pixels     pixels written
     * @param nanos      wall time of the pass
     */
    record Result(long billboards, long glyphs, long pixels, long nanos) {
        static final Result NONE = new Result(0, 0, 0, 0);
    }

    private final long[] pixels;

    /** @param threads the threads of the pool that will run it */
    QuadPass(int threads) {
        pixels = new long[threads];
    }

    Result draw(Draws draws, Framebuffer frame, WorkerPool pool) {
        QuadRaster quads = draws.quads();
        if (quads.count() == 0) {
            return Result.NONE;
        }
        long start = System.nanoTime();
        int rows = FrameRenderer.BAND_ROWS;
        quads.bin(frame.width(), frame.height(), rows);
        java.util.Arrays.fill(pixels, 0);
        int[] colour = frame.colour();
        float[] depth = frame.depth();
        pool.run((frame.height() + rows - 1) / rows, (thread, b) -> pixels[thread] += quads.drawBand(colour, depth, b));
        long written = 0;
        for (long p : pixels) {
            written += p;
        }
        return new Result(quads.count(QuadRaster.BILLBOARD), quads.count(QuadRaster.GLYPH), written,
                System.nanoTime() - start);
    }
}
