package dev.trisect.devtools;

import dev.trisect.metrics.Comparison;
import dev.trisect.metrics.HeatScale;
import dev.trisect.view.internal.FrameSlot;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewKind;
import dev.trisect.view.internal.ViewSettings;
import dev.trisect.view.internal.ViewState;
import java.util.Locale;
import javax.swing.BoxLayout;
import javax.swing.ButtonGroup;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JSlider;
import javax.swing.JPanel;
import javax.swing.JRadioButton;

/** Developer tools: the live comparison with the per-pixel path, its numbers, and the view it shows. */
public final class CompareSection implements ToolSection {
    static final String[] MEASURES = {"Max displacement", "p99 displacement", "Mean displacement", "Texels that differ",
        "PSNR", "Measured"};

    private final ViewController owner;
    private final ToolsForm form = new ToolsForm("Compare with per-pixel");
    private boolean syncing;
    private final JCheckBox compare = new JCheckBox("Measure against the per-pixel path");
    private final JRadioButton viewImage = new JRadioButton("Image");
    private final JRadioButton viewDifference = new JRadioButton("Difference");
    private final JRadioButton viewSplit = new JRadioButton("Split");
    private final JComboBox<String> heatScale = new JComboBox<>(new String[] {"Linear", "Logarithmic"});
    /** Top of the heat map's scale: 0..400 maps onto 0.1..1000 px, logarithmically. */
    private final JSlider heatTop = new JSlider(0, 400, topToSlider(2));
    private final NumberField heatTopValue;
    private final JCheckBox heatTopFitted = new JCheckBox("Top at the frame's largest displacement");

    CompareSection(ViewController owner) {
        this.owner = owner;
        heatTopValue = new NumberField("Heat map top", "px", 0.1, 1000, this::heatTop, owner::message).decimals(3);
        compare.setToolTipText("Render the same frame with the per-pixel perspective path as well, and measure "
                + "how far this path's texture is from it, at least twice a second");
        compare.addActionListener(e -> {
            if (!syncing) {
                owner.update(s -> s.withCompare(compare.isSelected()));
            }
        });
        form.row(compare);
        form.readouts(new String[][] {
            {MEASURES[0], "Exact: largest distance, in pixels, from a pixel's centre to where true perspective "
                    + "draws the texel coordinates it shows, over pixels this path and the per-pixel path draw "
                    + "with the same triangle"},
            {MEASURES[1], "99th percentile of that exact distance, in pixels"},
            {MEASURES[2], "Mean of that exact distance, in pixels; the count of pixels left out because their "
                    + "triangle's texture coordinates span no area follows when there are any"},
            {MEASURES[3], "Share of compared pixels whose sampled texel differs from the per-pixel path's"},
            {MEASURES[4], "Peak signal-to-noise ratio of the colours against the per-pixel image, dB (higher is closer)"},
            {MEASURES[5], "Age of these numbers and the time the comparison took"}});
        ButtonGroup views = new ButtonGroup();
        JPanel viewRow = new JPanel();
        viewRow.setLayout(new BoxLayout(viewRow, BoxLayout.X_AXIS));
        viewImage.setToolTipText("Show this path's image");
        viewDifference.setToolTipText("Show the exact displacement as a heat map (grey where the per-pixel path "
                + "shows another triangle), with its "
                + "colour legend, in place of the image");
        viewSplit.setToolTipText("Show this path left of a divider and the per-pixel path right of it; drag the "
                + "divider in the view");
        for (JRadioButton b : new JRadioButton[] {viewImage, viewDifference, viewSplit}) {
            views.add(b);
            viewRow.add(b);
        }
        viewImage.addActionListener(e -> setView(ViewKind.IMAGE));
        viewDifference.addActionListener(e -> setView(ViewKind.DIFFERENCE));
        viewSplit.addActionListener(e -> setView(ViewKind.SPLIT));
        form.row(ToolsForm.label("View", "What the main window shows"));
        form.row(viewRow);
        heatScale.setToolTipText("Heat map scale: linear from 0, or logarithmic over " + HeatScale.DECADES
                + " decades below its top, so that 0.5 px and 1,000 px errors both read");
        heatTop.setToolTipText("Displacement drawn white, at the top of the heat map's scale, pixels; setting it "
                + "keeps it there");
        heatTopFitted.setToolTipText("Put the top of the heat map's scale at the largest displacement of the frame "
                + "on screen, so that its worst pixel is white (the default); off, the top stays where it was set");
        heatTopFitted.addActionListener(e -> {
            if (!syncing) {
                owner.update(s -> s.withHeatTopFitted(heatTopFitted.isSelected()));
            }
        });
        // Linear or log keeps the top, fitted or set.
        heatScale.addActionListener(e -> {
            if (!syncing) {
                owner.update(s -> s.withHeatScale(new HeatScale(heatScale.getSelectedIndex() == 1,
                        s.heatScale().maxPixels())).withHeatTopFitted(s.heatTopFitted()));
            }
        });
        ToolsForm.listen(heatTop, () -> syncing, this::showHeatTop, v -> heat());
        form.row(ToolsForm.label("Heat map scale", heatScale.getToolTipText()), heatScale);
        form.row(ToolsForm.label("Heat map top", heatTop.getToolTipText()), heatTopValue);
        form.row(heatTop);
        form.row(heatTopFitted);
    }

