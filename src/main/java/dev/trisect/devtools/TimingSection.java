package dev.trisect.devtools;

import dev.trisect.render.RenderMode;
import dev.trisect.view.internal.FrameSlot;
import dev.trisect.view.internal.FrameTimes;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewState;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.Graphics;
import java.util.Locale;
import javax.swing.JComponent;

/**
 * Developer tools: the last five seconds of frame times as a live chart stacked by stage, and each
 * path's time on the last measured frame side by side. Drawn by hand: a few hundred filled rectangles
 * a refresh, which a chart library would only wrap.
 */
final class TimingSection implements ToolSection {
    /** Stage colours, in {@link FrameTimes#STAGES} order. */
    static final Color[] COLOURS = {new Color(0x4E79A7), new Color(0x76B7B2), new Color(0x59A14F),
        new Color(0xEDC948), new Color(0xF28E2B), new Color(0xE15759), new Color(0xB07AA1), new Color(0x9C9C9C)};

    private final ToolsForm form = new ToolsForm("Frame time");
    private final Graph graph = new Graph();
    private final ViewState state;

    TimingSection(ViewController owner) {
        this.state = owner.state();
        graph.setToolTipText("Milliseconds per frame over the last 5 s, stacked by stage: transform, clip, tessellate, "
                + "raster, overlay, compare (per-pixel render, other paths' timing, measuring), present (handing the "
                + "frame to the screen) and other; they add up to the whole frame. Bars right: each path's engine "
                + "time on the last measured frame");
        form.row(graph);
    }

    @Override
    public JComponent component() {
        return form.panel();
    }

    @Override
    public void refresh(ViewState.Progress progress, FrameSlot front, ViewState.Measurement m) {
        graph.frames = state.frameTimes.snapshot();
        graph.paths = state.pathMs();
        graph.repaint();
    }

    /** The chart. Event thread only. */
    static final class Graph extends JComponent {
        private static final long serialVersionUID = 1L;
        private static final int PATHS_W = 86;
        transient double[][] frames = new double[0][];
        transient double[] paths;

        Graph() {
            setPreferredSize(new Dimension(330, 185));
        }

        /** Top of the scale: the worst whole frame shown, rounded up to a step of 10 ms (at least 20). */
        static double scaleMs(double[][] frames) {
            double worst = 0;
            for (double[] f : frames) {
                double sum = 0;
                for (double v : f) {
                    sum += v;
                }
                worst = Math.max(worst, sum);
            }
            return Math.max(20, Math.ceil(worst / 10) * 10);
        }

        @Override
        protected void paintComponent(Graphics g0) {
            Graphics2D g = (Graphics2D) g0.create();
            try {
                int w = getWidth() - PATHS_W;
                int h = getHeight() - 52;
                g.setColor(new Color(0x202020));
                g.fillRect(0, 0, getWidth(), getHeight());
                double top = scaleMs(frames);
                g.setFont(g.getFont().deriveFont(10f));
                g.setColor(Color.GRAY);
                for (double ms = 0; ms <= top; ms += top / 4) {
                    int y = h - (int) Math.round(ms / top * (h - 12));
                    g.drawLine(0, y, w, y);
                    g.drawString(String.format(Locale.ROOT, "%.0f ms", ms), 2, y - 1);
                }
                int n = frames.length;
                for (int i = 0; i < n; i++) {
                    int x0 = (int) ((long) i * w / FrameTimes.CAPACITY) + (w - (int) ((long) n * w / FrameTimes.CAPACITY));
                    int x1 = Math.max(x0 + 1, (int) ((long) (i + 1) * w / FrameTimes.CAPACITY)
                            + (w - (int) ((long) n * w / FrameTimes.CAPACITY)));
                    double acc = 0;
                    for (int s = 0; s < frames[i].length; s++) {
                        int yLow = h - (int) Math.round(acc / top * (h - 12));
                        acc += frames[i][s];
                        int yHigh = h - (int) Math.round(acc / top * (h - 12));
                        g.setColor(COLOURS[s]);
                        g.fillRect(x0, yHigh, x1 - x0, Math.max(0, yLow - yHigh));
                    }
                }
                paintPaths(g, w + 6, h);
                // Legend under the chart.
                int lx = 2;
                int ly = h + 26;
                for (int s = 0; s < FrameTimes.STAGES.length; s++) {
                    String name = FrameTimes.STAGES[s];
                    int tw = g.getFontMetrics().stringWidth(name) + 16;
                    if (lx + tw > getWidth()) {
                        lx = 2;
                        ly += 13;
                    }
                    g.setColor(COLOURS[s]);
                    g.fillRect(lx, ly - 8, 9, 9);
                    g.setColor(Color.LIGHT_GRAY);
                    g.drawString(name, lx + 12, ly);
                    lx += tw;
                }
            } finally {
                g.dispose();
            }
        }

        private void paintPaths(Graphics2D g, int x, int h) {
            g.setColor(Color.LIGHT_GRAY);
            g.drawString("paths, ms", x, 10);
            if (paths == null) {
                g.drawString("(measuring off)", x, 24);
                return;
            }
            double top = 1;
            for (double p : paths) {
                top = Math.max(top, p);
            }
            String[] names = {"persp", "affine", "tess", "spans"};
            int barW = 22;
            for (RenderMode m : RenderMode.values()) {
                int bx = x + m.ordinal() * (barW + 4);
                int bh = (int) Math.round(paths[m.ordinal()] / top * (h - 30));
                g.setColor(new Color(0x59A14F).brighter());
                g.fillRect(bx, h - bh, barW, bh);
                g.setColor(Color.LIGHT_GRAY);
                g.drawString(String.format(Locale.ROOT, "%.1f", paths[m.ordinal()]), bx, h - bh - 2);
                g.drawString(names[m.ordinal()], bx, h + 11);
            }
        }
    }
}
