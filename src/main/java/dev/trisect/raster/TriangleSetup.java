package dev.trisect.raster;

import dev.trisect.tessellate.VertexLayout;

/**
 * One screen triangle set up for filling within a rectangle of the frame: what the span solver and
 * the pixel loops read. {@link #prepare} fills it from a triangle of a {@link ScreenTriangles}; the
 * fields are then read-only until the next {@code prepare}. One per thread, reused for every triangle.
 *
 * <p>Pixel (x, y) is the pixel whose centre is at (x + 0.5, y + 0.5) in pixels, row 0 at the top.
 */
final class TriangleSetup {
    private static final int ONE = FixedPoint.ONE;
    /** Texel coordinates below this magnitude fit 32.32 fixed point with room for stepping. */
    private static final double FIXED_POINT_LIMIT = 1 << 30;

    /** Rows [rowStart, rowEnd) whose centres the triangle's bounding box holds, within the rectangle. */
    int rowStart;
    int rowEnd;
    /** Columns [colStart, colEnd) likewise. */
    int colStart;
    int colEnd;
    /**
     * The triangle's own first column, before clipping to the rectangle: the anchor of fixed-point
     * stepping, so that a pixel's value never depends on the rectangle being filled.
     */
    int firstColumn;
    /**
     * Snapped corners in setup order (x0, y0, x1, y1, x2, y2), {@link FixedPoint} sub-pixel units,
     * reordered so that the signed area is positive (y down).
     */
    final long[] corners = new long[6];
    /**
     * Attribute planes over pixel centres, from the unsnapped corners: {@code planes[0]} is {@code 1/w}
     * (view-space units^-1), {@code planes[1 + k]} varying slot k of the triangles' {@link
     * VertexLayout} — divided by w when set up for a perspective fill (s/w, not
     * s: the pixel divides by the interpolated 1/w). The first {@link #planeCount} are set up.
     */
    final Plane[] planes = newPlanes();
    /** How many of {@link #planes} the last setup fitted: 1 + the layout's varyings. */
    int planeCount;
    /** {@code planes[0]}: 1/w. */
    final Plane qPlane = planes[0];
    /** {@code planes[1]}: varying 0, texel s (level-0 texels), or s/w. */
    final Plane sPlane = planes[1];
    /** {@code planes[2]}: varying 1, texel t, or t/w. */
    final Plane tPlane = planes[2];
    /** Whether the texel coordinates are small enough for 32.32 fixed point (|s|, |t| &lt; 2^30). */
    boolean fixedPointSafe;
    /**
     * Corner colours closer than this are one colour ({@link #constantColour}): 2^-24 of the [0, 1]
     * range, far below the 2^-16 steps the modulation takes the colour in.
     */
    static final double SAME_COLOUR = 0x1p-24;
    /**
     * Whether the last {@link #prepare} found the three corners' colour varyings (slots
     * {@link PixelState#COLOUR_SLOT}..+2) one colour, within {@link #SAME_COLOUR}: flat shading, a face lit
     * evenly, a colour carried through clipping. Then {@link #red16}, {@link #green16}, {@link #blue16}
     * hold it (corner 0's) and the colour planes are not fitted — only a {@link PixelState#CONSTANT} loop,
     * which reads no colour plane, fills such a triangle with a modulating material. Always true for a
     * layout carrying its colour in flat values ({@link PixelState#FLAT_COLOUR}); false for a layout
     * with no colour and after {@link #affinePlanes}.
     */
    boolean constantColour;
    /**
     * The triangle's one colour r, g, b in 16 fractional bits ({@link Modulate#f16}), where
     * {@link #constantColour}.
     */
    int red16;
    int green16;
    int blue16;
    /** The same colour as one number ({@link LitTextures#colourKey}), where {@link #constantColour}. */
    long colourKey;

