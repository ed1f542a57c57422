package dev.trisect.devtools;

import dev.trisect.base.internal.Counts;
import dev.trisect.render.RenderMode;
import dev.trisect.view.internal.FrameSlot;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewState;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.util.Locale;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JToggleButton;

/**
 * Developer tools: the last five seconds of frame times as a live chart stacked by stage
 * ({@link FrameChart}), which can be paused to pick a past frame and read its stages; and each
 * path's engine time on the last measured frame side by side.
 */
final class TimingSection implements ToolSection {
    private static final String PICKED = "Picked frame";

    private final ToolsForm form = new ToolsForm("Frame time");
    private final FrameChart chart = new FrameChart(this::pick);
    private final PathBars paths = new PathBars();
    private final JToggleButton pause = new JToggleButton("Pause");
    private final ViewState state;
    private final JLabel pickedText = new JLabel();
    private String picked = "";

    TimingSection(ViewController owner) {
        this.state = owner.state();
        pause.setToolTipText("Stop the chart on the frames it shows, to hover them or click one and read its stages");
        pause.addActionListener(e -> {
            if (!pause.isSelected()) {
                showPicked("");
            }
            pausedShown();
            refresh(null, null, null);
        });
        form.row(chart);
        form.row(pause, null);
        pickedText.setToolTipText("The stages of the frame clicked in the chart, milliseconds, top stage first");
        form.row(pickedText);
        showPicked("");
        form.row(paths);
    }

    @Override
    public JComponent component() {
        return form.panel();
    }

    /** The button and the chart's heading say whether the chart is paused. */
    private void pausedShown() {
        pause.setText(pause.isSelected() ? "Paused: click to resume" : "Pause");
        chart.paused(pause.isSelected());
    }

    /** A click in the chart pauses it and picks the frame under the mouse. */
    private void pick(int index) {
        if (!pause.isSelected()) {
            pause.setSelected(true);
            pausedShown();
        }
        double[][] rows = chart.frames();
        showPicked(index < 0 ? "" : Counts.of(rows.length - 1 - index, "frame") + " before the newest: "
                + FrameChart.breakdown(rows[index], ", ").replaceFirst(" ms, ", " ms = "));
        chart.show(rows, index);
    }

    @Override
    public void refresh(ViewState.Progress progress, FrameSlot front, ViewState.Measurement m) {
        if (!pause.isSelected()) {
            chart.show(state.frameTimes.snapshot(), -1);
        }
        paths.samples.offer(state.pathMs());
        paths.repaint();
    }

    /** The picked frame's line, wrapped to the section's width (the hint when none is picked). */
    private void showPicked(String text) {
        picked = text;
        pickedText.setText("<html><body style='width:300px'>" + (text.isEmpty()
                ? "Hover a bar for its stages; click one (or Pause) to stop the chart and read it here." : text)
                + "</body></html>");
    }

    @Override
    public String readout(String name) {
        return PICKED.equals(name) ? picked : form.get(name);
    }

    /** The chart, for tests. */
    FrameChart chart() {
        return chart;
    }

    /** The Pause button, for tests. */
    JToggleButton pauseButton() {
        return pause;
    }

    /**
     * Each path's engine time over the last comparisons: one row per path, its name, a bar to the median
     * and a whisker from the least to the greatest sample, and the numbers.
     */
    static final class PathBars extends JComponent {
        private static final long serialVersionUID = 1L;
        private static final String[] NAMES = {"perspective", "affine", "tessellated", "spans"};
        final transient PathSamples samples = new PathSamples();

        PathBars() {
            setPreferredSize(new Dimension(330, 4 * 15 + 16));
            setToolTipText("Each path's engine time over the last " + PathSamples.CAPACITY + " comparisons (about "
                    + "every 0.4 s): the bar is the median, the whisker runs from the least to the greatest, so one "
                    + "slow frame neither hides nor decides. The paths neither shown nor the reference are drawn too, "
                    + "to time them. Every path is timed recording the UV output the comparison reads, which bench "
                    + "does not: 10-30 % more than bench's times");
        }

        /** A row's numbers: "12.3 ms (10.1-15.0)", the median and the spread of the samples. */
        static String text(PathSamples s, int path) {
            return s.count() == 1 ? String.format(Locale.ROOT, "%.1f ms", s.median(path))
                    : String.format(Locale.ROOT, "%.1f ms (%.1f\u2013%.1f)", s.median(path), s.min(path), s.max(path));
        }

        @Override
        protected void paintComponent(Graphics g0) {
            Graphics2D g = (Graphics2D) g0.create();
            try {
                g.setFont(g.getFont().deriveFont(11f));
                g.setColor(Color.GRAY);
                int n = samples.count();
                g.drawString(n == 0 ? "each path's engine time" : "each path's engine time, median (range) of "
                        + Counts.of(n, "comparison"), 0, 11);
                if (n == 0) {
                    g.drawString("(nothing measured in this scene yet)", 0, 27);
                    return;
                }
                double top = 1;
                for (RenderMode mode : RenderMode.values()) {
                    top = Math.max(top, samples.max(mode.ordinal()));
                }
                int nameW = g.getFontMetrics().stringWidth("tessellated") + 8;
                int valueW = g.getFontMetrics().stringWidth("000.0 ms (000.0\u2013000.0)") + 6;
                int barMax = Math.max(10, getWidth() - nameW - valueW);
                for (RenderMode mode : RenderMode.values()) {
                    int y = 16 + mode.ordinal() * 15;
                    int p = mode.ordinal();
                    g.setColor(getForeground());
                    g.drawString(NAMES[p], 0, y + 10);
                    g.setColor(new Color(0x59A14F));
                    int bar = (int) Math.round(samples.median(p) / top * barMax);
                    g.fillRect(nameW, y + 2, bar, 10);
                    int lo = nameW + (int) Math.round(samples.min(p) / top * barMax);
                    int hi = nameW + (int) Math.round(samples.max(p) / top * barMax);
                    g.setColor(getForeground());
                    g.drawLine(lo, y + 7, hi, y + 7);
                    g.drawLine(lo, y + 4, lo, y + 10);
                    g.drawLine(hi, y + 4, hi, y + 10);
                    g.drawString(text(samples, p), Math.max(nameW + bar, hi) + 4, y + 10);
                }
            } finally {
                g.dispose();
            }
        }
    }
}
