package dev.trisect.view;

import dev.trisect.render.FrameStats;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;

/**
 * One frame a {@link TrisectView} drew, as its {@link FrameListener}s hear of it.
 *
 * @param number          the frame's number in this view, counting from 1
 * @param width           frame width, pixels: the view's size in device pixels times its render scale
 * @param height          frame height, pixels
 * @param camera          the camera it was drawn with (the user may have moved it), world space
 * @param settings        the settings it was drawn with; under a frame-time target, with the split
 *                        threshold the budget chose
 * @param stats           the engine's statistics of the frame: counts, and nanoseconds of wall time per stage
 * @param frameMillis     milliseconds the render thread spent on the frame: the engine's time plus the
 *                        overlay and anything the developer tools measured
 * @param framesPerSecond frames handed to the screen per second, over the last second
 * @param warning         one line for the user, starting with the sign "\u26a0", when a cap was reached
 *                        (pieces filled per pixel), triangles were skipped as unplaceable
 *                        ({@link FrameStats#skippedNote()}), or the frame budget's target is out of reach even
 *                        at the user's threshold; null when all is well
 */
public record FrameInfo(long number, int width, int height, Camera camera, RenderSettings settings,
                        FrameStats stats, double frameMillis, double framesPerSecond, String warning) {
}
