package dev.trisect.devtools;

import dev.trisect.render.RenderMode;
import dev.trisect.view.internal.FrameSlot;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewSettings;
import dev.trisect.view.internal.ViewState;
import java.util.Locale;
import javax.swing.JCheckBox;
import javax.swing.JComponent;

/**
 * Developer tools: the frame-time budget. "Auto" lets the budget controller choose the tessellated
 * path's threshold each frame to hold the target frame time, never looser than the threshold set in
 * the split-policy section (its ceiling); the section shows the threshold it chose.
 */
final class BudgetSection implements ToolSection {
    private final ViewState state;
    private final ToolsForm form = new ToolsForm("Frame budget");
    private boolean syncing;
    private final JCheckBox auto = new JCheckBox("Auto: hold the target frame time");
    private final NumberField target;
    /**
     * The smallest target the field takes: the view and {@code demo --target-ms} take any target above 0,
     * and the field shows one decimal, so 0.1 ms is the least it can show as typed.
     */
    static final double MIN_TARGET_MS = 0.1;

    BudgetSection(ViewController owner) {
        this.state = owner.state();
        target = new NumberField("Target ms", "ms", MIN_TARGET_MS, 1000, this::publish, owner::message).decimals(1);
        auto.setToolTipText(AUTO_TIP);
        target.setToolTipText("Frame time to hold, milliseconds per frame: the whole frame the status bar's frames "
                + "per second count (overlay, the tools' measuring and presenting included), 0.1 to 1000: type it and "
                + "press Enter");
        auto.addActionListener(e -> publish(state.budget().targetMs()));
        form.row(auto);
        form.row(ToolsForm.label("Target ms", target.getToolTipText()), target);
        form.readouts(new String[][] {
            {"Chosen threshold", "The threshold the controller chose for the next frame (px), and what holds it "
                + "there: your threshold (the target is out of reach even there), the finest (2 px or 0.05 px: the "
                + "target is met with room to spare), or the piece budget (finer would overfill it); - when off"}});
        form.note(WHY, "Why the threshold is where it is, with the numbers that decide it: the median frame time "
                + "(the whole frame, as the status bar's frames per second count it) against the target, or the "
                + "frame's pieces against its piece budget");
        form.note(CHANGE, "The controller's last change of threshold and what made it: a median frame over or "
                + "under the target, or pieces over 75 % of the piece budget");
        form.note(AGAINST, "The tessellated path's engine time against the per-pixel path's, from the last "
                + "comparison (Compare section): Auto never leaves the tessellated frame slower than the per-pixel "
                + "one without saying so here");
        sync(null);
    }

    private static final String AUTO_TIP = "Adjust the split threshold every frame to hold the target frame time "
            + "(tessellated path); the max edge or max error set above is the loosest it may go";
    static final String WHY = "Why";
    static final String CHANGE = "Last change";
    static final String AGAINST = "Against per-pixel";

    private void publish(double targetMs) {
        if (!syncing) {
            state.budget(new ViewState.Budget(auto.isSelected(), targetMs));
            target.show(targetMs);
        }
    }

    /** Shows the budget in force (the host may have set it). */
    @Override
    public void sync(ViewSettings settings) {
        syncing = true;
        try {
            ViewState.Budget b = state.budget();
            auto.setSelected(b.on());
            target.show(b.targetMs());
            if (settings != null) {
                // Auto chooses the tessellated path's threshold: in another path it has nothing to choose.
                boolean applies = settings.render().mode().splits();
                auto.setEnabled(applies);
                target.setEnabled(applies);
                auto.setToolTipText(ToolsForm.wrap(applies ? AUTO_TIP : "Not used now: the " + settings.render().mode()
                        .id() + " path splits nothing, so there is no threshold to choose; press 3 for the tessellated "
                        + "path", ToolsForm.TIP_LINE));
            }
        } finally {
            syncing = false;
        }
    }

    @Override
    public JComponent component() {
        return form.panel();
    }

    @Override
    public void refresh(ViewState.Progress progress, FrameSlot front, ViewState.Measurement measurement) {
        ViewState.BudgetChoice c = state.budgetChoice();
        form.set("Chosen threshold", c == null ? "-" : String.format(Locale.ROOT, "%.3f px", c.threshold())
                + (c.reason().isEmpty() ? "" : " (" + c.reason() + ")"));
        form.set(WHY, c == null ? "" : c.why());
        form.set(CHANGE, c == null ? "" : c.lastChange());
        form.set(AGAINST, c == null ? "" : againstPerPixel(state.pathMs()));
    }

    /**
     * The tessellated path's time against the per-pixel path's, from the last comparison that timed both
     * ({@code ms} by {@link RenderMode} ordinal, or null when none did): a warning when tessellating is
     * the slower of the two.
     */
    static String againstPerPixel(double[] ms) {
        if (ms == null) {
            return "not measured: tick Measure in the Compare section to time both paths";
        }
        double tess = ms[RenderMode.TESSELLATED.ordinal()];
        double perPixel = ms[RenderMode.PERSPECTIVE.ordinal()];
        return tess > perPixel ? String.format(Locale.ROOT, "\u26a0 slower than per-pixel: tessellated %.1f ms, "
                + "per-pixel %.1f ms (engine time, last comparison); press 1 for the per-pixel path, or raise the "
                + "threshold", tess, perPixel)
                : String.format(Locale.ROOT, "faster than per-pixel: tessellated %.1f ms, per-pixel %.1f ms (engine "
                + "time, last comparison)", tess, perPixel);
    }

    @Override
    public String readout(String name) {
        return form.get(name);
    }

    /** The target's field, for tests. */
    NumberField targetField() {
        return target;
    }

    /** The Auto switch, for tests. */
    JCheckBox autoSwitch() {
        return auto;
    }
}
