package dev.trisect.view.internal;

import dev.trisect.pipeline.PieceInfo;
import dev.trisect.raster.RowKnots;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** Draws the pixel inspector in the view: a crosshair on the pixel, a magnifier, and its numbers. */
public final class InspectorPainter {
    /** Frame pixels across the magnifier, and its size on screen. */
    static final int MAGNIFIED = 15;
    static final int MAGNIFIER_SIZE = 165;

    private InspectorPainter() {
    }

    /** The inspector's readout lines for an inspection (also what tests check). */
    static List<String> lines(PixelInspector.Inspection in, boolean pinned) {
        List<String> l = new ArrayList<>();
        l.add(String.format(Locale.ROOT, "pixel %d,%d %s #%06X", in.x(), in.y(), pinned ? "(pinned)" : "",
                in.argb() & 0xFFFFFF));
        PieceInfo mark = in.outline();
        if (mark != null) {
            // The magenta mark on the pixel belongs to this piece, which may not be the pixel's own.
            l.add("magenta outline: piece " + mark.index() + " of triangle " + mark.triangle() + ", " + perPixel(mark));
        }
        if (in.triangle() < 0) {
            l.add("background: nothing drawn");
            return l;
        }
        PieceInfo p = in.piece();
        l.add("triangle " + in.triangle() + (p == null ? "" : ", piece " + p.index() + ", split level " + p.level()
                + (p.fallback() ? ", " + perPixel(p) : "")));
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
        l.add(String.format(Locale.ROOT, "mip level %d (lambda %.2f%s), texel %d,%d", in.mipLevel(), in.lambda(),
                in.segment() >= 0 ? " of the segment" : "", in.texelX(), in.texelY()));
        return l;
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
        // Crosshair with a gap over the pixel itself, dark under light so it shows on any texture.
        for (int pass = 0; pass < 2; pass++) {
            g.setColor(pass == 0 ? new Color(0, 0, 0, 160) : Color.WHITE);
            g.setStroke(new BasicStroke(pass == 0 ? 3 : 1));
            int gap = 6;
            g.drawLine(px - 24, py, px - gap, py);
            g.drawLine(px + gap, py, px + 24, py);
            g.drawLine(px, py - 24, px, py - gap);
            g.drawLine(px, py + gap, px, py + 24);
        }
        paintKnots(g, in, sx, py);
        // Magnifier, top right: the frame's own pixels around the inspected one, nearest-neighbour.
        int mx = viewW - MAGNIFIER_SIZE - 12;
        int my = 12;
        int cell = MAGNIFIER_SIZE / MAGNIFIED;
        int[] argb = f.frame.color();
        for (int j = 0; j < MAGNIFIED; j++) {
            for (int i = 0; i < MAGNIFIED; i++) {
                int x = in.x() + i - MAGNIFIED / 2;
                int y = in.y() + j - MAGNIFIED / 2;
                boolean inside = x >= 0 && y >= 0 && x < f.width() && y < f.height();
                g.setColor(inside ? new Color(argb[y * f.width() + x], false) : Color.DARK_GRAY);
                g.fillRect(mx + i * cell, my + j * cell, cell, cell);
            }
        }
        g.setColor(Color.WHITE);
        g.drawRect(mx + MAGNIFIED / 2 * cell, my + MAGNIFIED / 2 * cell, cell - 1, cell - 1);
        g.drawRect(mx - 1, my - 1, MAGNIFIED * cell + 1, MAGNIFIED * cell + 1);
        // Numbers under the magnifier.
        List<String> lines = lines(in, pinned);
        g.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        int lineH = g.getFontMetrics().getHeight();
        int boxW = 0;
        for (String s : lines) {
            boxW = Math.max(boxW, g.getFontMetrics().stringWidth(s));
        }
        int bx = viewW - boxW - 20;
        int by = my + MAGNIFIED * cell + 10;
        g.setColor(new Color(0, 0, 0, 170));
        g.fillRect(bx - 6, by - 4, boxW + 12, lines.size() * lineH + 8);
        g.setColor(Color.WHITE);
        for (int k = 0; k < lines.size(); k++) {
            g.drawString(lines.get(k), bx, by + (k + 1) * lineH - 3);
        }
    }
}
