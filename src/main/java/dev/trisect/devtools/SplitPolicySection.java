package dev.trisect.devtools;

import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewSettings;
import java.util.function.UnaryOperator;
import javax.swing.BoxLayout;
import javax.swing.ButtonGroup;
import javax.swing.JComponent;
import javax.swing.JPanel;
import javax.swing.JRadioButton;
import javax.swing.JSlider;

/** Developer tools: the tessellated path's split policy and its limits. */
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
        form.row(ToolsForm.label("Max edge", maxEdge.getToolTipText()), maxEdgeValue);
        form.row(maxEdge);
        form.row(ToolsForm.label("Max error", maxError.getToolTipText()), maxErrorValue);
        form.row(maxError);
        form.row(ToolsForm.label("Max depth", maxDepth.getToolTipText()), maxDepthValue);
        form.row(maxDepth);
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
            maxEdge.setEnabled(t.policy() == SplitPolicy.EDGE);
            maxEdgeValue.setEnabled(maxEdge.isEnabled());
            maxError.setEnabled(t.policy().measuresError() || s.render().mode().knots());
            maxErrorValue.setEnabled(maxError.isEnabled());
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