    static int topToSlider(double px) {
        return (int) Math.round(100 * (Math.log10(px) + 1));
    }

    static double sliderToTop(int v) {
        return Math.pow(10, v / 100.0 - 1);
    }

    private void heat() {
        if (!syncing) {
            heatTop(sliderToTop(heatTop.getValue()));
        }
    }

    private void heatTop(double px) {
        owner.update(s -> s.withHeatScale(new HeatScale(heatScale.getSelectedIndex() == 1, px)));
    }

    private void showHeatTop() {
        if (!syncing) {
            heatTopValue.show(sliderToTop(heatTop.getValue()));
        }
    }

    @Override
    public JComponent component() {
        return form.panel();
    }

    private void setView(ViewKind kind) {
        if (!syncing) {
            owner.update(s -> s.withView(kind));
        }
    }

    @Override
    public void sync(ViewSettings s) {
        syncing = true;
        try {
            compare.setSelected(s.compare());
            viewImage.setSelected(s.view() == ViewKind.IMAGE);
            viewDifference.setSelected(s.view() == ViewKind.DIFFERENCE);
            viewSplit.setSelected(s.view() == ViewKind.SPLIT);
            heatScale.setSelectedIndex(s.heatScale().logarithmic() ? 1 : 0);
            heatTopFitted.setSelected(s.heatTopFitted());
            if (!s.heatTopFitted()) {
                showTop(s.heatScale().maxPixels());
            }
        } finally {
            syncing = false;
        }
    }

    /**
     * A measure's text, or a dash where there was nothing to measure (NaN): no pixel that both paths
     * drew with the same triangle, or none whose texture coordinates span an area (a model without
     * texture coordinates). It read "NaN px" there, where {@code compare} prints null.
     */
    static String measure(String format, double value) {
        return Double.isNaN(value) ? "\u2014" : String.format(Locale.ROOT, format, value);
    }

    /** Shows a top on the slider and in the field without setting it. */
    private void showTop(double px) {
        boolean was = syncing;
        syncing = true;
        try {
            heatTop.setValue(topToSlider(px));
            heatTopValue.show(px);
        } finally {
            syncing = was;
        }
    }

    @Override
    public void refresh(ViewState.Progress progress, FrameSlot front, ViewState.Measurement m) {
        ViewSettings now = owner.state().settings();
        if (now.heatTopFitted() && front != null && front.view == ViewKind.DIFFERENCE && front.heatScale != null
                && !heatTopValue.isFocusOwner()) {
            // The fitted top of the heat map on screen, as its legend says.
            showTop(front.heatScale.maxPixels());
        }
        boolean measuring = now.compare() || now.view() != ViewKind.IMAGE;
        for (String k : MEASURES) {
            form.setEnabled(k, measuring);
        }
        if (m == null) {
            for (String k : MEASURES) {
                form.set(k, "\u2014");
            }
            return;
        }
        // Unticked, the last numbers stay, greyed, so that they can still be read (and copied).
        Comparison c = m.comparison();
        form.set(MEASURES[0], measure("%.3f px", c.maxDisplacement()));
        form.set(MEASURES[1], measure("%.3f px", c.p99Displacement()));
        form.set(MEASURES[2], measure("%.3f px", c.meanDisplacement())
                + (c.degenerateUvPixels() > 0 ? String.format(Locale.ROOT, " (%d px no UV area)", c.degenerateUvPixels())
                        : ""));
        form.set(MEASURES[3], measure("%.2f %%", 100 * c.texelDifferShare()));
        form.set(MEASURES[4], Double.isInfinite(c.psnrDb()) ? "identical" : measure("%.2f dB", c.psnrDb()));
        form.set(MEASURES[5], String.format(Locale.ROOT, "%.1f s ago, %.0f ms", (System.nanoTime() - m.nanos()) / 1e9,
                progress.compareMs()));
        if (now.render().mode() != m.settings().render().mode()) {
            form.set(MEASURES[5], "updating\u2026");
        }
    }

    @Override
    public String readout(String name) {
        return form.get(name);
    }

    /** The "Measure against the per-pixel path" check box, for tests. */
    public JCheckBox measureBox() {
        return compare;
    }

    /** Whether a readout shows live numbers (not greyed out), for tests. */
    public boolean live(String name) {
        return form.enabled(name);
    }
}
