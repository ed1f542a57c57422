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
 */
public record ViewSettings(RenderSettings render, ViewKind view, double splitFraction, boolean compare,
                           double renderScale, HeatScale heatScale) {

    public static ViewSettings defaults() {
        return new ViewSettings(RenderSettings.display(), ViewKind.IMAGE, 0.5, true, 1.0, HeatScale.linear(2.0));
    }

    public ViewSettings withRender(RenderSettings r) {
        return new ViewSettings(r, view, splitFraction, compare, renderScale, heatScale);
    }

    /** Another view; the difference and split views compare with the per-pixel path, so they turn comparing on. */
    public ViewSettings withView(ViewKind v) {
        return new ViewSettings(render, v, splitFraction, compare || v != ViewKind.IMAGE, renderScale, heatScale);
    }

    public ViewSettings withSplitFraction(double f) {
        return new ViewSettings(render, view, Math.max(0, Math.min(1, f)), compare, renderScale, heatScale);
    }

    /** Comparing on or off; off also stops the views that show the comparison (back to the image). */
    public ViewSettings withCompare(boolean c) {
        return new ViewSettings(render, c ? view : ViewKind.IMAGE, splitFraction, c, renderScale, heatScale);
    }

    public ViewSettings withRenderScale(double s) {
        return new ViewSettings(render, view, splitFraction, compare, s, heatScale);
    }

    public ViewSettings withHeatScale(HeatScale h) {
        return new ViewSettings(render, view, splitFraction, compare, renderScale, h);
    }
}