    /**
     * Sets up triangle {@code tri} of {@code triangles} for filling pixels {@code [x0, x1) x [y0, y1)}:
     * bounds, corner order and attribute planes (a perspective fill's planes interpolate s/w and t/w).
     *
     * @return false when it covers no pixel centre there (or has no area): nothing else is set then
     */
    boolean prepare(ScreenTriangles triangles, int tri, boolean perspective, int x0, int y0, int x1, int y1) {
        int[] f = triangles.fixed();
        int o = tri * ScreenTriangles.FIXED_STRIDE;
        long ax = f[o];
        long ay = f[o + 1];
        long bx = f[o + 2];
        long by = f[o + 3];
        long cx = f[o + 4];
        long cy = f[o + 5];
        long area = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
        if (area == 0) {
            return false;
        }
        // Corner order after making the area positive: 0, i1, i2.
        int i1 = 1;
        int i2 = 2;
        if (area < 0) {
            long tx = bx;
            long ty = by;
            bx = cx;
            by = cy;
            cx = tx;
            cy = ty;
            i1 = 2;
            i2 = 1;
        }
        int minX = (int) Math.min(ax, Math.min(bx, cx));
        int maxX = (int) Math.max(ax, Math.max(bx, cx));
        int minY = (int) Math.min(ay, Math.min(by, cy));
        int maxY = (int) Math.max(ay, Math.max(by, cy));
        firstColumn = FixedPoint.firstCentre(minX);
        colStart = Math.max(x0, firstColumn);
        colEnd = Math.min(x1, FixedPoint.endCentre(maxX));
        rowStart = Math.max(y0, FixedPoint.firstCentre(minY));
        rowEnd = Math.min(y1, FixedPoint.endCentre(maxY));
        if (colStart >= colEnd || rowStart >= rowEnd) {
            return false;
        }
        long[] c = corners;
        c[0] = ax;
        c[1] = ay;
        c[2] = bx;
        c[3] = by;
        c[4] = cx;
        c[5] = cy;
        planes(triangles, tri, i1, i2, perspective, true);
        return true;
    }

    /**
     * Sets up only the affine attribute planes of triangle {@code tri} (its varyings, and
     * {@link #fixedPointSafe}), exactly as {@link #prepare} with {@code perspective} false sets them,
     * for fills that set up pieces in bulk ({@link SplitTrees}).
     *
     * @return false, with the planes unset, when the snapped corners enclose no area (then
     *         {@link #prepare} fills no pixel of it)
     */
    boolean affinePlanes(ScreenTriangles triangles, int tri) {
        int[] f = triangles.fixed();
        int o = tri * ScreenTriangles.FIXED_STRIDE;
        long ax = f[o];
        long ay = f[o + 1];
        long area = (f[o + 2] - ax) * (f[o + 5] - ay) - (f[o + 4] - ax) * (long) (f[o + 3] - ay);
        if (area == 0) {
            return false;
        }
        planes(triangles, tri, area < 0 ? 2 : 1, area < 0 ? 1 : 2, false, false);
        return true;
    }

