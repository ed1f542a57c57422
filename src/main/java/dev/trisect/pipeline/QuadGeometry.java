package dev.trisect.pipeline;

import dev.trisect.raster.Commands;
import dev.trisect.raster.QuadRaster;

/**
 * The quads' set-up, before the fill: the frame's screen-aligned quads ({@link Draws#quads()}:
 * billboards, the glyphs of labels and of screen text, their backdrops) set up for the frame's size
 * and listed as {@link Commands#QUAD} commands in the order they were added; the list is binned into
 * the fill's bands, where each band draws its quads last, after its lines ({@link BandPass}), so the
 * image does not depend on the thread count. The quads' own fog (the billboards', by the frame's fog
 * pass: after the band's fog pass, so each quad fogs its own fragments), depth test, alpha test and
 * blending are {@link QuadRaster}'s.
 */
final class QuadGeometry {
    /**
     * What the quads' set-up did.
     *
     * @param billboards billboard quads in the frame's draws
     * @param glyphs     glyph quads in them
     * @param nanos      wall time of the set-up
     */
    record Result(long billboards, long glyphs, long nanos) {
        static final Result NONE = new Result(0, 0, 0);
    }

    /** The frame's quads as commands: what the fill draws last in each band. */
    private final Commands commands = new Commands();

    /** The quads of the frame last set up, binned into the fill's bands. */
    Commands commands() {
        return commands;
    }

    /** Sets up and bins the quads of {@code draws} for a frame of {@code width x height} pixels. */
    Result setUp(Draws draws, int width, int height) {
        QuadRaster quads = draws.quads();
        commands.quads(quads).clear();
        if (quads.count() == 0) {
            commands.bin(height, FrameRenderer.BAND_ROWS);
            return Result.NONE;
        }
        long start = System.nanoTime();
        quads.setUp(width, height, draws.fogPass());
        for (int s = 0; s < quads.count(); s++) {
            commands.add(Commands.QUAD, s, quads.firstRow(s), quads.lastRow(s) + 1);
        }
        commands.bin(height, FrameRenderer.BAND_ROWS);
        return new Result(quads.count(QuadRaster.BILLBOARD), quads.count(QuadRaster.GLYPH), System.nanoTime() - start);
    }
}
