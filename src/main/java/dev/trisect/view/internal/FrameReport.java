package dev.trisect.view.internal;

import dev.trisect.render.FrameStats;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;

/**
 * One frame as the render loop reports it to its view.
 *
 * @param frame     the frame's number, counting from 1
 * @param width     frame width, pixels (the view's device pixels times the render scale)
 * @param height    frame height, pixels
 * @param camera    the camera it was drawn with
 * @param settings  the settings it was drawn with (the budget controller's threshold included)
 * @param stats     the engine's statistics of the frame
 * @param frameMs   milliseconds the render thread spent on it: engine, overlay and any comparison
 * @param fps       frames handed to the screen per second, over the last second
 * @param warning   one line when a cap was reached or the time budget missed, else null
 */
public record FrameReport(long frame, int width, int height, Camera camera, RenderSettings settings,
                          FrameStats stats, double frameMs, double fps, String warning) {

    FrameReport withFps(double f) {
        return new FrameReport(frame, width, height, camera, settings, stats, frameMs, f, warning);
    }
}
