package dev.trisect.raster;

import dev.trisect.texture.Texture;

/**
 * Fills screen-space triangles into a {@link Framebuffer}, restricted to a rectangle of the frame.
 *
 * <p>Coverage is exact integer arithmetic on snapped corners: a pixel belongs to a triangle when its
 * centre is inside, and a centre exactly on an edge goes to the triangle for which that edge is a top
 * or a left edge (image coordinates, y down). Each row's covered span is solved from the three edge
 * functions directly instead of testing every pixel of the bounding box; the division is estimated in
 * floating point and then corrected with the exact integer test, so the span is exactly the set of
 * centres that a per-pixel test would accept.
 *
 * <p>Because every decision is a function of the triangle and the pixel alone, filling the frame in
 * bands or tiles — on any number of threads — gives the same pixels as filling it whole, provided
 * each pixel sees its triangles in the same order.
 *
 * <p>One instance per thread: it keeps the current triangle's setup in fields. Nothing is allocated
 * per triangle or per pixel.
 */
public final class Rasterizer {
    private static final int ONE = FixedPoint.ONE;
    private static final int HALF = FixedPoint.HALF;

    // Current triangle, corners reordered so that the snapped signed area is positive (y down).
    private int rowStart;
    private int rowEnd;
    private int colStart;
    private int colEnd;
    // Edge k runs from corner k to corner k+1. Inside when K - m * x > 0 on the current row,
    // m = ONE * dY; K advances by ONE * dX per row.
    private long k0;
    private long k1;
    private long k2;
    private long m0;
    private long m1;
    private long m2;
    private long step0;
    private long step1;
    private long step2;
    private double inv0;
    private double inv1;
    private double inv2;
    // Attribute planes over pixel centres: value = base + dx * x + dy * y for pixel (x, y).
    private double qBase;
    private double qDx;
    private double qDy;
    private double sBase;
    private double sDx;
    private double sDy;
    private double tBase;
    private double tDx;
    private double tDy;

    /**
     * Fills triangles {@code order[from..to)} of {@code triangles}, in that order, into the pixels
     * {@code [x0, x1) x [y0, y1)} of the frame.
     *
     * @param perspective true: u/w, v/w and 1/w interpolate linearly on screen and every pixel
     *                    divides; false: u and v interpolate linearly on screen (affine)
     * @param textures    texture of each material index
     * @return the number of pixels written (depth test passed)
     */
    public long fill(Framebuffer frame, ScreenTriangles triangles, int[] order, int from, int to,
                     Texture[] textures, boolean perspective, int x0, int y0, int x1, int y1) {
        long written = 0;
        int[] materials = triangles.materials();
        int[] ids = triangles.ids();
        for (int n = from; n < to; n++) {
            int tri = order[n];
            if (!setup(triangles, tri, perspective, x0, y0, x1, y1)) {
                continue;
            }
            Texture texture = textures[materials[tri]];
            written += spans(frame, texture, ids[tri] + 1, perspective);
        }
        return written;
    }

    /**
     * Adds 1 to {@code counts[y * width + x]} for every pixel of {@code [x0, x1) x [y0, y1)} whose
     * centre each of triangles {@code order[from..to)} covers, with exactly the coverage rule of
     * {@link #fill}, ignoring depth. For checking that pieces tile without gaps or overlaps, and for
     * showing overdraw.
     *
     * @return the number of coverings counted
     */
    public long countCoverage(int[] counts, int width, ScreenTriangles triangles, int[] order, int from, int to,
                              int x0, int y0, int x1, int y1) {
        long covered = 0;
        for (int n = from; n < to; n++) {
            if (!setup(triangles, order[n], false, x0, y0, x1, y1)) {
                continue;
            }
            for (int y = rowStart; y < rowEnd; y++, nextRow()) {
                if (span()) {
                    int row = y * width;
                    for (int x = spanStart; x < spanEnd; x++) {
                        counts[row + x]++;
                    }
                    covered += spanEnd - spanStart;
                }
            }
        }
        return covered;
    }

