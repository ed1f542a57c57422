package dev.trisect.cli;

import dev.trisect.base.InputException;
import dev.trisect.render.Framebuffer;

/** Frame allocation with a clear message when memory runs short. */
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
}
