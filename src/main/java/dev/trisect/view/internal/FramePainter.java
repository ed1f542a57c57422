package dev.trisect.view.internal;

import dev.trisect.metrics.HeatMap;
import dev.trisect.metrics.HeatScale;
import dev.trisect.render.RenderMode;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;

/**
 * Paints a frame into a view: the image scaled to the view (nearest neighbour, so device pixels map
 * one to one at render scale 1), and over it what the developer tools add — the outline colours'
 * legend, the pixel inspector, the heat map's legend, the split view's divider. Event thread only.
 */
public final class FramePainter {
    private FramePainter() {
    }

    /**
     * Paints a view: takes the controller's newest finished frame (handing back the one shown until
     * now), paints it into the {@code w x h} view (logical pixels) as {@link #paint} does, and tells
     * the render thread which frame is now on screen ({@code pinned}: the pixel inspector is pinned).
     */
    public static void present(Graphics g, ViewController controller, int w, int h, boolean pinned) {
        FrameSlot front = controller.acquireFront();
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            paint(g2, front, w, h, pinned);
            if (controller.state().statOverlay()) {
                StatOverlay.paint(g2, front, controller.state().progress().fps());
            }
        } finally {
            g2.dispose();
        }
        if (front != null) {
            controller.framePainted(front.serial);
        }
    }

    /** Paints {@code front} (or a dark grey view before the first frame) into a {@code w x h} view. */
    public static void paint(Graphics2D g2, FrameSlot front, int w, int h, boolean pinned) {
        if (front == null) {
            g2.setColor(Color.DARK_GRAY);
            g2.fillRect(0, 0, w, h);
            return;
        }
        g2.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
        g2.drawImage(front.image, 0, 0, w, h, null);
        if (front.render != null && front.render.borders() && front.view != ViewKind.DIFFERENCE) {
            // Whenever outlines are drawn, whatever their colour, the legend says what they are.
            BorderLegend.of(front.render, fallbackPieces(front)).paint(g2, h);
        }
        if (front.inspection != null) {
            InspectorPainter.paint(g2, front, w, h, pinned);
        }
        InspectorPainter.paintPins(g2, front, w, h);
        if (front.view == ViewKind.DIFFERENCE) {
            paintLegend(g2, front.heatScale);
        } else if (front.view == ViewKind.SPLIT) {
            paintDivider(g2, (int) Math.round(front.splitFraction * w), h, splitLabels(front.render.mode()));
        }
    }

    /**
     * The frame of {@code front} as a new image, as a host saves it: with its borders, without the
     * legends painted over it — except in the Difference view, where the heat map gets its scale's
     * legend drawn in, as {@code trisect compare --heatmap} writes it (a heat map means nothing
     * without its scale).
     */
    public static BufferedImage image(FrameSlot front) {
        BufferedImage image = front.frame.toImage();
        if (front.view == ViewKind.DIFFERENCE && front.heatScale != null) {
            int[] argb = image.getRGB(0, 0, front.width(), front.height(), null, 0, front.width());
            HeatMap.drawLegend(argb, front.width(), front.height(), front.heatScale);
            image.setRGB(0, 0, front.width(), front.height(), argb, 0, front.width());
        }
        return image;
    }

    /**
     * The names of the split view's halves, left and right: the path shown, and the per-pixel path —
     * one name for the per-pixel path on both sides when it is the path shown.
     */
    static String[] splitLabels(RenderMode mode) {
        return mode == RenderMode.PERSPECTIVE ? new String[] {"per-pixel (this path)", "per-pixel (reference)"}
                : new String[] {mode.id(), "per-pixel"};
    }

    private static void paintDivider(Graphics2D g, int x, int h, String[] labels) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(new Color(0, 0, 0, 120));
        g.setStroke(new BasicStroke(3));
        g.drawLine(x, 0, x, h);
        g.setColor(Color.WHITE);
        g.setStroke(new BasicStroke(1));
        g.drawLine(x, 0, x, h);
        g.fillOval(x - 6, h / 2 - 6, 12, 12);
        g.setFont(g.getFont().deriveFont(Font.BOLD, 13f));
        label(g, labels[0], x - 10 - g.getFontMetrics().stringWidth(labels[0]), 22);
        label(g, labels[1], x + 10, 22);
    }

    /** Size of the heat-map legend's text, pixels. */
    static final float LEGEND_TEXT_PX = 13f;

    /**
     * The heat map's legend, on a panel of its own in the top-left corner: the ramp with its labels,
     * the scale named, and what black (nothing drawn) and grey (another triangle) mean.
     */
    static void paintLegend(Graphics2D g, HeatScale scale) {
        int x = 14;
        int y = 14;
        int barW = 300;
        int barH = 14;
        g.setFont(g.getFont().deriveFont(LEGEND_TEXT_PX));
        java.awt.FontMetrics fm = g.getFontMetrics();
        int line = fm.getHeight();
        String title = (scale.logarithmic() ? "log" : "linear") + " displacement from the per-pixel path";
        int sw = fm.getAscent() - 2;
        String[] names = {"not drawn", "not comparable (another triangle)"};
        int[] colours = {HeatMap.UNCOVERED_ARGB, HeatMap.UNDEFINED_ARGB};
        int rowW = 2 * (sw + 4) + 14 + fm.stringWidth(names[0]) + fm.stringWidth(names[1]);
        int boxW = Math.max(barW, Math.max(fm.stringWidth(title), rowW));
        g.setColor(new Color(HeatMap.LEGEND_BACKGROUND & 0xFFFFFF | 0xE0000000, true));
        g.fillRoundRect(x - 8, y - 8, boxW + 16, barH + 8 + 3 * line + 12, 10, 10);
        for (int i = 0; i < barW; i++) {
            g.setColor(new Color(HeatMap.colour(scale.pixelsAt((double) i / (barW - 1)), scale)));
            g.fillRect(x + i, y, 1, barH);
        }
        g.setColor(Color.WHITE);
        // A label at every decade (log) or at the ends and middle (linear), with a tick; the top "≥".
        for (HeatScale.Label l : scale.labels()) {
            int tx = x + (int) Math.round((barW - 1) * l.fraction());
            g.drawLine(tx, y + barH, tx, y + barH + 3);
        }
        int base = y + barH + 4 + fm.getAscent();
        for (HeatScale.Placed p : HeatScale.layout(scale.labels(), barW, fm::stringWidth, 6)) {
            g.drawString(p.text(), x + p.x(), base);
        }
        g.drawString(title, x, base + line);
        int sx = x;
        for (int k = 0; k < 2; k++) {
            // A white frame round each swatch, so that black shows on the dark panel.
            g.fillRect(sx, base + 2 * line - sw, sw, sw);
            g.setColor(new Color(colours[k]));
            g.fillRect(sx + 1, base + 2 * line - sw + 1, sw - 2, sw - 2);
            g.setColor(Color.WHITE);
            g.drawString(names[k], sx + sw + 4, base + 2 * line);
            sx += sw + 4 + fm.stringWidth(names[k]) + 14;
        }
    }

    /** The frame's pieces filled per pixel (outlined in magenta), 0 when unknown. */
    static long fallbackPieces(FrameSlot front) {
        return front.stats == null ? 0 : front.stats.piecesFallback();
    }

    private static void label(Graphics2D g, String text, int x, int y) {
        g.setColor(new Color(0, 0, 0, 140));
        g.drawString(text, x + 1, y + 1);
        g.setColor(Color.WHITE);
        g.drawString(text, x, y);
    }
}
