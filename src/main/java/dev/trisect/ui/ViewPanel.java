package dev.trisect.ui;

import dev.trisect.metrics.HeatMap;
import dev.trisect.pipeline.RenderSettings;
import dev.trisect.raster.BorderStyle;
import dev.trisect.raster.OverlayColours;
import dev.trisect.metrics.HeatScale;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.util.Locale;
import java.util.function.DoubleConsumer;
import javax.swing.JComponent;

/**
 * Shows the newest frame from the render thread, at device pixels on HiDPI screens, with the heat
 * map's legend in the difference view and the divider in the split view. Mouse drags turn the camera
 * (or move the divider), the wheel raises and lowers it. Event thread only.
 */
final class ViewPanel extends JComponent {
    private static final long serialVersionUID = 1L;
    /** Grab distance of the split divider, logical pixels. */
    private static final int DIVIDER_GRAB = 8;

    private final transient DemoState state;
    private final transient TripleBuffer buffers;
    private transient RenderLoop loop;
    private transient FrameSlot front;
    private final transient DoubleConsumer splitMoved;
    private int lastX;
    private int lastY;
    private boolean draggingDivider;
    private boolean inspecting;
    private boolean pinned;
    private boolean dragged;

    ViewPanel(DemoState state, TripleBuffer buffers, DoubleConsumer splitMoved) {
        this.state = state;
        this.buffers = buffers;
        this.splitMoved = splitMoved;
        setPreferredSize(new Dimension(1280, 720));
        setOpaque(true);
        setFocusable(true);
        MouseAdapter mouse = new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                dragged = false;
                lastX = e.getX();
                lastY = e.getY();
                draggingDivider = state.settings().view() == ViewKind.SPLIT
                        && Math.abs(e.getX() - dividerX()) <= DIVIDER_GRAB;
                requestFocusInWindow();
            }

            @Override
            public void mouseMoved(MouseEvent e) {
                if (inspecting && !pinned) {
                    inspectAt(e.getX(), e.getY());
                }
            }

            @Override
            public void mouseReleased(MouseEvent e) {
                if (inspecting && !dragged && !draggingDivider) {
                    // A click without a drag pins the inspector to this pixel, or lets it follow again.
                    pinned = !pinned;
                    inspectAt(e.getX(), e.getY());
                }
            }

            @Override
            public void mouseDragged(MouseEvent e) {
                dragged = true;
                if (draggingDivider) {
                    splitMoved.accept(getWidth() == 0 ? 0.5 : (double) e.getX() / getWidth());
                } else {
                    state.input.drag(e.getX() - lastX, e.getY() - lastY);
                }
                lastX = e.getX();
                lastY = e.getY();
            }

