package dev.trisect.pipeline;

import dev.trisect.raster.BorderOverlay;
import dev.trisect.raster.BorderStyle;
import dev.trisect.raster.Framebuffer;
import dev.trisect.raster.OutlinePlan;
import dev.trisect.raster.ScreenTriangles;
import dev.trisect.tessellate.TessellationSettings;
import java.util.Arrays;

/**
 * The border overlay of a frame: one {@link OutlinePlan} per chunk of screen triangles, prepared per
 * chunk (on any thread), then drawn band by band in chunk order, so that every pixel sees the
 * outlines in the order of the triangles, whatever the number of threads.
 */
final class Outlines {
    private OutlinePlan[] plans = new OutlinePlan[0];
    private int count;

    /** Makes room for {@code chunks} plans; call before {@link #prepare}, on one thread. */
    void resize(int chunks) {
        if (plans.length < chunks) {
            OutlinePlan[] grown = Arrays.copyOf(plans, chunks);
            for (int i = plans.length; i < chunks; i++) {
                grown[i] = new OutlinePlan();
            }
            plans = grown;
        }
        count = chunks;
    }

    /** Prepares chunk {@code c}'s outlines for a frame {@code height} pixels high. */
    void prepare(int c, ScreenTriangles triangles, BorderStyle style, TessellationSettings tessellation,
                 int height) {
        plans[c].prepare(triangles, style, tessellation.maxDepth(), tessellation.maxError(), height,
                FrameRenderer.BAND_ROWS);
    }

    /** Draws every chunk's outlines within band {@code band}, rows [y0, y1), with a thread's overlay. */
    void drawBand(BorderOverlay overlay, Framebuffer frame, int band, int y0, int y1) {
        for (int c = 0; c < count; c++) {
            overlay.draw(frame, plans[c], band, 0, y0, frame.width(), y1);
        }
    }
}
