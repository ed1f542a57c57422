package dev.trisect.view;

/**
 * An update hook: called before each frame a {@link TrisectView} draws, to move things on by the time
 * step. What it changes — objects' transforms, the scene, the view's camera and settings — shows in
 * the frame about to be drawn. The view's {@link TrisectView#getCamera()} is that frame's camera, already
 * moved by the camera controls, so a light can follow the camera (a headlight):
 * {@code Camera c = view.getCamera(); headlight.setVector(c.eye().sub(c.target()));}
 *
 * <pre>{@code
 * view.addUpdateListener((seconds, frame) -> {
 *     angle += 90 * seconds;                                  // 90 degrees a second, whatever the frame rate
 *     crate.setTransform(Transform.translation(0, 0.5, 0).withRotation(Quaternion.ofY(angle)));
 *     return true;                                            // it animates: keep frames coming
 * });
 * }</pre>
 *
 * <p>Called on the view's render thread, before the frame's snapshot of the scene is taken; keep it
 * short (the frame waits for it). It may touch the scene graph and the view's setters of what it
 * shows; to touch Swing components, use {@code SwingUtilities.invokeLater}. A hook that throws is
 * reported as a message (see {@link TrisectView#addMessageListener}) and the frame is drawn anyway.
 *
 * <p>A view draws only when something changed or something animates. A hook is called only before
 * frames that are drawn; returning {@code true} asks for the next frame, so a hook that animates
 * returns true for as long as it does, and the view idles once every hook returns false and nothing
 * else changes. Its own changes to the scene do not by themselves ask for another frame (they are in
 * the frame about to be drawn).
 */
@FunctionalInterface
public interface UpdateListener {
    /**
     * Moves things on before a frame.
     *
     * @param seconds the time since the last frame started (for the first frame, since the render
     *                thread started), measured, seconds: never negative, and at most
     *                {@link TrisectView#MAX_STEP_SECONDS} (after a pause — the view idle, frozen, hidden —
     *                things move on by no more than that)
     * @param frame   the number of the frame about to be drawn, counting from 1 (as {@link FrameInfo#number()})
     * @return true to ask for the next frame (it animates), false when it needs none
     */
    boolean update(double seconds, long frame);
}
