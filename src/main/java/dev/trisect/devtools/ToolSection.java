package dev.trisect.devtools;

import dev.trisect.view.internal.FrameSlot;
import dev.trisect.view.internal.ViewSettings;
import dev.trisect.view.internal.ViewState;
import javax.swing.JComponent;

/**
 * One titled section of the developer tools. Each section owns its controls and the settings they
 * change; {@link DevToolsPanel} only stacks the sections and forwards these calls. Event thread only.
 */
public interface ToolSection {
    /** The section's panel, built once. */
    JComponent component();

    /** Shows the current settings in the controls (after a key, a menu or another control changed them). */
    default void sync(ViewSettings settings) {
    }

    /** Updates readouts from the render thread's latest numbers, a few times a second. */
    default void refresh(ViewState.Progress progress, FrameSlot front, ViewState.Measurement measurement) {
    }

    /** The text of a readout this section shows, or null if it has none of that name. */
    default String readout(String name) {
        return null;
    }
}
