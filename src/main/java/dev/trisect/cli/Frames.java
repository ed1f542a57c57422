package dev.trisect.cli;

import dev.trisect.base.InputException;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;

/** Frame allocation with a clear message when memory runs short; notes about a rendered frame. */
final class Frames {
    private Frames() {
    }

    /** Bytes of the frame last allocated in this process (its colour and depth), 0 before any. */
    private static volatile long frameBytes;

    /**
     * Whether a smaller {@code --size} would free a good part of the heap: the frame allocated takes an
     * eighth of it or more. Otherwise the scene's own storage (per triangle) is what fills it.
     */
    static boolean frameMatters() {
        return frameBytes >= Runtime.getRuntime().maxMemory() / 8;
    }

    static Framebuffer allocate(Converters.Size size) {
        frameBytes = 8L * size.width() * size.height();
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
        String note = stats.skippedNote();
        if (note != null) {
            common.note(note);
        }
    }
}
