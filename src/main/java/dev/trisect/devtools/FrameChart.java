package dev.trisect.devtools;

import dev.trisect.base.internal.Counts;
import dev.trisect.view.internal.FrameTimes;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.FontMetrics;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.util.Arrays;
import java.util.Locale;
import java.util.function.IntConsumer;
import javax.swing.JComponent;
import javax.swing.ToolTipManager;

/**
 * The frame-time chart: the last {@link FrameTimes#CAPACITY} frames, each a bar stacked by stage, on
 * a scale that slow frames do not stretch (its top is a round value over the 75th percentile frame;
 * taller bars are cut at the top and marked in red), with grid lines at round milliseconds and the
 * 16.7 and 33.3 ms lines (60 and 30 frames per second). Hovering a bar shows its stages; a click
 * picks it. Drawn by hand: a few hundred filled rectangles a refresh, which a chart library would
 * only wrap. Event thread only.
 */
final class FrameChart extends JComponent {
    private static final long serialVersionUID = 1L;
    /** Stage colours, in {@link FrameTimes#STAGES} order. */
    static final Color[] COLOURS = {new Color(0x4E79A7), new Color(0x76B7B2), new Color(0x59A14F),
        new Color(0xEDC948), new Color(0xF28E2B), new Color(0xE15759), new Color(0xB07AA1), new Color(0x9C9C9C)};
    /** The lowest top of the scale, so that the 16.7 ms line always shows. */
    static final double MIN_TOP_MS = 20;
    /** Frame times drawn as reference lines: 60 and 30 frames per second. */
    static final double[] TARGET_MS = {1000 / 60.0, 1000 / 30.0};
    private static final int PLOT_TOP = 14;
    private static final int LEGEND_H = 30;

    private transient double[][] frames = new double[0][];
    private int picked = -1;
    private boolean paused;

