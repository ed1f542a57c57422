package dev.trisect.view.internal;

/**
 * Hands finished frames from the render thread to the event thread without tearing and without
 * either side waiting on the other for more than a pointer swap.
 *
 * <p>The render thread draws into its own slot and {@link #publish}es it, getting back the slot that
 * was waiting (never the one on screen). The event thread {@link #acquire}s the newest frame when it
 * paints. A slot is therefore only ever written by the render thread while the event thread cannot be
 * reading it.
 */
public final class TripleBuffer {
    private FrameSlot ready;
    private boolean fresh;

    /** Render thread: offers a finished frame; returns a slot to draw the next one into (may be null). */
    public synchronized FrameSlot publish(FrameSlot drawn) {
        FrameSlot old = ready;
        ready = drawn;
        fresh = true;
        return sameSize(old, drawn);
    }

    /**
     * {@code slot}, or null when it is of another size than {@code newest}: a slot is kept only for
     * frames of the size drawn now, so that a view made smaller, which draws one frame and idles, holds
     * no frame of the old size (12 bytes a pixel and more) until something moves.
     */
    private static FrameSlot sameSize(FrameSlot slot, FrameSlot newest) {
        return slot != null && slot.is(newest.width(), newest.height()) ? slot : null;
    }

    /**
     * Event thread: the newest finished frame, handing back {@code showing} (the slot on screen until
     * now) for reuse; {@code showing} itself when nothing new has arrived.
     */
    public synchronized FrameSlot acquire(FrameSlot showing) {
        if (!fresh) {
            return showing;
        }
        FrameSlot next = ready;
        ready = sameSize(showing, next);
        fresh = false;
        return next;
    }
}
