package dev.trisect.view.internal;

/**
 * Frames shown per second, over the last whole second of drawing: the render loop counts each frame
 * it hands over, and the rate is renewed once a second has gone since the count began. A pause —
 * the frame frozen, or the view minimized — is not drawing: the count starts again when drawing
 * resumes, so the first rate after a pause is not a few frames spread over the pause (the status
 * bar read "0 fps" for a second after a freeze). Until then the rate from before the pause stands. Render
 * thread only.
 */
final class FrameRate {
    private static final long SECOND_NANOS = 1_000_000_000L;

    /** When the count began ({@link System#nanoTime}), or -1 when it has not since the last pause. */
    private long since = -1;
    private long frames;
    private double fps;

    /**
     * A frame was handed to the screen.
     *
     * @param now {@link System#nanoTime} when it was
     * @return the frames per second (the last whole second's, or the one before a pause)
     */
    double frameShown(long now) {
        if (since < 0) {
            since = now;
            frames = 0;
            return fps;
        }
        frames++;
        if (now - since >= SECOND_NANOS) {
            fps = frames * 1e9 / (now - since);
            since = now;
            frames = 0;
        }
        return fps;
    }

    /** Nothing is drawn for a while (frozen, minimized): the count starts again at the next frame. */
    void pause() {
        since = -1;
    }

    /** The frames per second last worked out (0 before the first whole second). */
    double fps() {
        return fps;
    }
}
