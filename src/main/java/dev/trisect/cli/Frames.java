package dev.trisect.cli;

import dev.trisect.base.InputException;
import dev.trisect.base.internal.Counts;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;

/** Frame allocation with a clear message when memory runs short; notes about a rendered frame. */
final class Frames {
    private Frames() {
    }

    static Framebuffer allocate(Converters.Size size) {
        try {
            return new Framebuffer(size.width(), size.height());
        } catch (OutOfMemoryError e) {
            throw new InputException("not enough memory for a " + size + " frame (use a smaller --size, "
                    + "or give Java more with -Xmx)");
        }
    }

    /**
     * Says on standard error when a frame skipped triangles (never silently dropped geometry):
     * non-finite coordinates, or corners too far from the view for double precision.
     */
    static void noteSkipped(CommonOptions common, FrameStats stats) {
        if (stats.skippedInvalid() > 0) {
            common.note(stats.skippedInvalid() + " of " + Counts.of(stats.trianglesIn(), "triangle") + " skipped: coordinates "
                    + "not finite, or too far from the view to place in double precision (see "
                    + "docs/reading-limits.md)");
        }
    }
}
