package dev.trisect.view.internal;

import dev.trisect.pipeline.PieceInfo;
import dev.trisect.raster.RowKnots;
import dev.trisect.scene.internal.DrawnFrame;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.RenderingHints;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** Draws the pixel inspector in the view: a crosshair on the pixel, a magnifier, and its numbers. */
public final class InspectorPainter {
    /** Frame pixels across the magnifier, and its size on screen. */
    static final int MAGNIFIED = 15;
    static final int MAGNIFIER_SIZE = 165;
    /** View pixels between the panel and the view's edge, and between the magnifier and the numbers. */
    static final int MARGIN = 12;
    private static final int GAP = 8;
    /** How far the crosshair's arms reach from the pixel's centre, plus their dark edge. */
    static final int REACH = 26;

    private InspectorPainter() {
    }

    /**
     * A triangle as the user knows it: its object's name (or place in draw order when it has none) and its
     * index in that object's own mesh; the frame-wide number only when the object is not known.
     */
    static String triangleOf(DrawnFrame.Owner owner, int frameTriangle) {
        if (owner == null) {
            return "triangle " + frameTriangle;
        }
        String object = owner.name() != null ? "\"" + owner.name() + "\"" : "object " + (owner.draw() + 1);
        return object + " triangle " + owner.triangle();
    }

    /** The inspector's readout lines for an inspection (also what tests check). */
    static List<String> lines(PixelInspector.Inspection in, boolean pinned) {
        List<String> l = new ArrayList<>();
        // Both paths' colours side by side (swatches follow the text in the view).
        l.add(String.format(Locale.ROOT, "pixel %d,%d %s#%06X", in.x(), in.y(), pinned ? "(pinned) " : "",
                in.argb() & 0xFFFFFF) + (in.refArgb() == 0 ? "" : String.format(Locale.ROOT, ", per-pixel #%06X",
                in.refArgb() & 0xFFFFFF)));
        if (in.shape() != null) {
            // Drawn over the triangle (whose numbers follow): a line, a label, a billboard, the screen text.
            l.add("drawn here: " + in.shape());
        }
        PieceInfo mark = in.outline();
        if (mark != null) {
            // The magenta mark on the pixel belongs to this piece, which may not be the pixel's own.
            l.add("magenta outline: piece " + mark.index() + " of " + triangleOf(in.outlineOwner(), mark.triangle()) + ", "
                    + perPixel(mark));
        }
        if (in.triangle() < 0) {
            l.add("background: nothing drawn");
            return l;
        }
        PieceInfo p = in.piece();
        l.add(triangleOf(in.owner(), in.triangle()) + (p == null ? "" : ", piece " + p.index() + ", split level " + p.level()
                + (p.fallback() ? ", " + perPixel(p) : "")));
        if (p != null || in.triangle2d() != null) {
            l.add("in the view: " + (p == null ? "" : "piece outlined cyan" + (in.triangle2d() == null ? "" : ", "))
                    + (in.triangle2d() == null ? "" : "input triangle dashed"));
        }
        l.add(String.format(Locale.ROOT, "depth w %.4f", in.w()));
        l.add(String.format(Locale.ROOT, "texel s,t this path %.3f, %.3f", in.s(), in.t()));
        l.add(Double.isNaN(in.refS()) ? "per-pixel path: other triangle"
                : String.format(Locale.ROOT, "texel s,t per-pixel  %.3f, %.3f", in.refS(), in.refT()));
        l.add(Double.isNaN(in.displacement()) ? "displacement: undefined"
                : String.format(Locale.ROOT, "exact displacement %.4f px", in.displacement()));
        RowKnots knots = in.knots();
        if (knots != null) {
            int k = in.segment();
            l.add(k < 0 ? String.format(Locale.ROOT, "span: a lone knot (%d knots on the row)", knots.columns().length)
                    : String.format(Locale.ROOT, "span segment %d of %d: knots x %d..%d (%d px), bound %.3f px", k + 1,
                    knots.bounds().length, knots.columns()[k], knots.columns()[k + 1],
                    knots.columns()[k + 1] - knots.columns()[k], knots.bounds()[k]));
        }
        double[] light = in.light();
        l.add(String.format(Locale.ROOT, "mip level %d (lambda %.2f%s), texel %d,%d", in.mipLevel(), in.lambda(),
                in.segment() >= 0 ? " of the segment" : "", in.texelX(), in.texelY())
                + (light == null ? "" : String.format(Locale.ROOT, ", light %.3f %.3f %.3f", light[0], light[1], light[2])));
        return l;
    }