    /** @param onPick given the index of a frame the user clicked in the frames shown (or -1 off any bar) */
    FrameChart(IntConsumer onPick) {
        setPreferredSize(new Dimension(330, 170));
        setToolTipText("");
        addMouseListener(new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                onPick.accept(frameAt(e.getX()));
            }
        });
        // The breakdown follows the mouse from bar to bar without the usual wait.
        ToolTipManager.sharedInstance().registerComponent(this);
    }

    /** Shows these frames (oldest first, milliseconds per stage) and the picked one (-1 for none). */
    void show(double[][] rows, int pick) {
        frames = rows;
        picked = pick;
        repaint();
    }

    double[][] frames() {
        return frames;
    }

    /** A frame's whole time: the sum of its stages. */
    static double total(double[] stages) {
        double sum = 0;
        for (double v : stages) {
            sum += v;
        }
        return sum;
    }

    /**
     * The top of the scale, milliseconds: the smallest round value (1, 2, 2.5 or 5 times a power of
     * ten) at or over 1.5 times the 75th percentile frame, and at least {@link #MIN_TOP_MS}. Slow frames
     * — a spike, or the one in ten that also draws the per-pixel path to measure it — are cut at the top
     * and marked instead of squashing the rest.
     */
    static double topMs(double[][] rows) {
        if (rows.length == 0) {
            return MIN_TOP_MS;
        }
        double[] totals = new double[rows.length];
        for (int i = 0; i < rows.length; i++) {
            totals[i] = total(rows[i]);
        }
        Arrays.sort(totals);
        double p75 = totals[(int) Math.floor(0.75 * (totals.length - 1))];
        return roundUp(Math.max(MIN_TOP_MS, 1.5 * p75));
    }

    /** The smallest of 1, 2, 2.5, 5 times a power of ten at or over {@code v} (greater than 0). */
    static double roundUp(double v) {
        double decade = Math.pow(10, Math.floor(Math.log10(v)));
        for (double m : new double[] {1, 2, 2.5, 5, 10}) {
            if (m * decade >= v * (1 - 1e-12)) {
                return m * decade;
            }
        }
        return 10 * decade;
    }

    /** Grid spacing for a scale of {@code top}: the largest of 1, 2, 5 times a power of ten at most a quarter of it. */
    static double gridStep(double top) {
        double quarter = top / 4;
        double decade = Math.pow(10, Math.floor(Math.log10(quarter)));
        for (double m : new double[] {5, 2, 1}) {
            if (m * decade <= quarter * (1 + 1e-12)) {
                return m * decade;
            }
        }
        return decade;
    }

    /** The index of the frame drawn at view column {@code x}, or -1 where there is none. */
    int frameAt(int x) {
        int n = frames.length;
        int slot = (int) Math.floor((double) x * FrameTimes.CAPACITY / Math.max(1, getWidth()));
        int i = slot - (FrameTimes.CAPACITY - n);
        return i >= 0 && i < n ? i : -1;
    }

    /** The stages of frame {@code i}, one line each, for the tooltip and the picked-frame readout. */
    static String breakdown(double[] row, String separator) {
        StringBuilder b = new StringBuilder(String.format(Locale.ROOT, "%.1f ms", total(row)));
        for (int s = FrameTimes.STAGES.length - 1; s >= 0; s--) {
            b.append(separator).append(String.format(Locale.ROOT, "%s %.2f", FrameTimes.STAGES[s], row[s]));
        }
        return b.toString();
    }

    @Override
    public String getToolTipText(MouseEvent e) {
        int i = frameAt(e.getX());
        if (i < 0) {
            return "<html>Milliseconds per frame over the last 5 s, stacked by stage (they add up to the whole<br>"
                    + "frame). Hover a bar for its stages; click one to pause the chart and pick it.</html>";
        }
        return "<html><b>" + Counts.of(frames.length - 1 - i, "frame") + " before the newest</b><br>"
                + breakdown(frames[i], "<br>") + "</html>";
    }

    @Override
    protected void paintComponent(Graphics g0) {
        Graphics2D g = (Graphics2D) g0.create();
        try {
            int w = getWidth();
            int plotH = getHeight() - LEGEND_H - PLOT_TOP;
            int base = PLOT_TOP + plotH;
            g.setColor(BACKGROUND);
            g.fillRect(0, 0, w, getHeight());
            g.setFont(g.getFont().deriveFont(10f));
            FontMetrics fm = g.getFontMetrics();
            double top = topMs(frames);
            int n = frames.length;
            double slotW = (double) w / FrameTimes.CAPACITY;
            int clipped = 0;
            double worst = 0;
            for (int i = 0; i < n; i++) {
                int x0 = (int) Math.floor((FrameTimes.CAPACITY - n + i) * slotW);
                int x1 = Math.max(x0 + 1, (int) Math.floor((FrameTimes.CAPACITY - n + i + 1) * slotW));
                double acc = 0;
                for (int s = 0; s < frames[i].length; s++) {
                    int yLow = y(acc, top, base, plotH);
                    acc += frames[i][s];
                    int yHigh = y(acc, top, base, plotH);
                    g.setColor(COLOURS[s]);
                    g.fillRect(x0, yHigh, x1 - x0, Math.max(0, yLow - yHigh));
                }
                worst = Math.max(worst, acc);
                if (acc > top) {
                    // Cut at the top: a red cap says the bar goes on.
                    clipped++;
                    g.setColor(Color.RED);
                    g.fillRect(x0, PLOT_TOP - 4, x1 - x0, 4);
                }
                if (i == picked) {
                    g.setColor(Color.WHITE);
                    g.drawRect(x0 - 1, y(acc, top, base, plotH) - 1, x1 - x0 + 1, base - y(acc, top, base, plotH) + 1);
                }
            }
            g.setColor(new Color(255, 255, 255, 60));
            double step = gridStep(top);
            for (double ms = step; ms <= top * (1 + 1e-9); ms += step) {
                int y = y(ms, top, base, plotH);
                g.drawLine(0, y, w, y);
            }
            for (double ms = step; ms <= top * (1 + 1e-9); ms += step) {
                // Under its line, so that the top one stays clear of the heading; on a band of the chart's
                // background, so that it reads over the bars.
                boxed(g, msText(ms) + " ms", 2, y(ms, top, base, plotH) + fm.getAscent(), Color.LIGHT_GRAY);
            }
            g.setStroke(new BasicStroke(1, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {4, 3}, 0));
            g.setColor(new Color(0xFF, 0xFF, 0xFF, 170));
            int y60 = y(TARGET_MS[0], top, base, plotH);
            int y30 = y(TARGET_MS[1], top, base, plotH);
            g.drawLine(0, y60, w, y60);
            if (TARGET_MS[1] <= top) {
                g.drawLine(0, y30, w, y30);
            }
            // One label per line, or one for both where they lie too close to read apart.
            if (TARGET_MS[1] > top) {
                label(g, "16.7 ms (60 fps)", w, y60);
            } else if (y60 - y30 >= fm.getHeight()) {
                label(g, "16.7 ms (60 fps)", w, y60);
                label(g, "33.3 ms (30 fps)", w, y30);
            } else {
                label(g, "16.7 and 33.3 ms (60, 30 fps)", w, y30);
            }
            g.setColor(Color.LIGHT_GRAY);
            g.drawString(heading(paused, clipped, worst, top), 2, PLOT_TOP - 5);
            paintLegend(g, base + 12, w);
        } finally {
            g.dispose();
        }
    }

    private static void label(Graphics2D g, String text, int w, int y) {
        boxed(g, text, w - g.getFontMetrics().stringWidth(text) - 2, y - 2, Color.WHITE);
    }

    /** The chart's background, behind its labels too. */
    static final Color BACKGROUND = new Color(0x202020);

    /** Draws {@code text} at baseline {@code y} on a box of the chart's background, so that bars never run through it. */
    private static void boxed(Graphics2D g, String text, int x, int y, Color colour) {
        FontMetrics fm = g.getFontMetrics();
        g.setColor(BACKGROUND);
        g.fillRect(x - 1, y - fm.getAscent(), fm.stringWidth(text) + 2, fm.getAscent() + fm.getDescent());
        g.setColor(colour);
        g.drawString(text, x, y);
    }

    /** The line over the chart: paused or not, its scale, or the frames cut at its top. */
    static String heading(boolean paused, int clipped, double worst, double top) {
        String scale = clipped == 0 ? "scale 0\u2013" + msText(top) + " ms"
                : String.format(Locale.ROOT, "%d frame%s above the scale (red), worst %.0f ms", clipped,
                clipped == 1 ? "" : "s", worst);
        return paused ? "PAUSED \u2014 " + scale : scale;
    }

    /** Marks the chart paused (the heading says so) or live. */
    void paused(boolean on) {
        paused = on;
        repaint();
    }

    private static int y(double ms, double top, int base, int plotH) {
        return base - (int) Math.round(Math.min(ms, top) / top * plotH);
    }

    /** Stage names under the chart, wrapping so that none runs into the next. */
    private static void paintLegend(Graphics2D g, int y, int w) {
        int lx = 2;
        int ly = y;
        for (int s = 0; s < FrameTimes.STAGES.length; s++) {
            String name = FrameTimes.STAGES[s];
            int tw = g.getFontMetrics().stringWidth(name) + 18;
            if (lx + tw > w) {
                lx = 2;
                ly += 13;
            }
            g.setColor(COLOURS[s]);
            g.fillRect(lx, ly - 8, 9, 9);
            g.setColor(Color.LIGHT_GRAY);
            g.drawString(name, lx + 12, ly);
            lx += tw;
        }
    }

    /** Milliseconds on the scale, without needless decimals (5, 2.5, 0.5). */
    static String msText(double v) {
        return v == Math.rint(v) ? Long.toString(Math.round(v)) : String.format(Locale.ROOT, "%.1f", v);
    }
}