    /**
     * Prepares triangle {@code tri} for filling within the rectangle; false when it covers no pixel
     * centre there (or has no area).
     */
    boolean setup(ScreenTriangles triangles, int tri, boolean perspective, int x0, int y0, int x1, int y1) {
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
        colStart = Math.max(x0, ScreenTriangles.ceilDiv(minX - HALF, ONE));
        colEnd = Math.min(x1, Math.floorDiv(maxX - HALF, ONE) + 1);
        rowStart = Math.max(y0, ScreenTriangles.ceilDiv(minY - HALF, ONE));
        rowEnd = Math.min(y1, Math.floorDiv(maxY - HALF, ONE) + 1);
        if (colStart >= colEnd || rowStart >= rowEnd) {
            return false;
        }
        long py = (long) rowStart * ONE + HALF;
        k0 = edgeK(ax, ay, bx, by, py);
        k1 = edgeK(bx, by, cx, cy, py);
        k2 = edgeK(cx, cy, ax, ay, py);
        m0 = ONE * (by - ay);
        m1 = ONE * (cy - by);
        m2 = ONE * (ay - cy);
        step0 = ONE * (bx - ax);
        step1 = ONE * (cx - bx);
        step2 = ONE * (ax - cx);
        inv0 = m0 == 0 ? 0 : 1.0 / m0;
        inv1 = m1 == 0 ? 0 : 1.0 / m1;
        inv2 = m2 == 0 ? 0 : 1.0 / m2;
        planes(triangles, tri, i1, i2, perspective);
        return true;
    }

    /**
     * The constant part K of edge a-&gt;b's function on the row with centre {@code py}, so that a pixel
     * x is inside the edge when {@code K - ONE * (by - ay) * x > 0}. Includes the top-left bias: a
     * centre exactly on a top edge (horizontal, interior below) or a left edge (going up) counts as
     * inside, which for integers means adding 1.
     */
    private static long edgeK(long ax, long ay, long bx, long by, long py) {
        long dx = bx - ax;
        long dy = by - ay;
        long bias = (dy < 0 || (dy == 0 && dx > 0)) ? 1 : 0;
        // E(P) = dx * (Py - ay) - dy * (Px - ax) with Px = ONE * x + HALF.
        return dx * (py - ay) - dy * (HALF - ax) + bias;
    }

    /** Attribute planes from the unsnapped corners, so snapping moves coverage but never the mapping. */
    private void planes(ScreenTriangles triangles, int tri, int i1, int i2, boolean perspective) {
        double[] sc = triangles.screen();
        double[] at = triangles.attributes();
        int s = tri * ScreenTriangles.SCREEN_STRIDE;
        int a = tri * ScreenTriangles.ATTRIBUTE_STRIDE;
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
        int c0 = a;
        int c1 = a + 3 * i1;
        int c2 = a + 3 * i2;
        double q0 = at[c0];
        double q1 = at[c1];
        double q2 = at[c2];
        double s0 = at[c0 + 1];
        double s1 = at[c1 + 1];
        double s2 = at[c2 + 1];
        double t0 = at[c0 + 2];
        double t1 = at[c1 + 2];
        double t2 = at[c2 + 2];
        if (perspective) {
            // Interpolate s/w and t/w; the pixel divides by the interpolated 1/w.
            s0 *= q0;
            s1 *= q1;
            s2 *= q2;
            t0 *= q0;
            t1 *= q1;
            t2 *= q2;
        }
        // Pixel (x, y) has its centre at (x + 0.5, y + 0.5); plane value there is
        // v0 + dx * (x + 0.5 - x0) + dy * (y + 0.5 - y0).
        double ox = 0.5 - x0;
        double oy = 0.5 - y0;
        double dq1 = q1 - q0;
        double dq2 = q2 - q0;
        qDx = (dq1 * ey2 - dq2 * ey1) * inv;
        qDy = (dq2 * ex1 - dq1 * ex2) * inv;
        qBase = q0 + qDx * ox + qDy * oy;
        double ds1 = s1 - s0;
        double ds2 = s2 - s0;
        sDx = (ds1 * ey2 - ds2 * ey1) * inv;
        sDy = (ds2 * ex1 - ds1 * ex2) * inv;
        sBase = s0 + sDx * ox + sDy * oy;
        double dt1 = t1 - t0;
        double dt2 = t2 - t0;
        tDx = (dt1 * ey2 - dt2 * ey1) * inv;
        tDy = (dt2 * ex1 - dt1 * ex2) * inv;
        tBase = t0 + tDx * ox + tDy * oy;
    }