    /**
     * Attribute planes from the unsnapped corners, so snapping moves coverage but never the mapping;
     * with {@code oneColour}, the colour planes of a triangle of one colour are left unfitted
     * ({@link #constantColour}).
     */
    private void planes(ScreenTriangles triangles, int tri, int i1, int i2, boolean perspective, boolean oneColour) {
        double[] sc = triangles.screen();
        double[] at = triangles.attributes();
        int s = tri * ScreenTriangles.SCREEN_STRIDE;
        int a = tri * triangles.attributeStride();
        double x0 = sc[s];
        double y0 = sc[s + 1];
        double ex1 = sc[s + 2 * i1] - x0;
        double ey1 = sc[s + 2 * i1 + 1] - y0;
        double ex2 = sc[s + 2 * i2] - x0;
        double ey2 = sc[s + 2 * i2 + 1] - y0;
        double det = ex1 * ey2 - ex2 * ey1;
        if (det == 0 || !Double.isFinite(det)) {
            // Snapping gave area to a triangle that had none: use the snapped corners instead.
            int[] f = triangles.fixed();
            int o = tri * ScreenTriangles.FIXED_STRIDE;
            x0 = f[o] / (double) ONE;
            y0 = f[o + 1] / (double) ONE;
            ex1 = f[o + 2 * i1] / (double) ONE - x0;
            ey1 = f[o + 2 * i1 + 1] / (double) ONE - y0;
            ex2 = f[o + 2 * i2] / (double) ONE - x0;
            ey2 = f[o + 2 * i2 + 1] / (double) ONE - y0;
            det = ex1 * ey2 - ex2 * ey1;
        }
        double inv = 1.0 / det;
        int cs = triangles.cornerStride();
        int c0 = a;
        int c1 = a + cs * i1;
        int c2 = a + cs * i2;
        double q0 = at[c0];
        double q1 = at[c1];
        double q2 = at[c2];
        double limit = FIXED_POINT_LIMIT;
        fixedPointSafe = Math.abs(at[c0 + 1]) < limit && Math.abs(at[c1 + 1]) < limit && Math.abs(at[c2 + 1]) < limit
                && Math.abs(at[c0 + 2]) < limit && Math.abs(at[c1 + 2]) < limit && Math.abs(at[c2 + 2]) < limit;
        qPlane.fit(x0, y0, ex1, ey1, ex2, ey2, inv, q0, q1, q2);
        planeCount = cs;
        constantColour = false;
        if (cs == 3) {
            // The textured layout (s, t alone), every frame but a lit one: two fits written out, with
            // no loop over a count the compiler does not know and no load of the plane from the array
            // (sphere160k, where setup weighs as much as the pixels, is 2-3 % faster so; docs/
            // performance/pixel-stage.md, "The pixel stage as templates, and attributes by layout").
            double s0 = at[c0 + 1];
            double s1 = at[c1 + 1];
            double s2 = at[c2 + 1];
            double t0 = at[c0 + 2];
            double t1 = at[c1 + 2];
            double t2 = at[c2 + 2];
            if (perspective) {
                sPlane.fit(x0, y0, ex1, ey1, ex2, ey2, inv, s0 * q0, s1 * q1, s2 * q2);
                tPlane.fit(x0, y0, ex1, ey1, ex2, ey2, inv, t0 * q0, t1 * q1, t2 * q2);
            } else {
                sPlane.fit(x0, y0, ex1, ey1, ex2, ey2, inv, s0, s1, s2);
                tPlane.fit(x0, y0, ex1, ey1, ex2, ey2, inv, t0, t1, t2);
            }
            int fs = triangles.layout().flats();
            if (oneColour && fs > PixelState.FLAT_COLOUR) {
                // A flat-lit frame's colour, once per triangle and packed (PixelState.flatColour): one
                // colour by construction, unpacked by shifts.
                long key = (long) at[a + triangles.flatOffset() + PixelState.FLAT_COLOUR];
                constantColour = true;
                colourKey = key;
                red16 = LitTextures.channel16(key, 0);
                green16 = LitTextures.channel16(key, 1);
                blue16 = LitTextures.channel16(key, 2);
            }
            return;
        }
        // The colour planes, skipped for a triangle of one colour (a flat-shaded sphere's thousands of
        // tiny triangles: three fits of five, and the check Rasterizer made after them).
        int skipFrom = 1 + PixelState.COLOUR_SLOT;
        int skipTo = skipFrom;
        if (oneColour && cs >= skipFrom + 3 && sameColour(at, c0, c1, c2, skipFrom)) {
            constantColour = true;
            red16 = Modulate.f16(at[c0 + skipFrom]);
            green16 = Modulate.f16(at[c0 + skipFrom + 1]);
            blue16 = Modulate.f16(at[c0 + skipFrom + 2]);
            colourKey = LitTextures.colourKey(red16, green16, blue16);
            skipTo = skipFrom + 3;
        }
        for (int k = 1; k < cs; k++) {
            if (k >= skipFrom && k < skipTo) {
                continue;
            }
            double v0 = at[c0 + k];
            double v1 = at[c1 + k];
            double v2 = at[c2 + k];
            if (perspective) {
                // Interpolate v/w; the pixel divides by the interpolated 1/w.
                v0 *= q0;
                v1 *= q1;
                v2 *= q2;
            }
            planes[k].fit(x0, y0, ex1, ey1, ex2, ey2, inv, v0, v1, v2);
        }
    }

    /** Whether corners {@code c1} and {@code c2} have corner {@code c0}'s three values from offset {@code k}, within {@link #SAME_COLOUR}. */
    private static boolean sameColour(double[] at, int c0, int c1, int c2, int k) {
        for (int j = k; j < k + 3; j++) {
            double v = at[c0 + j];
            if (Math.abs(at[c1 + j] - v) > SAME_COLOUR || Math.abs(at[c2 + j] - v) > SAME_COLOUR) {
                return false;
            }
        }
        return true;
    }

    private static Plane[] newPlanes() {
        Plane[] p = new Plane[1 + VertexLayout.MAX_VARYINGS];
        for (int k = 0; k < p.length; k++) {
            p[k] = new Plane();
        }
        return p;
    }
}
