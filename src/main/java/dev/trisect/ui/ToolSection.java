package dev.trisect.ui;

import javax.swing.JComponent;

/**
 * One titled section of the developer tools. Each section owns its controls and the settings they
 * change; {@link DevToolsDialog} only stacks the sections and forwards these calls. Event thread only.
 */
interface ToolSection {
    /** The section's panel, built once. */
    JComponent component();

    /** Shows the current settings in the controls (after a key, a menu or another control changed them). */
    default void sync(ViewSettings settings) {
    }

    /** Updates readouts from the render thread's latest numbers, a few times a second. */
    default void refresh(DemoState.Progress progress, FrameSlot front, DemoState.Measurement measurement) {
    }

    /** The text of a readout this section shows, or null if it has none of that name. */
    default String readout(String name) {
        return null;
    }
}
