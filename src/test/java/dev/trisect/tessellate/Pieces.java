package dev.trisect.tessellate;

import dev.trisect.math.Viewport;
import java.util.ArrayList;
import java.util.List;

/** Test support: builds tessellator input from screen positions and collects the pieces. */
final class Pieces implements PieceSink {
    private static final int STRIDE = VertexLayout.PROJECTED_STRIDE;
    /** Each piece: 3 vertices of {@link VertexLayout#PROJECTED_STRIDE} doubles, copied. */
    final List<double[]> pieces = new ArrayList<>();
    /** Whether each piece was flagged for the per-pixel fallback. */
    final List<Boolean> fallback = new ArrayList<>();
    /** The split level handed on with each piece. */
    final List<Integer> levels = new ArrayList<>();

    /** The links handed on with each piece, copied. */
    final List<int[]> links = new ArrayList<>();

    @Override
    public void piece(double[] v, int a, int b, int c, int level, boolean perPixel, int[] edgeLinks) {
        links.add(edgeLinks.clone());
        fallback.add(perPixel);
        levels.add(level);
        double[] p = new double[3 * STRIDE];
        System.arraycopy(v, a, p, 0, STRIDE);
        System.arraycopy(v, b, p, STRIDE, STRIDE);
        System.arraycopy(v, c, p, 2 * STRIDE, STRIDE);
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
        int n = VertexLayout.CLIP_STRIDE;
        double[] t = new double[3 * n];
        System.arraycopy(a, 0, t, 0, n);
        System.arraycopy(b, 0, t, n, n);
        System.arraycopy(c, 0, t, 2 * n, n);
        return t;
    }

    /** Twice the signed screen area of piece p (from the screen x, y of its vertices). */
    static double area2(double[] p) {
        int s = STRIDE;
        int x = VertexLayout.SCREEN_X;
        int y = VertexLayout.SCREEN_Y;
        double x0 = p[x];
        double y0 = p[y];
        return (p[s + x] - x0) * (p[2 * s + y] - y0) - (p[2 * s + x] - x0) * (p[s + y] - y0);
    }
}
