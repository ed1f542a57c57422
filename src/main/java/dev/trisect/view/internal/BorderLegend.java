package dev.trisect.view.internal;

import dev.trisect.raster.OverlayColours;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import java.awt.Color;
import java.awt.Graphics2D;
import java.util.List;
import java.util.Locale;
import java.util.function.DoubleToIntFunction;

/**
 * The border overlay's legend, bottom left of the view: what the outline colours mean. Its content
 * ({@link #of}) is kept apart from its painting so that a test can read what it says. The tessellated
 * path's overlay outlines pieces, filled affinely or (magenta) per pixel; the span path fills no pieces
 * and its overlay outlines triangles and ticks their knots (docs/conventions.md, "Border overlay
 * colours"), so its legend names those instead and has no magenta entry; the per-pixel and affine
 * paths outline whole triangles, and say how they are filled.
 *
 * @param ramp     the bar's colour (ARGB) at a fraction 0..1 of its width, or null for no bar
 * @param left     the label under the bar's left end
 * @param right    the label under the bar's right end
 * @param swatches the lines under the bar, each a colour square and its words
 */
record BorderLegend(DoubleToIntFunction ramp, String left, String right, List<Swatch> swatches) {
    /** A line of the legend: a square of {@code colour} (ARGB) and what outlines of that colour are. */
    record Swatch(int colour, String text) {
    }

    /** Width of the bar, logical pixels. */
    private static final int BAR_WIDTH = 220;

    /**
     * The legend for outlines drawn with {@code r}.
     *
     * @param fallback the frame's pieces filled per pixel (outlined in magenta); with none the legend has no
     *                 magenta entry
     */
    static BorderLegend of(RenderSettings r, long fallback) {
        BorderStyle.Colouring colouring = r.borderStyle().colouring();
        int maxLevel = r.tessellation().maxDepth();
        if (r.borderStyle().onlyFallback()) {
            // Only the fallback pieces are outlined, and only the tessellated path has any.
            return new BorderLegend(null, null, null, r.mode().splits()
                    ? List.of(new Swatch(OverlayColours.FALLBACK, fallbackNote(fallback))) : List.of());
        }
        if (r.mode().knots()) {
            return switch (colouring) {
                case YELLOW -> new BorderLegend(null, null, null, List.of(new Swatch(OverlayColours.PIECE,
                        "triangle outline; ticks: its knots, on one row in 16")));
                // Nothing is split in this path: every outline and tick has level 0's colour.
                case DEPTH -> new BorderLegend(null, null, null, List.of(new Swatch(OverlayColours.depth(0, maxLevel),
                        "triangle outline and knot ticks: level 0 (nothing is split)")));
                // A segment's bound never exceeds Max error (the knots are spaced so), so the bar ends there.
                case BOUND -> new BorderLegend(OverlayColours::bound, "knot tick: bound 0", "at max error",
                        List.of(new Swatch(OverlayColours.PIECE, "triangle outline")));
            };
        }
        if (!r.mode().splits()) {
            // The per-pixel and affine paths split nothing and have no fallback: whole triangles, level 0.
            String filled = r.mode() == RenderMode.AFFINE ? "filled affinely" : "filled per pixel, perspective-correct";
            return switch (colouring) {
                case YELLOW -> new BorderLegend(null, null, null,
                        List.of(new Swatch(OverlayColours.PIECE, "triangle outline (" + filled + ")")));
                case DEPTH -> new BorderLegend(null, null, null, List.of(new Swatch(OverlayColours.depth(0, maxLevel),
                        "triangle outline: level 0 (nothing is split)")));
                // The bound is what filling the triangle affinely would be off by, whatever this path does.
                case BOUND -> new BorderLegend(f -> OverlayColours.bound(f * 1.25), "affine bound 0",
                        "\u2265 1.25\u00d7 max error", List.of());
            };
        }
        // A magenta entry only when the frame has magenta outlines (a cube seen whole has none).
        List<Swatch> perPixel = fallback > 0 ? List.of(new Swatch(OverlayColours.FALLBACK, fallbackNote(fallback)))
                : List.of();
        return switch (colouring) {
            case YELLOW -> new BorderLegend(null, null, null, concat(
                    new Swatch(OverlayColours.PIECE, "piece outline (filled affinely)"), perPixel));
            case DEPTH -> new BorderLegend(f -> OverlayColours.depth((int) Math.round(f * maxLevel), maxLevel),
                    "level 0", "level " + maxLevel + " (cap)", perPixel);
            // The scale is Max error whatever the policy: say which value, and that Edge does not hold it.
            case BOUND -> new BorderLegend(f -> OverlayColours.bound(f * 1.25), "bound 0",
                    "\u2265 1.25\u00d7 max error", concat(new Swatch(OverlayColours.bound(1), boundScale(r)),
                    perPixel));
        };
    }

