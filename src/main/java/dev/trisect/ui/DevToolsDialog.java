package dev.trisect.ui;

import dev.trisect.metrics.Comparison;
import dev.trisect.pipeline.FrameStats;
import dev.trisect.pipeline.RenderSettings;
import dev.trisect.tessellate.SplitPolicy;
import dev.trisect.tessellate.TessellationSettings;
import java.awt.Dialog;
import java.awt.Font;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.awt.Toolkit;
import java.awt.Window;
import java.awt.datatransfer.StringSelection;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.function.IntConsumer;
import javax.swing.BorderFactory;
import javax.swing.Box;
import javax.swing.BoxLayout;
import javax.swing.ButtonGroup;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JRadioButton;
import javax.swing.JScrollPane;
import javax.swing.JSlider;
import javax.swing.SwingConstants;

/**
 * The "Developer tools" window: polygon borders, texturing path, split policy, the live comparison
 * with the per-pixel path and its views, frame statistics and render scale. Every control says what
 * it does in a tooltip, and changes take effect on the next frame.
 *
 * <p>The window never takes the keyboard ({@link #setFocusableWindowState} false), so the view keeps
 * flying while the mouse works the controls here. Event thread only.
 */
final class DevToolsDialog extends JDialog {
    private static final long serialVersionUID = 1L;
    /** Max-error slider: 0..SCALE maps logarithmically onto MIN_ERROR..MAX_ERROR pixels. */
    private static final int SCALE = 1000;
    private static final double MIN_ERROR = 0.05;
    private static final double MAX_ERROR = 8;

    private final transient DemoWindow owner;
    private boolean syncing;

    private final JRadioButton edgePolicy = new JRadioButton("Edge");
    private final JRadioButton errorPolicy = new JRadioButton("Error");
    private final JSlider maxEdge = new JSlider(2, 128, 32);
    private final JLabel maxEdgeValue = value();
    private final JSlider maxError = new JSlider(0, SCALE, errorToSlider(0.5));
    private final JLabel maxErrorValue = value();
    private final JSlider maxDepth = new JSlider(0, 24, 16);
    private final JLabel maxDepthValue = value();
    private final JCheckBox compare = new JCheckBox("Measure against the per-pixel path");
    private final JRadioButton viewImage = new JRadioButton("Image");
    private final JRadioButton viewDifference = new JRadioButton("Difference");
    private final JRadioButton viewSplit = new JRadioButton("Split");
    private final JSlider renderScale = new JSlider(25, 100, 100);
    private final JLabel renderScaleValue = value();
    private final Map<String, JLabel> readouts = new LinkedHashMap<>();

