package dev.trisect.view;

/**
 * Hears about every frame a {@link TrisectView} draws.
 *
 * <p>Called on the view's render thread, right after the frame is handed to the screen and before
 * the next one starts: keep it short. It may change the scene (the next frame shows the change — a
 * way to animate) or the view's camera and settings; to touch Swing components, use
 * {@code SwingUtilities.invokeLater}. Each change asks for another frame, so a listener that changes
 * the scene after every frame keeps the view drawing: show a changing figure (the frame rate) in a
 * Swing component rather than as {@code ScreenText}. Setting a value equal to the one in force (the
 * same screen text, transform or light) is no change, and asks for nothing.
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