    private static List<Swatch> concat(Swatch first, List<Swatch> rest) {
        List<Swatch> all = new java.util.ArrayList<>(rest.size() + 1);
        all.add(first);
        all.addAll(rest);
        return List.copyOf(all);
    }

    /**
     * Where the error-bound colouring's scale comes from: Max error, which the Error policy holds and
     * the Edge policy does not (there the colours show how far a piece's bound is from a value nothing
     * enforces, and red can appear).
     */
    static String boundScale(RenderSettings r) {
        String px = String.format(Locale.ROOT, "%.3g px", r.tessellation().maxError());
        return r.tessellation().policy().measuresError()
                ? "yellow at Max error, " + px + " (the Error policy holds it)"
                : "yellow at Max error, " + px + " (Split policy section; Edge does not hold it: red above)";
    }

    /**
     * What the magenta outlines are: the fallback pieces and why they are filled per pixel ({@code pieces}
     * of them, or an unknown number when 0: only the fallback-only overlay asks for that).
     */
    static String fallbackNote(long pieces) {
        return pieces > 0 ? String.format(Locale.ROOT, "%d piece%s filled per pixel (slivers, or a cap reached)",
                pieces, pieces == 1 ? "" : "s") : "filled per pixel (a sliver, or a cap reached)";
    }

    /** Paints the legend into the bottom-left corner of a view {@code h} logical pixels high. */
    void paint(Graphics2D g, int h) {
        if (ramp == null && swatches.isEmpty()) {
            return;
        }
        g.setFont(g.getFont().deriveFont(11f));
        java.awt.FontMetrics fm = g.getFontMetrics();
        int x = 14;
        // The bar and its labels take 32 px; each swatch line 16.
        int top = ramp != null ? 32 : 2;
        int boxH = top + 16 * swatches.size() + (ramp != null ? 12 : 8);
        int y = h - boxH - 2;
        int widest = BAR_WIDTH;
        for (Swatch s : swatches) {
            widest = Math.max(widest, 18 + fm.stringWidth(s.text()));
        }
        g.setColor(new Color(0, 0, 0, 160));
        g.fillRoundRect(x - 8, y - 8, widest + 16, boxH, 10, 10);
        if (ramp != null) {
            for (int i = 0; i < BAR_WIDTH; i++) {
                g.setColor(new Color(ramp.applyAsInt((double) i / (BAR_WIDTH - 1)), false));
                g.fillRect(x + i, y, 1, 12);
            }
            g.setColor(Color.WHITE);
            g.drawString(left, x, y + 25);
            g.drawString(right, x + BAR_WIDTH - fm.stringWidth(right), y + 25);
        }
        for (int i = 0; i < swatches.size(); i++) {
            int sy = y + top + 16 * i;
            g.setColor(new Color(swatches.get(i).colour(), false));
            g.fillRect(x, sy, 12, 10);
            g.setColor(Color.WHITE);
            g.drawString(swatches.get(i).text(), x + 18, sy + 9);
        }
    }
}
