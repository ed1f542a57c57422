package dev.trisect.tessellate;

import dev.trisect.math.Viewport;
import java.util.ArrayList;
import java.util.List;

/** Test support: builds tessellator input from screen positions and collects the pieces. */
final class Pieces implements PieceSink {
    /** Each piece: 3 vertices of {@link Tessellator#STRIDE} doubles, copied. */
    final List<double[]> pieces = new ArrayList<>();
    /** Whether each piece was flagged for the per-pixel fallback. */
    final List<Boolean> fallback = new ArrayList<>();

    @Override
    public void piece(double[] v, int a, int b, int c, boolean perPixel) {
        fallback.add(perPixel);
        double[] p = new double[3 * Tessellator.STRIDE];
        System.arraycopy(v, a, p, 0, Tessellator.STRIDE);
        System.arraycopy(v, b, p, Tessellator.STRIDE, Tessellator.STRIDE);
        System.arraycopy(v, c, p, 2 * Tessellator.STRIDE, Tessellator.STRIDE);
        pieces.add(p);
    }

    /**
     * One input vertex whose projection lands at screen (sx, sy) at view depth w, with texel
     * coordinates (s, t): clip x and y are chosen so that x/w and y/w map to (sx, sy).
     */
    static double[] vertex(Viewport vp, double sx, double sy, double w, double s, double t) {
        double ndcX = 2 * sx / vp.width() - 1;
        double ndcY = 1 - 2 * sy / vp.height();
        return new double[] {ndcX * w, ndcY * w, 0.5 * w, w, s, t};
    }

    /** Three input vertices in one array, offsets 0, 6, 12. */
    static double[] triangle(double[] a, double[] b, double[] c) {
        double[] t = new double[3 * Tessellator.INPUT_STRIDE];
        System.arraycopy(a, 0, t, 0, 6);
        System.arraycopy(b, 0, t, 6, 6);
        System.arraycopy(c, 0, t, 12, 6);
        return t;
    }

    /** Twice the signed screen area of piece p (from the screen x, y of its vertices). */
    static double area2(double[] p) {
        int s = Tessellator.STRIDE;
        double x0 = p[6];
        double y0 = p[7];
        return (p[s + 6] - x0) * (p[2 * s + 7] - y0) - (p[2 * s + 6] - x0) * (p[s + 7] - y0);
    }
}