    private int spanStart;
    private int spanEnd;

    /**
     * Narrows [colStart, colEnd) to the covered span of the current row into {@code spanStart} and
     * {@code spanEnd}; returns false when the row is empty.
     */
    private boolean span() {
        long start = colStart;
        long end = colEnd;
        // Edge 0
        if (m0 > 0) {
            end = Math.min(end, endOf(k0, m0, inv0));
        } else if (m0 < 0) {
            start = Math.max(start, startOf(k0, m0, inv0));
        } else if (k0 <= 0) {
            return false;
        }
        if (m1 > 0) {
            end = Math.min(end, endOf(k1, m1, inv1));
        } else if (m1 < 0) {
            start = Math.max(start, startOf(k1, m1, inv1));
        } else if (k1 <= 0) {
            return false;
        }
        if (m2 > 0) {
            end = Math.min(end, endOf(k2, m2, inv2));
        } else if (m2 < 0) {
            start = Math.max(start, startOf(k2, m2, inv2));
        } else if (k2 <= 0) {
            return false;
        }
        if (start >= end) {
            return false;
        }
        spanStart = (int) start;
        spanEnd = (int) end;
        return true;
    }

    /** For m &gt; 0 (inside where x &lt; K/m): the first x that is outside, ceil(K / m). */
    private static long endOf(long k, long m, double inv) {
        long x = (long) Math.ceil(k * inv);
        while (k - m * (x - 1) <= 0) {
            x--;
        }
        while (k - m * x > 0) {
            x++;
        }
        return x;
    }

    /** For m &lt; 0 (inside where x &gt; K/m): the first x that is inside, floor(K / m) + 1. */
    private static long startOf(long k, long m, double inv) {
        long x = (long) Math.floor(k * inv) + 1;
        while (k - m * (x - 1) > 0) {
            x--;
        }
        while (k - m * x <= 0) {
            x++;
        }
        return x;
    }

    private void nextRow() {
        k0 += step0;
        k1 += step1;
        k2 += step2;
    }

    private long spans(Framebuffer frame, Texture texture, int uvId, boolean perspective) {
        int width = frame.width();
        int[] color = frame.color();
        float[] depth = frame.depth();
        float[] uv = frame.uv();
        int[] texels = texture.argb();
        int tw = texture.width();
        int th = texture.height();
        // Power-of-two sides wrap with a mask (exact for negative values in two's complement).
        boolean pot = (tw & (tw - 1)) == 0 && (th & (th - 1)) == 0;
        int wMask = tw - 1;
        int hMask = th - 1;
        int topRow = th - 1;
        long written = 0;
        for (int y = rowStart; y < rowEnd; y++, nextRow()) {
            if (!span()) {
                continue;
            }
            double qRow = qBase + qDy * y;
            double sRow = sBase + sDy * y;
            double tRow = tBase + tDy * y;
            int rowOffset = y * width;
            // Every value comes from the plane at this pixel, not by accumulation along the row, so
            // no rounding error builds up across a wide triangle.
            for (int x = spanStart; x < spanEnd; x++) {
                double q = qRow + qDx * x;
                float qf = (float) q;
                int i = rowOffset + x;
                if (qf > depth[i]) {
                    depth[i] = qf;
                    double r = perspective ? 1.0 / q : 1.0;
                    double s = (sRow + sDx * x) * r;
                    double t = (tRow + tDx * x) * r;
                    int si = (int) Math.floor(s);
                    int ti = (int) Math.floor(t);
                    int column = pot ? si & wMask : Math.floorMod(si, tw);
                    int rowFromBottom = pot ? ti & hMask : Math.floorMod(ti, th);
                    color[i] = texels[(topRow - rowFromBottom) * tw + column] | 0xFF000000;
                    if (uv != null) {
                        uv[3 * i] = (float) s;
                        uv[3 * i + 1] = (float) t;
                        uv[3 * i + 2] = uvId;
                    }
                    written++;
                }
            }
        }
        return written;
    }

    // Accessors for the overlay, which reuses the setup's depth plane.
    double qBase() {
        return qBase;
    }

    double qDx() {
        return qDx;
    }

    double qDy() {
        return qDy;
    }
}
