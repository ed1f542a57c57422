package dev.trisect.raster;

/**
 * Whether one screen triangle's outline lights one pixel, by the overlay's own rules (the edge walk of
 * {@link OutlinePlan} and {@link BorderOverlay}, the same arithmetic, and its depth test), for the
 * pixel inspector: one pixel and one triangle at a time, never per frame. The overlay walks whole edges
 * band by band; this answers for one pixel, so it restates the rule rather than sharing the walk —
 * {@code FallbackOutlineLookupTest} holds the two to the same pixels on a real frame.
 */
public final class OutlineProbe {
    private OutlineProbe() {
    }

    /**
     * Whether triangle {@code tri}'s outline lights pixel (x, y) of a frame {@code height} rows high
     * whose depth buffer holds 1/w = {@code depth} there: the triangle is outlined (it covers a pixel
     * centre's row of the frame, has an area), one of its edges passes through the pixel as the overlay
     * walks it, and its 1/w there is not behind {@code depth} (held to its corners' range when it is
     * filled per pixel, see {@link OutlinePlan#looks}).
     */
    public static boolean lights(ScreenTriangles t, int tri, int x, int y, int height, double depth) {
        if (y < 0 || y >= height || Math.max(0, t.firstRow(tri)) >= Math.min(height, t.endRow(tri))) {
            return false;
        }
        return onEdge(t.fixed(), tri, x, y) && !(depthAt(t, tri, x, y) < depth * (1 - BorderOverlay.DEPTH_TOLERANCE));
    }

    /** Whether an edge of {@code tri}, walked as {@link OutlinePlan} lists and {@link BorderOverlay} walks it, lights (x, y). */
    private static boolean onEdge(int[] f, int tri, int x, int y) {
        int o = tri * ScreenTriangles.FIXED_STRIDE;
        for (int e = 0; e < 3; e++) {
            int a = o + 2 * e;
            int b = o + (e == 2 ? 0 : 2 * e + 2);
            // From the smaller (x, y) end, as the overlay walks every edge.
            boolean flip = f[a] > f[b] || f[a] == f[b] && f[a + 1] > f[b + 1];
            int from = flip ? b : a;
            int to = flip ? a : b;
            double xa = f[from] / (double) FixedPoint.ONE;
            double ya = f[from + 1] / (double) FixedPoint.ONE;
            double xb = f[to] / (double) FixedPoint.ONE;
            double yb = f[to + 1] / (double) FixedPoint.ONE;
            double dx = xb - xa;
            double dy = yb - ya;
            if (Math.abs(dx) >= Math.abs(dy)) {
                if (dx != 0 && x >= Math.ceil(xa - 0.5) && x <= Math.floor(xb - 0.5)
                        && Math.floor(ya + (x + 0.5 - xa) * (dy / dx)) == y) {
                    return true;
                }
            } else if (y >= Math.ceil(Math.min(ya, yb) - 0.5) && y <= Math.floor(Math.max(ya, yb) - 0.5)
                    && Math.floor(xa + (y + 0.5 - ya) * (dx / dy)) == x) {
                return true;
            }
        }
        return false;
    }

    /** The outline's 1/w at pixel (x, y) as the overlay tests it; -infinity for a triangle without area (not outlined). */
    private static double depthAt(ScreenTriangles t, int tri, int x, int y) {
        double[] sc = t.screen();
        double[] at = t.attributes();
        int s = tri * ScreenTriangles.SCREEN_STRIDE;
        int a = tri * t.attributeStride();
        int cs = t.cornerStride();
        double x0 = sc[s];
        double y0 = sc[s + 1];
        double ex1 = sc[s + 2] - x0;
        double ey1 = sc[s + 3] - y0;
        double ex2 = sc[s + 4] - x0;
        double ey2 = sc[s + 5] - y0;
        double det = ex1 * ey2 - ex2 * ey1;
        if (det == 0 || !Double.isFinite(det)) {
            return Double.NEGATIVE_INFINITY;
        }
        Plane plane = new Plane();
        plane.fit(x0, y0, ex1, ey1, ex2, ey2, 1 / det, at[a], at[a + cs], at[a + 2 * cs]);
        double q = plane.base + plane.dx * x + plane.dy * y;
        if (t.perPixel()[tri]) {
            q = Math.max(Math.min(at[a], Math.min(at[a + cs], at[a + 2 * cs])),
                    Math.min(Math.max(at[a], Math.max(at[a + cs], at[a + 2 * cs])), q));
        }
        return q;
    }
}
