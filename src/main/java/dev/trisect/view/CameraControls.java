package dev.trisect.view;

/**
 * How a {@link TrisectView}'s mouse and keys move its camera. The controls take +y as up.
 *
 * @see TrisectView#setCameraControls
 */
public enum CameraControls {
    /**
     * Fly, as in a game: W A S D (or the arrow keys) move forward, left, back and right, E and Q (Page
     * Up, Page Down) up and down, Shift held five times faster; a drag looks around; the wheel moves
     * down (toward you) or up. The default.
     */
    FLY,
    /**
     * Orbit round the camera's target (set it with {@link TrisectView#setCamera}): a drag turns the
     * camera round it, the wheel and W / S (up, down arrows) move nearer or further, A / D (left, right)
     * turn round it, E / Q (Page Up, Page Down) raise and lower it; Shift held is faster.
     */
    ORBIT,
    /** None: the camera stays exactly where the program puts it; the movement keys are left to the host. */
    NONE
}