    /** The frame's colours in the magnifier's square round (x, y), row by row; 0 outside the frame. */
    static int[] patch(int[] argb, int width, int height, int x, int y) {
        int[] out = new int[MAGNIFIED * MAGNIFIED];
        for (int j = 0; j < MAGNIFIED; j++) {
            for (int i = 0; i < MAGNIFIED; i++) {
                int px = x + i - MAGNIFIED / 2;
                int py = y + j - MAGNIFIED / 2;
                out[j * MAGNIFIED + i] = px >= 0 && py >= 0 && px < width && py < height ? argb[py * width + px] : 0;
            }
        }
        return out;
    }

    /**
     * What the magnifier says when it shows marks drawn over the image — outlines (B), the hover tint —
     * that the numbers exclude (they are read from the image before them): how many of its pixels
     * they cover; null when it shows none.
     */
    static String marksNote(FrameSlot f) {
        if (f.underMarks == null || f.inspection == null) {
            return null;
        }
        int[] now = patch(f.frame.colour(), f.width(), f.height(), f.inspection.x(), f.inspection.y());
        int marked = 0;
        for (int k = 0; k < now.length; k++) {
            marked += now[k] != f.underMarks[k] ? 1 : 0;
        }
        boolean centre = now[now.length / 2] != f.underMarks[now.length / 2];
        return marked == 0 ? null : String.format(Locale.ROOT, "magnifier: %d px marked over the image%s "
                + "(outlines, hover tint); the numbers are of the image", marked, centre ? ", this one too" : "");
    }

    /** A pinned pixel's one-line readout, numbered from 1 as its marker in the view. */
    static String pinLine(int number, PixelInspector.Inspection in) {
        String what = in.triangle() < 0 ? "background" : triangleOf(in.owner(), in.triangle())
                + (Double.isNaN(in.displacement()) ? ", displacement undefined"
                : String.format(Locale.ROOT, ", exact displacement %.4f px", in.displacement()));
        return String.format(Locale.ROOT, "#%d %d,%d #%06X %s", number, in.x(), in.y(), in.argb() & 0xFFFFFF, what);
    }

    /**
     * The pinned pixels: a numbered square on each, and their readouts, read afresh each frame, in a box
     * at the view's bottom right.
     */
    static void paintPins(Graphics2D g, FrameSlot f, int viewW, int viewH) {
        if (f.pins.length == 0) {
            return;
        }
        double sx = (double) viewW / f.width();
        double sy = (double) viewH / f.height();
        g.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        int lineH = g.getFontMetrics().getHeight();
        int textW = 0;
        for (int k = 0; k < f.pins.length; k++) {
            PixelInspector.Inspection in = f.pins[k];
            int px = (int) Math.round((in.x() + 0.5) * sx);
            int py = (int) Math.round((in.y() + 0.5) * sy);
            g.setColor(new Color(0, 0, 0, 170));
            g.fillRect(px - 5, py - 5, 11, 11);
            g.setColor(Color.ORANGE);
            g.drawRect(px - 4, py - 4, 8, 8);
            g.drawString(Integer.toString(k + 1), px + 8, py - 6);
            textW = Math.max(textW, g.getFontMetrics().stringWidth(pinLine(k + 1, in)));
        }
        int h = f.pins.length * lineH + 8;
        int x = viewW - textW - 12 - MARGIN;
        int y = viewH - h - MARGIN;
        g.setColor(new Color(0, 0, 0, 170));
        g.fillRect(x, y, textW + 12, h);
        g.setColor(Color.WHITE);
        for (int k = 0; k < f.pins.length; k++) {
            g.drawString(pinLine(k + 1, f.pins[k]), x + 6, y + 4 + (k + 1) * lineH - 3);
        }
    }

    /** The readout as text, one line each, for the clipboard. */
    static String text(PixelInspector.Inspection in) {
        return String.join(System.lineSeparator(), lines(in, false)) + System.lineSeparator();
    }

