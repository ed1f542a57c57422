package dev.trisect.view;

/**
 * Hears about every frame a {@link TrisectView} draws.
 *
 * <p>Called on the view's render thread, right after the frame is handed to the screen and before
 * the next one starts: keep it short. It may change the scene (the next frame shows the change — a
 * way to animate) or the view's camera and settings; to touch Swing components, use
 * {@code SwingUtilities.invokeLater}.
 */
@FunctionalInterface
public interface FrameListener {
    /**
     * A frame was drawn.
     *
     * @param frame what was drawn and how long it took
     */
    void frameDrawn(FrameInfo frame);
}
