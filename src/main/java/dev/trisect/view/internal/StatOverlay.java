package dev.trisect.view.internal;

import dev.trisect.render.FrameStats;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.TessellationSettings;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.util.List;
import java.util.Locale;

/**
 * The in-view statistics overlay (U), as a game engine's {@code stat unit}: frames per second, the frame's
 * milliseconds split into geometry (transform and clip), tessellation, fill and overlay, and what the rest
 * of the whole frame went to; pieces and fallback pieces; the path, split policy, threshold and filter the
 * frame was drawn with. Every number is the frame on screen's own, so each can be checked against the
 * others and against the developer tools. Painted over the view's top-left corner. Event thread only.
 */
final class StatOverlay {
    private StatOverlay() {
    }

    /**
     * The overlay's lines for the frame {@code front} at {@code fps} frames per second (the status bar's
     * rate; 0 before the first whole second).
     */
    static List<String> lines(FrameSlot front, double fps) {
        FrameStats st = front.stats;
        RenderSettings r = front.drawnRender;
        double geometry = (st.transformNanos() + st.clipNanos()) / 1e6;
        double tessellation = st.tessellateNanos() / 1e6;
        double fill = st.rasterNanos() / 1e6;
        double overlay = (st.overlayNanos() + front.overlayNanos) / 1e6;
        double engine = geometry + tessellation + fill + overlay;
        double whole = fps > 0 ? 1000 / fps : Double.NaN;
        String frame = Double.isNaN(whole) ? String.format(Locale.ROOT, "frame  %.1f ms in the engine", engine)
                : String.format(Locale.ROOT, "%.1f fps  frame %.1f ms = engine %.1f + other %.1f (tools, presenting)", fps,
                whole, engine, Math.max(0, whole - engine));
        String split = String.format(Locale.ROOT, "geometry %.1f  tessellation %s  fill %.1f  overlay %.1f ms",
                geometry, r.mode().splits() ? String.format(Locale.ROOT, "%.1f", tessellation) : "-", fill, overlay);
        String pieces = String.format(Locale.ROOT, "pieces %,d  fallback %,d (filled per pixel)", st.pieces(),
                st.piecesFallback());
        return List.of(frame, split, pieces, how(r));
    }

    /** The path, policy, threshold and filter of {@code r}. */
    static String how(RenderSettings r) {
        TessellationSettings t = r.tessellation();
        String policy = r.mode().splits() ? String.format(Locale.ROOT, "  policy %s  threshold %.3g px", t.policy().id(),
                t.policy().threshold(t)) : r.mode().knots() ? String.format(Locale.ROOT, "  knot error %.3g px",
                r.knotError()) : "";
        return "path " + r.mode().id() + policy + "  filter " + r.filter().id();
    }

    /** Paints the overlay in the view's top-left corner. */
    static void paint(Graphics2D g, FrameSlot front, double fps) {
        if (front == null || front.stats == null || front.drawnRender == null) {
            return;
        }
        List<String> lines = lines(front, fps);
        g.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 13));
        FontMetrics fm = g.getFontMetrics();
        int width = 0;
        for (String l : lines) {
            width = Math.max(width, fm.stringWidth(l));
        }
        int x = 10;
        int y = 10;
        int line = fm.getHeight();
        g.setColor(new Color(0, 0, 0, 170));
        g.fillRoundRect(x - 6, y - 4, width + 12, line * lines.size() + 8, 8, 8);
        g.setColor(Color.WHITE);
        for (int i = 0; i < lines.size(); i++) {
            g.drawString(lines.get(i), x, y + fm.getAscent() + i * line);
        }
    }
}