    DevToolsDialog(DemoWindow owner) {
        super(owner.frame(), "Developer tools", Dialog.ModalityType.MODELESS);
        this.owner = owner;
        setFocusableWindowState(false);
        setAutoRequestFocus(false);
        setDefaultCloseOperation(HIDE_ON_CLOSE);
        addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                owner.devToolsClosed();
            }
        });
        JPanel content = new JPanel();
        content.setLayout(new BoxLayout(content, BoxLayout.Y_AXIS));
        content.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        content.add(overlaySection());
        content.add(modeSection());
        content.add(splitSection());
        content.add(compareSection());
        content.add(statisticsSection());
        content.add(renderSection());
        content.add(Box.createVerticalGlue());
        JScrollPane scroll = new JScrollPane(content);
        scroll.setBorder(null);
        setContentPane(scroll);
        pack();
        setSize(380, Math.min(getHeight(), 900));
    }

    /** Places the window to the right of the main window (or inside the screen) and shows it. */
    void showBeside(Window main) {
        int x = main.getX() + main.getWidth();
        int screen = Toolkit.getDefaultToolkit().getScreenSize().width;
        if (x + getWidth() > screen) {
            x = Math.max(0, screen - getWidth());
        }
        setLocation(x, main.getY());
        setVisible(true);
    }

    private static JLabel value() {
        JLabel l = new JLabel("", SwingConstants.RIGHT);
        l.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        return l;
    }

    private static JPanel section(String title) {
        JPanel p = new JPanel(new GridBagLayout());
        p.setBorder(BorderFactory.createCompoundBorder(BorderFactory.createTitledBorder(title),
                BorderFactory.createEmptyBorder(2, 4, 4, 4)));
        p.setAlignmentX(LEFT_ALIGNMENT);
        return p;
    }

    private static void row(JPanel p, int y, java.awt.Component left, java.awt.Component right) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridy = y;
        c.insets = new Insets(1, 2, 1, 2);
        c.anchor = GridBagConstraints.WEST;
        c.fill = GridBagConstraints.HORIZONTAL;
        c.gridx = 0;
        c.weightx = right == null ? 1 : 0.6;
        c.gridwidth = right == null ? 2 : 1;
        p.add(left, c);
        if (right != null) {
            c.gridx = 1;
            c.weightx = 0.4;
            p.add(right, c);
        }
    }

    private JPanel overlaySection() {
        JPanel p = section("Overlay");
        JCheckBox borders = new JCheckBox(owner.bordersCommand);
        borders.setText("Show polygon borders (B)");
        borders.setToolTipText("Outline every piece actually filled in yellow: tessellated pieces, or whole "
                + "triangles in the other paths (B)");
        row(p, 0, borders, null);
        return p;
    }

    private JPanel modeSection() {
        JPanel p = section("Mode");
        ButtonGroup group = new ButtonGroup();
        int y = 0;
        for (Command c : owner.modeCommands) {
            JRadioButton b = new JRadioButton(c);
            b.setText(c.getValue(javax.swing.Action.NAME) + " (" + (y + 1) + ")");
            group.add(b);
            row(p, y++, b, null);
        }
        return p;
    }

    private JPanel splitSection() {
        JPanel p = section("Split policy (tessellated path)");
        ButtonGroup group = new ButtonGroup();
        group.add(edgePolicy);
        group.add(errorPolicy);
        edgePolicy.setToolTipText("Split while a piece's longest edge on screen is longer than Max edge");
        errorPolicy.setToolTipText("Split while an edge's worst affine displacement (Kamen-Shirman bound) exceeds "
                + "Max error: no pixel is then further than that from the per-pixel path");
        edgePolicy.addActionListener(e -> setPolicy(SplitPolicy.EDGE));
        errorPolicy.addActionListener(e -> setPolicy(SplitPolicy.ERROR));
        maxEdge.setToolTipText("Longest edge a piece may have on screen, in pixels");
        maxError.setToolTipText("Largest affine displacement allowed, in pixels (logarithmic scale)");
        maxDepth.setToolTipText("How many times an edge may be halved; an edge at this depth is not split again "
                + "(the cap is per edge, so it never opens cracks)");
        listen(maxEdge, v -> tessellation(t -> t.withMaxEdge(v)));
        listen(maxError, v -> tessellation(t -> t.withMaxError(sliderToError(v))));
        listen(maxDepth, v -> tessellation(t -> t.withMaxDepth(v)));
        JPanel policies = new JPanel();
        policies.setLayout(new BoxLayout(policies, BoxLayout.X_AXIS));
        policies.add(edgePolicy);
        policies.add(errorPolicy);
        row(p, 0, policies, null);
        row(p, 1, label("Max edge", maxEdge.getToolTipText()), maxEdgeValue);
        row(p, 2, maxEdge, null);
        row(p, 3, label("Max error", maxError.getToolTipText()), maxErrorValue);
        row(p, 4, maxError, null);
        row(p, 5, label("Max depth", maxDepth.getToolTipText()), maxDepthValue);
        row(p, 6, maxDepth, null);
        return p;
    }

    private JPanel compareSection() {
        JPanel p = section("Compare with per-pixel");
        compare.setToolTipText("Render the same frame with the per-pixel perspective path as well, and measure "
                + "how far this path's texture is from it, at least twice a second");
        compare.addActionListener(e -> {
            if (!syncing) {
                owner.update(s -> s.withCompare(compare.isSelected()));
            }
        });
        row(p, 0, compare, null);
        int y = 1;
        for (String[] r : new String[][] {
            {"Max displacement", "Largest on-screen distance, in pixels, between where this path and the per-pixel "
                    + "path show the same texture, over pixels both draw with the same triangle"},
            {"p99 displacement", "99th percentile of that distance, in pixels"},
            {"Texels that differ", "Share of compared pixels whose sampled texel differs from the per-pixel path's"},
            {"PSNR", "Peak signal-to-noise ratio of the colours against the per-pixel image, dB (higher is closer)"},
            {"Measured", "Age of these numbers and the time the comparison took"}}) {
            y = readout(p, y, r[0], r[1]);
        }
        ButtonGroup views = new ButtonGroup();
        JPanel viewRow = new JPanel();
        viewRow.setLayout(new BoxLayout(viewRow, BoxLayout.X_AXIS));
        viewImage.setToolTipText("Show this path's image");
        viewDifference.setToolTipText("Show the displacement against the per-pixel path as a heat map, with its "
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
        row(p, y++, label("View", "What the main window shows"), null);
        row(p, y, viewRow, null);
        return p;
    }

    private JPanel statisticsSection() {
        JPanel p = section("Statistics");
        int y = 0;
        for (String[] r : new String[][] {
            {"Frames per second", "Frames shown per second, over the last second"},
            {"Frame size", "Pixels rendered per frame (view size in device pixels times render scale)"},
            {"Render threads", "Threads that fill each frame"},
            {"ms transform", "Milliseconds per frame transforming vertices to clip space"},
            {"ms clip", "Milliseconds culling and clipping triangles"},
            {"ms tessellate", "Milliseconds splitting triangles into pieces and projecting them"},
            {"ms raster", "Milliseconds clearing and filling the frame"},
            {"ms overlay", "Milliseconds drawing polygon borders"},
            {"ms total", "Milliseconds for the whole frame in the engine"},
            {"Triangles in", "Triangles in the scene"},
            {"Culled", "Triangles dropped as facing away, off screen, or without area"},
            {"Pieces filled", "Triangles filled: tessellated pieces, or clipped triangles in the other paths"},
            {"Splits", "Midpoint splits made this frame"},
            {"Deepest split", "The most times an edge was halved this frame"},
            {"Caps reached", "Triangles whose splitting a depth or piece cap stopped short"},
            {"Pixels written", "Pixels that passed the depth test"}}) {
            y = readout(p, y, r[0], r[1]);
        }
        return p;
    }

    private JPanel renderSection() {
        JPanel p = section("Render");
        renderScale.setToolTipText("Render at this share of the view's device pixels and scale up (faster when lower)");
        listen(renderScale, v -> owner.update(s -> s.withRenderScale(v / 100.0)));
        row(p, 0, label("Render scale", renderScale.getToolTipText()), renderScaleValue);
        row(p, 1, renderScale, null);
        JButton copy = new JButton("Copy compare command");
        copy.setToolTipText("Copy the command line that measures the last compared frame with trisect compare");
        copy.addActionListener(e -> {
            DemoState.Measurement m = owner.state().measurement();
            if (m != null) {
                String cmd = "java -jar trisect.jar " + String.join(" ", CliArgs.compare(owner.state().scene(), m));
                Toolkit.getDefaultToolkit().getSystemClipboard().setContents(new StringSelection(cmd), null);
                owner.status("Copied: " + cmd);
            }
        });
        row(p, 2, copy, null);
        return p;
    }

    private static JLabel label(String text, String tip) {
        JLabel l = new JLabel(text);
        l.setToolTipText(tip);
        return l;
    }

    private int readout(JPanel p, int y, String name, String tip) {
        JLabel v = value();
        v.setToolTipText(tip);
        readouts.put(name, v);
        row(p, y, label(name, tip), v);
        return y + 1;
    }

    private void listen(JSlider s, IntConsumer change) {
        s.addChangeListener(e -> {
            updateValueLabels();
            if (!syncing) {
                change.accept(s.getValue());
            }
        });
    }

    private void tessellation(java.util.function.UnaryOperator<TessellationSettings> f) {
        owner.update(s -> s.withRender(s.render().withTessellation(f.apply(s.render().tessellation()))));
    }

    private void setPolicy(SplitPolicy policy) {
        if (!syncing) {
            tessellation(t -> t.withPolicy(policy));
        }
    }

    private void setView(ViewKind kind) {
        if (!syncing) {
            owner.update(s -> s.withView(kind).withCompare(kind == ViewKind.IMAGE ? s.compare() : true));
        }
    }

    static int errorToSlider(double px) {
        return (int) Math.round(SCALE * Math.log(px / MIN_ERROR) / Math.log(MAX_ERROR / MIN_ERROR));
    }

    static double sliderToError(int v) {
        return MIN_ERROR * Math.pow(MAX_ERROR / MIN_ERROR, (double) v / SCALE);
    }

    /** Shows the current settings in the controls (after a key, a menu or another control changed them). */
    void syncFromSettings() {
        syncing = true;
        try {
            ViewSettings s = owner.state().settings();
            TessellationSettings t = s.render().tessellation();
            edgePolicy.setSelected(t.policy() == SplitPolicy.EDGE);
            errorPolicy.setSelected(t.policy() == SplitPolicy.ERROR);
            maxEdge.setValue((int) Math.round(t.maxEdge()));
            maxError.setValue(errorToSlider(t.maxError()));
            maxDepth.setValue(t.maxDepth());
            maxEdge.setEnabled(t.policy() == SplitPolicy.EDGE);
            maxError.setEnabled(t.policy() == SplitPolicy.ERROR);
            compare.setSelected(s.compare());
            viewImage.setSelected(s.view() == ViewKind.IMAGE);
            viewDifference.setSelected(s.view() == ViewKind.DIFFERENCE);
            viewSplit.setSelected(s.view() == ViewKind.SPLIT);
            renderScale.setValue((int) Math.round(s.renderScale() * 100));
            updateValueLabels();
        } finally {
            syncing = false;
        }
    }

    private void updateValueLabels() {
        maxEdgeValue.setText(maxEdge.getValue() + " px");
        maxErrorValue.setText(String.format(Locale.ROOT, "%.2f px", sliderToError(maxError.getValue())));
        maxDepthValue.setText(Integer.toString(maxDepth.getValue()));
        renderScaleValue.setText(renderScale.getValue() + " %");
    }

    /** The text of one readout, for tests and tooling. */
    String readout(String name) {
        JLabel l = readouts.get(name);
        return l == null ? null : l.getText();
    }

    /** Updates the readouts from the render thread's latest numbers. */
    void refresh(DemoState.Progress progress, FrameSlot front, DemoState.Measurement m) {
        set("Frames per second", String.format(Locale.ROOT, "%.1f", progress.fps()));
        set("Render threads", Integer.toString(owner.loop().threads()));
        if (front != null && front.stats != null) {
            FrameStats st = front.stats;
            set("Frame size", front.width() + "x" + front.height());
            set("ms transform", ms(st.transformNanos()));
            set("ms clip", ms(st.clipNanos()));
            set("ms tessellate", ms(st.tessellateNanos()));
            set("ms raster", ms(st.rasterNanos()));
            set("ms overlay", ms(st.overlayNanos()));
            set("ms total", ms(st.totalNanos()));
            set("Triangles in", Long.toString(st.trianglesIn()));
            set("Culled", Long.toString(st.culled()));
            set("Pieces filled", Long.toString(st.pieces()));
            set("Splits", Long.toString(st.splits()));
            set("Deepest split", Integer.toString(st.deepestSplit()));
            set("Caps reached", Long.toString(st.capsReached()));
            set("Pixels written", Long.toString(st.pixelsWritten()));
        }
        RenderSettings r = owner.state().settings().render();
        boolean measuring = owner.state().settings().compare() || owner.state().settings().view() != ViewKind.IMAGE;
        if (m == null || !measuring) {
            for (String k : new String[] {"Max displacement", "p99 displacement", "Texels that differ", "PSNR", "Measured"}) {
                set(k, "\u2014");
            }
            return;
        }
        Comparison c = m.comparison();
        set("Max displacement", String.format(Locale.ROOT, "%.3f px", c.maxDisplacement()));
        set("p99 displacement", String.format(Locale.ROOT, "%.3f px", c.p99Displacement()));
        set("Texels that differ", String.format(Locale.ROOT, "%.2f %%", 100 * c.texelDifferShare()));
        set("PSNR", Double.isInfinite(c.psnrDb()) ? "identical" : String.format(Locale.ROOT, "%.2f dB", c.psnrDb()));
        set("Measured", String.format(Locale.ROOT, "%.1f s ago, %.0f ms", (System.nanoTime() - m.nanos()) / 1e9,
                progress.compareMs()));
        if (r.mode() != m.settings().render().mode()) {
            set("Measured", "updating\u2026");
        }
    }

    private void set(String name, String text) {
        JLabel l = readouts.get(name);
        if (l != null && !text.equals(l.getText())) {
            l.setText(text);
        }
    }

    private static String ms(long nanos) {
        return String.format(Locale.ROOT, "%.2f", nanos / 1e6);
    }
}
