package dev.trisect.view.internal;

import dev.trisect.metrics.HeatScale;
import dev.trisect.render.RenderSettings;

/**
 * Everything the user has chosen, as one immutable value: the event thread replaces it, the render
 * thread reads the latest one at the start of each frame, so a change takes effect on the next frame.
 *
 * @param render        how frames are drawn
 * @param view          image, difference heat map, or split
 * @param splitFraction divider position in the split view, 0..1 of the width
 * @param compare       measure the frame against the per-pixel path (at least twice a second)
 * @param renderScale   frame pixels per device pixel, (0, 1]
 * @param heatScale     how displacements map onto the heat map's colours (linear or logarithmic, and its top)
 * @param heatTopFitted the heat map's top is each frame's largest displacement ({@link HeatScale#fitted}),
 *                      not {@code heatScale}'s; on until the user sets a top
 */
public record ViewSettings(RenderSettings render, ViewKind view, double splitFraction, boolean compare,
                           double renderScale, HeatScale heatScale, boolean heatTopFitted) {

    public static ViewSettings defaults() {
        return new ViewSettings(RenderSettings.display(), ViewKind.IMAGE, 0.5, true, 1.0, HeatScale.linear(2.0), true);
    }

    public ViewSettings withRender(RenderSettings r) {
        return new ViewSettings(r, view, splitFraction, compare, renderScale, heatScale, heatTopFitted);
    }

    /** Another view; the difference and split views compare with the per-pixel path, so they turn comparing on. */
    public ViewSettings withView(ViewKind v) {
        return new ViewSettings(render, v, splitFraction, compare || v != ViewKind.IMAGE, renderScale, heatScale,
                heatTopFitted);
    }

    public ViewSettings withSplitFraction(double f) {
        return new ViewSettings(render, view, Math.max(0, Math.min(1, f)), compare, renderScale, heatScale,
                heatTopFitted);
    }

    /** Comparing on or off; off also stops the views that show the comparison (back to the image). */
    public ViewSettings withCompare(boolean c) {
        return new ViewSettings(render, c ? view : ViewKind.IMAGE, splitFraction, c, renderScale, heatScale,
                heatTopFitted);
    }

    public ViewSettings withRenderScale(double s) {
        return new ViewSettings(render, view, splitFraction, compare, s, heatScale, heatTopFitted);
    }

    /** A heat-map scale chosen by the user: its top is then theirs, no longer fitted to each frame. */
    public ViewSettings withHeatScale(HeatScale h) {
        return new ViewSettings(render, view, splitFraction, compare, renderScale, h, false);
    }

    /** The heat map's top fitted to each frame's largest displacement, or {@link #heatScale}'s. */
    public ViewSettings withHeatTopFitted(boolean fitted) {
        return new ViewSettings(render, view, splitFraction, compare, renderScale, heatScale, fitted);
    }
}
