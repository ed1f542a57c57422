package dev.trisect.tessellate;

/**
 * The tessellator's rule for slivers: pieces so thin that they are filled per pixel instead of
 * affinely (see {@link #SLIVER_PIXELS} for why).
 */
public final class Slivers {
    private Slivers() {
    }

    /**
     * Pieces with an altitude below this many pixels (and below an eighth of their longest edge) are
     * filled per pixel. Coverage uses corners snapped to 1/256 px, so a pixel centre up to about
     * 0.003 px outside a piece can be filled by it, its affine map extrapolated that far (since the
     * one-pass fill, only across the input triangle's own edges: inside, a pixel takes the piece its
     * centre lies in by the unsnapped split lines); across a sliver thinner than the snapping that
     * extrapolation is large and the bound can fail (measured: 0.125 px at max-error 0.1 with the 3D
     * midpoint on a plane to the horizon). At 1/16 px the reach outside is under 5 % of the piece's
     * thickness. Such pieces cover few pixels, so filling them per pixel costs next to nothing.
     */
    public static final double SLIVER_PIXELS = 1.0 / 16;

    /**
     * Whether a triangle with these screen corners (pixels) is a sliver, as the tessellator judges its
     * pieces: least altitude below {@link #SLIVER_PIXELS} and below an eighth of its longest edge.
     */
    public static boolean sliver(double x0, double y0, double x1, double y1, double x2, double y2) {
        double ex1 = x1 - x0;
        double ey1 = y1 - y0;
        double ex2 = x2 - x0;
        double ey2 = y2 - y0;
        double ex3 = x2 - x1;
        double ey3 = y2 - y1;
        double area2 = Math.abs(ex1 * ey2 - ex2 * ey1);
        double l2 = Math.max(ex1 * ex1 + ey1 * ey1, Math.max(ex2 * ex2 + ey2 * ey2, ex3 * ex3 + ey3 * ey3));
        // altitude = area2 / longest edge, compared squared to spare a square root: below the limit,
        // and below an eighth of the longest edge (a small piece of good shape is no sliver).
        double altitude2 = area2 * area2 / l2;
        return altitude2 < SLIVER_PIXELS * SLIVER_PIXELS && altitude2 * 64 < l2;
    }
}