            @Override
            public void mouseWheelMoved(MouseWheelEvent e) {
                state.input.wheel(e.getWheelRotation());
            }
        };
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        addMouseWheelListener(mouse);
    }

    /** Turns the pixel inspector on (it follows the mouse; a click pins it) or off. */
    void inspector(boolean on) {
        inspecting = on;
        pinned = false;
        if (!on) {
            state.inspect(-1, -1);
        } else {
            java.awt.Point p = getMousePosition();
            inspectAt(p == null ? getWidth() / 2 : p.x, p == null ? getHeight() / 2 : p.y);
        }
    }

    boolean pinned() {
        return pinned;
    }

    /** Points the inspector at the frame pixel under view point (x, y). */
    void inspectAt(int x, int y) {
        FrameSlot f = front;
        if (f == null || getWidth() == 0 || getHeight() == 0) {
            return;
        }
        int fx = Math.max(0, Math.min(f.width() - 1, (int) ((long) x * f.width() / getWidth())));
        int fy = Math.max(0, Math.min(f.height() - 1, (int) ((long) y * f.height() / getHeight())));
        state.inspect(fx, fy);
    }

    /** Connects the loop that waits for frames to be shown. */
    void attach(RenderLoop renderLoop) {
        this.loop = renderLoop;
    }

    /** The frame on screen now, or null before the first one. Event thread only. */
    FrameSlot front() {
        return front;
    }

    private int dividerX() {
        return (int) Math.round(state.settings().splitFraction() * getWidth());
    }

    /** Tells the render thread the view's size in device pixels. */
    void publishSize() {
        double scale = getGraphicsConfiguration() == null ? 1
                : getGraphicsConfiguration().getDefaultTransform().getScaleX();
        state.viewSize((int) Math.round(getWidth() * scale), (int) Math.round(getHeight() * scale));
    }

    @Override
    protected void paintComponent(Graphics g) {
        front = buffers.acquire(front);
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            int w = getWidth();
            int h = getHeight();
            if (front == null) {
                g2.setColor(Color.DARK_GRAY);
                g2.fillRect(0, 0, w, h);
                return;
            }
            // Nearest neighbour: at render scale 1 the image maps onto device pixels one to one, and
            // below it the pixels stay crisp rather than blurred.
            g2.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
            g2.drawImage(front.image, 0, 0, w, h, null);
            if (front.render != null && front.render.borders() && front.view != ViewKind.DIFFERENCE
                    && front.render.borderStyle().colouring() != BorderStyle.Colouring.YELLOW) {
                paintBorderLegend(g2, front.render, h);
            }
            if (front.inspection != null) {
                InspectorPainter.paint(g2, front, w, h, pinned);
            }
            if (front.view == ViewKind.DIFFERENCE) {
                paintLegend(g2, front.heatScale);
            } else if (front.view == ViewKind.SPLIT) {
                paintDivider(g2, (int) Math.round(front.splitFraction * w), h);
            }
        } finally {
            g2.dispose();
        }
        if (loop != null) {
            loop.framePainted(front.serial);
        }
    }

    private void paintDivider(Graphics2D g, int x, int h) {
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(new Color(0, 0, 0, 120));
        g.setStroke(new BasicStroke(3));
        g.drawLine(x, 0, x, h);
        g.setColor(Color.WHITE);
        g.setStroke(new BasicStroke(1));
        g.drawLine(x, 0, x, h);
        g.fillOval(x - 6, h / 2 - 6, 12, 12);
        g.setFont(g.getFont().deriveFont(Font.BOLD, 13f));
        String left = state.settings().render().mode().id();
        label(g, left, x - 10 - g.getFontMetrics().stringWidth(left), 22);
        label(g, "per-pixel", x + 10, 22);
    }

    private void paintLegend(Graphics2D g, HeatScale scale) {
        int x = 14;
        int y = 14;
        int barW = 220;
        int barH = 14;
        g.setColor(new Color(0, 0, 0, 150));
        g.fillRoundRect(x - 8, y - 8, barW + 16, barH + 44, 10, 10);
        for (int i = 0; i < barW; i++) {
            g.setColor(new Color(HeatMap.colour(scale.pixelsAt((double) i / (barW - 1)), scale)));
            g.fillRect(x + i, y, 1, barH);
        }
        g.setColor(Color.WHITE);
        g.setFont(g.getFont().deriveFont(11f));
        g.drawString(HeatScale.number(scale.minPixels()), x, y + barH + 14);
        if (scale.logarithmic()) {
            // Decade ticks, so that the log scale reads as one.
            for (int d = 1; d < HeatScale.DECADES; d++) {
                int tx = x + (int) Math.round((barW - 1) * (double) d / HeatScale.DECADES);
                g.drawLine(tx, y + barH, tx, y + barH + 3);
            }
        }
        String end = HeatScale.number(scale.maxPixels()) + " px";
        g.drawString(end, x + barW - g.getFontMetrics().stringWidth(end), y + barH + 14);
        g.drawString((scale.logarithmic() ? "log" : "linear") + " displacement vs per-pixel; grey: not comparable",
                x, y + barH + 29);
    }

    /** The outline colours' legend, bottom left: the ramp of split depth or of error bound, and fallback. */
    private void paintBorderLegend(Graphics2D g, RenderSettings r, int h) {
        boolean depth = r.borderStyle().colouring() == BorderStyle.Colouring.DEPTH;
        int maxLevel = r.tessellation().maxDepth();
        int barW = 220;
        int x = 14;
        int y = h - 62;
        g.setFont(g.getFont().deriveFont(11f));
        String note = depth ? "fallback (filled per pixel)" : "fallback; yellow = at max error, red = above";
        int boxW = Math.max(barW, 18 + g.getFontMetrics().stringWidth(note)) + 16;
        g.setColor(new Color(0, 0, 0, 160));
        g.fillRoundRect(x - 8, y - 8, boxW, 60, 10, 10);
        for (int i = 0; i < barW; i++) {
            double f = (double) i / (barW - 1);
            int c = depth ? OverlayColours.depth((int) Math.round(f * maxLevel), maxLevel)
                    : OverlayColours.bound(f * 1.25);
            g.setColor(new Color(c, false));
            g.fillRect(x + i, y, 1, 12);
        }
        g.setColor(Color.WHITE);
        g.setFont(g.getFont().deriveFont(11f));
        String left = depth ? "level 0" : "bound 0";
        String right = depth ? "level " + maxLevel + " (cap)" : "\u2265 1.25\u00d7 max error";
        g.drawString(left, x, y + 25);
        g.drawString(right, x + barW - g.getFontMetrics().stringWidth(right), y + 25);
        g.setColor(new Color(OverlayColours.FALLBACK, false));
        g.fillRect(x, y + 32, 12, 10);
        g.setColor(Color.WHITE);
        g.drawString(note, x + 18, y + 41);
    }

    private static void label(Graphics2D g, String text, int x, int y) {
        g.setColor(new Color(0, 0, 0, 140));
        g.drawString(text, x + 1, y + 1);
        g.setColor(Color.WHITE);
        g.drawString(text, x, y);
    }
}
