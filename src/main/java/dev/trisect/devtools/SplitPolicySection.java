package dev.trisect.devtools;

import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewSettings;
import java.util.function.UnaryOperator;
import javax.swing.BoxLayout;
import javax.swing.ButtonGroup;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JRadioButton;
import javax.swing.JSlider;

/**
 * Developer tools: the tessellated path's split policy and its limits, and the span path's Max error.
 * A control the current path and policy do not use is disabled, its tooltip saying why.
 */
final class SplitPolicySection implements ToolSection {
    /** Max-error slider: 0..SCALE maps logarithmically onto MIN_ERROR..MAX_ERROR pixels. */
    private static final int SCALE = 1000;
    private static final double MIN_ERROR = 0.05;
    private static final double MAX_ERROR = 8;

    private final ViewController owner;
    private final ToolsForm form = new ToolsForm("Split policy (tessellated path), Max error (span path)");
    private boolean syncing;
    private final JRadioButton edgePolicy = new JRadioButton("Edge");
    private final JRadioButton errorPolicy = new JRadioButton("Error");
    private final JSlider maxEdge = new JSlider(2, 128, 32);
    private final NumberField maxEdgeValue;
    private final JSlider maxError = new JSlider(0, SCALE, errorToSlider(0.5));
    private final NumberField maxErrorValue;
    private final JSlider maxDepth = new JSlider(0, 30, 16);
    private final NumberField maxDepthValue;

    SplitPolicySection(ViewController owner) {
        this.owner = owner;
        maxEdgeValue = new NumberField("Max edge", "px", 2, 128,
                v -> tessellation(t -> t.withMaxEdge(Math.round(v))), owner::message).decimals(0);
        maxErrorValue = new NumberField("Max error", "px", MIN_ERROR, MAX_ERROR,
                this::setMaxError, owner::message).decimals(3);
        maxDepthValue = new NumberField("Max depth", "", 0, 30,
                v -> tessellation(t -> t.withMaxDepth((int) Math.round(v))), owner::message).decimals(0);
        ButtonGroup group = new ButtonGroup();
        group.add(edgePolicy);
        group.add(errorPolicy);
        edgePolicy.setToolTipText("Split while a piece's longest edge on screen is longer than Max edge");
        errorPolicy.setToolTipText("Split while an edge's worst affine displacement (Kamen-Shirman bound) exceeds "
                + "Max error: no pixel is then further than that from the per-pixel path");
        edgePolicy.addActionListener(e -> setPolicy(SplitPolicy.EDGE));
        errorPolicy.addActionListener(e -> setPolicy(SplitPolicy.ERROR));
        maxEdge.setToolTipText("Longest edge a piece may have on screen, in pixels");
        maxError.setToolTipText("Largest affine displacement allowed, in pixels (logarithmic scale): the Error "
                + "policy's threshold, and the span path's knot spacing");
        maxDepth.setToolTipText("How many times an edge may be halved; an edge at this depth is not split again "
                + "(the cap is per edge, so it never opens cracks)");
        ToolsForm.listen(maxEdge, () -> syncing, this::showValues, v -> tessellation(t -> t.withMaxEdge(v)));
        ToolsForm.listen(maxError, () -> syncing, this::showValues,
                v -> setMaxError(sliderToError(v)));
        ToolsForm.listen(maxDepth, () -> syncing, this::showValues, v -> tessellation(t -> t.withMaxDepth(v)));
        JPanel policies = new JPanel();
        policies.setLayout(new BoxLayout(policies, BoxLayout.X_AXIS));
        policies.add(edgePolicy);
        policies.add(errorPolicy);
        form.row(policies);
        JLabel edgeLabel = ToolsForm.label("Max edge", maxEdge.getToolTipText());
        JLabel errorLabel = ToolsForm.label("Max error", maxError.getToolTipText());
        JLabel depthLabel = ToolsForm.label("Max depth", maxDepth.getToolTipText());
        form.row(edgeLabel, maxEdgeValue);
        form.row(maxEdge);
        form.row(errorLabel, maxErrorValue);
        form.row(maxError);
        form.row(depthLabel, maxDepthValue);
        form.row(maxDepth);
        policyControls = new Control(edgePolicy.getToolTipText() + "; Error: " + errorPolicy.getToolTipText(),
                edgePolicy, errorPolicy);
        edgeControls = new Control(maxEdge.getToolTipText(), edgeLabel, maxEdge, maxEdgeValue);
        errorControls = new Control(maxError.getToolTipText(), errorLabel, maxError, maxErrorValue);
        depthControls = new Control(maxDepth.getToolTipText(), depthLabel, maxDepth, maxDepthValue);
    }

    private final Control policyControls;
    private final Control edgeControls;
    private final Control errorControls;
    private final Control depthControls;

