package dev.trisect.ui;

import java.util.Locale;
import javax.swing.JCheckBox;
import javax.swing.JComponent;
import javax.swing.JSpinner;
import javax.swing.SpinnerNumberModel;

/**
 * Developer tools: the frame-time budget. "Auto" lets the budget controller choose the tessellated
 * path's threshold each frame to hold the target frame time, never looser than the threshold set in
 * the split-policy section (its ceiling); the section shows the threshold it chose.
 */
final class BudgetSection implements ToolSection {
    private final DemoState state;
    private final ToolsForm form = new ToolsForm("Frame budget");
    private final JCheckBox auto = new JCheckBox("Auto: hold the target frame time");
    private final JSpinner target = new JSpinner(new SpinnerNumberModel(DemoState.Budget.DEFAULT_TARGET_MS, 1.0,
            1000.0, 0.5));

    BudgetSection(DemoWindow owner) {
        this.state = owner.state();
        auto.setToolTipText("Adjust the split threshold every frame to hold the target frame time (tessellated "
                + "path); the max edge or max error set above is the loosest it may go");
        target.setToolTipText("Frame time to hold, milliseconds of engine time per frame");
        auto.addActionListener(e -> publish());
        target.addChangeListener(e -> publish());
        form.row(auto);
        form.row(ToolsForm.label("Target ms", target.getToolTipText()), target);
        form.readouts(new String[][] {
            {"Chosen threshold", "The threshold the controller chose for the last frame (px); - when off"}});
        DemoState.Budget b = state.budget();
        auto.setSelected(b.on());
        target.setValue(b.targetMs());
    }

    private void publish() {
        state.budget(new DemoState.Budget(auto.isSelected(), ((Number) target.getValue()).doubleValue()));
    }

    @Override
    public JComponent component() {
        return form.panel();
    }

    @Override
    public void refresh(DemoState.Progress progress, FrameSlot front, DemoState.Measurement measurement) {
        double t = state.chosenThreshold();
        form.set("Chosen threshold", Double.isNaN(t) ? "-" : String.format(Locale.ROOT, "%.3f px", t));
    }

    @Override
    public String readout(String name) {
        return form.get(name);
    }

    /** The Auto switch, for tests. */
    JCheckBox autoSwitch() {
        return auto;
    }
}