    /** Why a fallback piece is filled per pixel: a sliver, or a cap stopped its splitting. */
    static String perPixel(PieceInfo p) {
        return p.sliver() ? "filled per pixel: a sliver (thinner than 1/16 px)"
                : "filled per pixel: a cap stopped its splitting";
    }

    /**
     * In the span path, the knots of the inspected row of its triangle: a short tick at each, the two
     * of the pixel's segment taller and cyan, so the segment the pixel is interpolated on shows.
     */
    private static void paintKnots(Graphics2D g, PixelInspector.Inspection in, double sx, int py) {
        RowKnots knots = in.knots();
        if (knots == null) {
            return;
        }
        int k = in.segment();
        int[] columns = knots.columns();
        for (int pass = 0; pass < 2; pass++) {
            g.setStroke(new BasicStroke(pass == 0 ? 3 : 1));
            for (int n = 0; n < columns.length; n++) {
                boolean ends = n == k || n == k + 1;
                int kx = (int) Math.round((columns[n] + 0.5) * sx);
                int reach = ends ? 8 : 4;
                g.setColor(pass == 0 ? new Color(0, 0, 0, 160) : ends ? Color.CYAN : Color.WHITE);
                g.drawLine(kx, py - reach, kx, py + reach);
            }
        }
    }