    /**
     * A control and its label and field, enabled when the path and policy use it; disabled, each part's
     * tooltip says why instead of what it does.
     */
    static final class Control {
        private final String tip;
        private final JComponent[] parts;

        Control(String tip, JComponent... parts) {
            this.tip = tip;
            this.parts = parts;
        }

        /** Enables the parts, or disables them with {@code why} (null: they apply) in their tooltips. */
        void applies(String why) {
            for (JComponent p : parts) {
                p.setEnabled(why == null);
                p.setToolTipText(ToolsForm.wrap(why == null ? tip : "Not used now: " + why, ToolsForm.TIP_LINE));
            }
        }

        /** The tooltip of the control's first part, for tests. */
        String tooltip() {
            return parts[parts.length - 1].getToolTipText();
        }

        boolean enabled() {
            return parts[parts.length - 1].isEnabled();
        }
    }

    /**
     * Why a control does not apply to {@code r}, or null when it does: the paths that split nothing (and
     * the span path, which spaces knots by Max error alone), and the threshold the other policy uses.
     */
    static String notUsed(String control, RenderSettings r) {
        RenderMode m = r.mode();
        if (!m.splits() && !(m.knots() && control.equals("Max error"))) {
            return m.knots() ? "the span path (4) splits nothing: its knots are spaced by Max error alone"
                    : "the " + m.id() + " path splits nothing; the tessellated path (3) uses the split policy"
                    + (control.equals("Max error") ? ", the span path (4) Max error" : "");
        }
        SplitPolicy p = r.tessellation().policy();
        if (m.splits() && control.equals("Max edge") && p.measuresError()) {
            return "the Error policy splits by the error bound, not by length: choose Edge to use Max edge";
        }
        if (m.splits() && control.equals("Max error") && !p.measuresError()) {
            return "the Edge policy splits by length, not by the error bound: choose Error to use Max error";
        }
        return null;
    }

    /** The controls of {@code name} ("Policy", "Max edge", "Max error", "Max depth"), for tests. */
    Control control(String name) {
        return switch (name) {
            case "Policy" -> policyControls;
            case "Max edge" -> edgeControls;
            case "Max error" -> errorControls;
            default -> depthControls;
        };
    }

    @Override
    public JComponent component() {
        return form.panel();
    }

    private void tessellation(UnaryOperator<TessellationSettings> f) {
        owner.update(s -> s.withRender(s.render().withTessellation(f.apply(s.render().tessellation()))));
    }

    /** Max error is the error policy's threshold and the span path's knot spacing: it sets both. */
    private void setMaxError(double px) {
        owner.update(s -> s.withRender(s.render().withTessellation(s.render().tessellation().withMaxError(px))
                .withKnotError(px)));
    }

    private void setPolicy(SplitPolicy policy) {
        if (!syncing) {
            tessellation(t -> t.withPolicy(policy));
        }
    }

    static int errorToSlider(double px) {
        return (int) Math.round(SCALE * Math.log(px / MIN_ERROR) / Math.log(MAX_ERROR / MIN_ERROR));
    }

    static double sliderToError(int v) {
        return MIN_ERROR * Math.pow(MAX_ERROR / MIN_ERROR, (double) v / SCALE);
    }

    @Override
    public void sync(ViewSettings s) {
        syncing = true;
        try {
            TessellationSettings t = s.render().tessellation();
            double error = s.render().mode().knots() ? s.render().knotError() : t.maxError();
            edgePolicy.setSelected(t.policy() == SplitPolicy.EDGE);
            errorPolicy.setSelected(t.policy() == SplitPolicy.ERROR);
            maxEdge.setValue((int) Math.round(t.maxEdge()));
            maxError.setValue(errorToSlider(error));
            maxDepth.setValue(t.maxDepth());
            policyControls.applies(notUsed("Policy", s.render()));
            edgeControls.applies(notUsed("Max edge", s.render()));
            errorControls.applies(notUsed("Max error", s.render()));
            depthControls.applies(notUsed("Max depth", s.render()));
            // The values in force, not the sliders' steps: a typed 0.333 px shows as typed.
            maxEdgeValue.show(t.maxEdge());
            maxErrorValue.show(error);
            maxDepthValue.show(t.maxDepth());
        } finally {
            syncing = false;
        }
    }

    /** While a slider moves, its field follows it. */
    private void showValues() {
        if (!syncing) {
            maxEdgeValue.show(maxEdge.getValue());
            maxErrorValue.show(sliderToError(maxError.getValue()));
            maxDepthValue.show(maxDepth.getValue());
        }
    }

    /** The typed fields, for tests: max edge, max error, max depth. */
    NumberField[] fields() {
        return new NumberField[] {maxEdgeValue, maxErrorValue, maxDepthValue};
    }
}
