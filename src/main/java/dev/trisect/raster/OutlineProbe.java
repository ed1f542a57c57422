package dev.trisect.raster;

/**
 * Whether one screen triangle's outline lights one pixel, by the overlay's own rules (the line
 * rasterizer's {@link LineCrossing crossing rule} its edges are drawn by, and {@link BorderOverlay}'s
 * depth test), for the pixel inspector: one pixel and one triangle at a time, never per frame. The
 * overlay walks whole edges band by band; this asks the rule for one pixel ({@link LineCrossing#lights})
 * and restates the depth test — {@code FallbackOutlineLookupTest} holds the two to the same pixels on a
 * real frame.
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

    /** Whether an edge of {@code tri} lights (x, y) by the overlay's line rule ({@link LineCrossing#lights}). */
    private static boolean onEdge(int[] f, int tri, int x, int y) {
        int o = tri * ScreenTriangles.FIXED_STRIDE;
        for (int e = 0; e < 3; e++) {
            int a = o + 2 * e;
            int b = o + (e == 2 ? 0 : 2 * e + 2);
            if (LineCrossing.lights(f[a], f[a + 1], f[b], f[b + 1], x, y)) {
                return true;
            }
        }
        return false;
    }

    /** The outline's 1/w at pixel (x, y) as the overlay tests it; -infinity for a triangle without area (not outlined). */
    private static double depthAt(ScreenTriangles t, int tri, int x, int y) {
        Plane plane = new Plane();
        if (!OutlinePlan.depthPlane(t, tri, new double[ScreenTriangles.EDGES], plane)) {
            return Double.NEGATIVE_INFINITY;
        }
        double[] at = t.attributes();
        int a = tri * t.attributeStride();
        int cs = t.cornerStride();
        double q = plane.base + plane.dx * x + plane.dy * y;
        if (t.perPixel()[tri]) {
            q = Math.max(Math.min(at[a], Math.min(at[a + cs], at[a + 2 * cs])),
                    Math.min(Math.max(at[a], Math.max(at[a + cs], at[a + 2 * cs])), q));
        }
        return q;
    }
}