    public static void paint(Graphics2D g, FrameSlot f, int viewW, int viewH, boolean pinned) {
        PixelInspector.Inspection in = f.inspection;
        double sx = (double) viewW / f.width();
        double sy = (double) viewH / f.height();
        int px = (int) Math.round((in.x() + 0.5) * sx);
        int py = (int) Math.round((in.y() + 0.5) * sy);
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_OFF);
        paintShapes(g, in, sx, sy);
        // Crosshair with a gap over the pixel itself, dark under light so it shows on any texture.
        for (int pass = 0; pass < 2; pass++) {
            g.setColor(pass == 0 ? new Color(0, 0, 0, 160) : Color.WHITE);
            g.setStroke(new BasicStroke(pass == 0 ? 3 : 1));
            int gap = 6;
            int arm = REACH - 2;
            g.drawLine(px - arm, py, px - gap, py);
            g.drawLine(px + gap, py, px + arm, py);
            g.drawLine(px, py - arm, px, py - gap);
            g.drawLine(px, py + gap, px, py + arm);
        }
        paintKnots(g, in, sx, py);
        List<String> lines = lines(in, pinned);
        String note = marksNote(f);
        if (note != null) {
            lines.add(note);
        }
        g.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        int lineH = g.getFontMetrics().getHeight();
        int textW = 0;
        for (String s : lines) {
            textW = Math.max(textW, g.getFontMetrics().stringWidth(s));
        }
        int magnifier = MAGNIFIED * (MAGNIFIER_SIZE / MAGNIFIED);
        textW = Math.max(textW, g.getFontMetrics().stringWidth(lines.get(0)) + 2 * lineH + 6);
        Rectangle panel = place(Math.max(magnifier + 2, textW + 12), magnifier + 2 + GAP + lines.size() * lineH + 8,
                px, py, viewW, viewH);
        // The magnifier on the panel's outer side, the numbers under it.
        boolean right = panel.x + panel.width / 2 > viewW / 2;
        int mx = right ? panel.x + panel.width - magnifier - 1 : panel.x + 1;
        paintMagnifier(g, f, in, mx, panel.y + 1);
        int by = panel.y + magnifier + 2 + GAP;
        g.setColor(new Color(0, 0, 0, 170));
        g.fillRect(panel.x, by, panel.width, lines.size() * lineH + 8);
        g.setColor(Color.WHITE);
        for (int k = 0; k < lines.size(); k++) {
            g.drawString(lines.get(k), panel.x + 6, by + 4 + (k + 1) * lineH - 3);
        }
        // Swatches of the two colours after the first line, this path's first.
        int sw = lineH - 5;
        int sxw = panel.x + 6 + g.getFontMetrics().stringWidth(lines.get(0)) + 6;
        int[] colours = in.refArgb() == 0 ? new int[] {in.argb()} : new int[] {in.argb(), in.refArgb()};
        for (int c = 0; c < colours.length; c++) {
            g.setColor(new Color(colours[c], false));
            g.fillRect(sxw + c * (sw + 3), by + 6, sw, sw);
            g.setColor(Color.WHITE);
            g.drawRect(sxw + c * (sw + 3), by + 6, sw, sw);
        }
    }

    /**
     * The inspected piece outlined in cyan and its input triangle dashed (both over a dark edge, so
     * that they show on any texture), in view pixels.
     */
    private static void paintShapes(Graphics2D g, PixelInspector.Inspection in, double sx, double sy) {
        double[][] shapes = {in.triangle2d(), in.piece() == null ? null : in.piece().screen()};
        for (int k = 0; k < 2; k++) {
            double[] c = shapes[k];
            if (c == null) {
                continue;
            }
            java.awt.geom.Path2D.Double path = new java.awt.geom.Path2D.Double();
            path.moveTo(c[0] * sx, c[1] * sy);
            for (int v = 2; v < c.length; v += 2) {
                path.lineTo(c[v] * sx, c[v + 1] * sy);
            }
            path.closePath();
            float[] dash = k == 0 ? new float[] {6, 4} : null;
            g.setColor(new Color(0, 0, 0, 150));
            g.setStroke(new BasicStroke(3, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, dash, 0));
            g.draw(path);
            g.setColor(k == 0 ? Color.WHITE : Color.CYAN);
            g.setStroke(new BasicStroke(1, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, dash, 0));
            g.draw(path);
        }
    }

    /**
     * The frame's own pixels around the inspected one, nearest-neighbour, at {@code (mx, my)} in the
     * view, a grid between them so that single pixels count, the inspected one framed in white.
     */
    private static void paintMagnifier(Graphics2D g, FrameSlot f, PixelInspector.Inspection in, int mx, int my) {
        int cell = MAGNIFIER_SIZE / MAGNIFIED;
        int[] argb = f.frame.colour();
        for (int j = 0; j < MAGNIFIED; j++) {
            for (int i = 0; i < MAGNIFIED; i++) {
                int x = in.x() + i - MAGNIFIED / 2;
                int y = in.y() + j - MAGNIFIED / 2;
                boolean inside = x >= 0 && y >= 0 && x < f.width() && y < f.height();
                g.setColor(inside ? new Color(argb[y * f.width() + x], false) : Color.DARK_GRAY);
                g.fillRect(mx + i * cell, my + j * cell, cell, cell);
            }
        }
        g.setColor(new Color(0, 0, 0, 70));
        for (int k = 1; k < MAGNIFIED; k++) {
            g.drawLine(mx + k * cell, my, mx + k * cell, my + MAGNIFIED * cell - 1);
            g.drawLine(mx, my + k * cell, mx + MAGNIFIED * cell - 1, my + k * cell);
        }
        g.setColor(Color.WHITE);
        g.drawRect(mx + MAGNIFIED / 2 * cell, my + MAGNIFIED / 2 * cell, cell, cell);
        g.drawRect(mx - 1, my - 1, MAGNIFIED * cell + 1, MAGNIFIED * cell + 1);
    }

    /**
     * Where the inspector's panel (magnifier and numbers), {@code w x h} view pixels, goes so that it
     * never covers the crosshair at {@code (px, py)}: the first corner of the view — top right, top
     * left, bottom right, bottom left — whose panel stays clear of the crosshair's reach; in a view
     * too small for any, the corner farthest from the pixel.
     */
    static Rectangle place(int w, int h, int px, int py, int viewW, int viewH) {
        Rectangle cross = new Rectangle(px - REACH, py - REACH, 2 * REACH + 1, 2 * REACH + 1);
        int left = MARGIN;
        int rightX = viewW - w - MARGIN;
        int top = MARGIN;
        int bottom = viewH - h - MARGIN;
        Rectangle[] corners = {new Rectangle(rightX, top, w, h), new Rectangle(left, top, w, h),
            new Rectangle(rightX, bottom, w, h), new Rectangle(left, bottom, w, h)};
        Rectangle far = corners[0];
        double farthest = -1;
        for (Rectangle c : corners) {
            if (!c.intersects(cross)) {
                return c;
            }
            double d = Math.hypot(c.getCenterX() - px, c.getCenterY() - py);
            if (d > farthest) {
                farthest = d;
                far = c;
            }
        }
        return far;
    }
}
