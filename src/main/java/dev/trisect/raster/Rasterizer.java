package dev.trisect.raster;

import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;

/**
 * Fills screen-space triangles into a {@link Framebuffer}, restricted to a rectangle of the frame.
 *
 * <p>Coverage is exact integer arithmetic on snapped corners: a pixel belongs to a triangle when its
 * centre is inside, and a centre exactly on an edge goes to the triangle for which that edge is a top
 * or a left edge (image coordinates, y down). Each row's covered span is solved from the three edge
 * functions instead of testing every pixel of the bounding box: each edge's bound is stepped from row
 * to row with integer additions (an exact DDA, set up per triangle), so the span is exactly the set of
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
    int rowStart;
    int rowEnd;
    private int colStart;
    private int colEnd;
    /** The triangle's own first column, before clipping to the rectangle: the anchor of fixed-point stepping. */
    int firstColumn;
    /**
     * The covered pixels of each row of the current triangle: row {@code rowStart + j} covers
     * [spans[2j], spans[2j + 1]); an empty row has start &gt;= end.
     */
    int[] spans = new int[64];
    // Attribute planes over pixel centres: value = base + dx * x + dy * y for pixel (x, y).
    final Plane qPlane = new Plane();
    final Plane sPlane = new Plane();
    final Plane tPlane = new Plane();
    /** Whether the texel coordinates are small enough for 32.32 fixed point (|s|, |t| &lt; 2^30). */
    private boolean fixedPointSafe;
    /** How {@link #fill} samples textures; bilinear and trilinear loops are in {@link FilteredSpans}. */
    private TextureFilter filter = TextureFilter.NEAREST;

    /** Sets how the following {@link #fill} calls sample textures (nearest until set). */
    public void filter(TextureFilter f) {
        if (f == null) {
            throw new IllegalArgumentException("texture filter must not be null");
        }
        filter = f;
    }

    /**
     * Fills triangles {@code order[from..to)} of {@code triangles}, in that order, into the pixels
     * {@code [x0, x1) x [y0, y1)} of the frame.
     *
     * @param perspective true: u/w, v/w and 1/w interpolate linearly on screen and every pixel
     *                    divides; false: u and v interpolate linearly on screen (affine), except for
     *                    triangles flagged {@link ScreenTriangles#perPixel()}, which divide
     * @param textures    texture of each material index
     * @return the number of pixels written (depth test passed)
     */
    public long fill(Framebuffer frame, ScreenTriangles triangles, int[] order, int from, int to,
                     Texture[] textures, boolean perspective, int x0, int y0, int x1, int y1) {
        long written = 0;
        int[] materials = triangles.materials();
        int[] ids = triangles.ids();
        boolean[] perPixel = triangles.perPixel();
        for (int n = from; n < to; n++) {
            int tri = order[n];
            boolean divide = perspective || perPixel[tri];
            if (!setup(triangles, tri, divide, x0, y0, x1, y1)) {
                continue;
            }
            Texture texture = textures[materials[tri]];
            if (filter != TextureFilter.NEAREST) {
                written += FilteredSpans.fill(this, frame, texture.mipChain(), ids[tri] + 1, divide,
                        fixedPointSafe, filter);
                continue;
            }
            written += divide || !fixedPointSafe
                    ? spans(frame, texture, ids[tri] + 1, divide)
                    : spansAffineFixed(frame, texture, ids[tri] + 1);
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
            int[] sp = spans;
            for (int y = rowStart, j = 0; y < rowEnd; y++, j += 2) {
                int row = y * width;
                int end = sp[j + 1];
                for (int x = sp[j]; x < end; x++) {
                    counts[row + x]++;
                }
                covered += end - sp[j];
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
        firstColumn = ScreenTriangles.ceilDiv(minX - HALF, ONE);
        colStart = Math.max(x0, firstColumn);
        colEnd = Math.min(x1, Math.floorDiv(maxX - HALF, ONE) + 1);
        rowStart = Math.max(y0, ScreenTriangles.ceilDiv(minY - HALF, ONE));
        rowEnd = Math.min(y1, Math.floorDiv(maxY - HALF, ONE) + 1);
        if (colStart >= colEnd || rowStart >= rowEnd) {
            return false;
        }
        computeSpans(ax, ay, bx, by, cx, cy);
        planes(triangles, tri, i1, i2, perspective);
        return true;
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
        double limit = 1 << 30;
        fixedPointSafe = Math.abs(s0) < limit && Math.abs(s1) < limit && Math.abs(s2) < limit
                && Math.abs(t0) < limit && Math.abs(t1) < limit && Math.abs(t2) < limit;
        if (perspective) {
            // Interpolate s/w and t/w; the pixel divides by the interpolated 1/w.
            s0 *= q0;
            s1 *= q1;
            s2 *= q2;
            t0 *= q0;
            t1 *= q1;
            t2 *= q2;
        }
        qPlane.fit(x0, y0, ex1, ey1, ex2, ey2, inv, q0, q1, q2);
        sPlane.fit(x0, y0, ex1, ey1, ex2, ey2, inv, s0, s1, s2);
        tPlane.fit(x0, y0, ex1, ey1, ex2, ey2, inv, t0, t1, t2);
    }

    /**
     * ceil(a / m) for m &gt; 0, exactly, without an integer division: a floating-point estimate from
     * {@code inv = 1.0 / m} is off by at most one here (|a| &lt; 2^52), and the integer checks fix it.
     */
    private static long ceilDiv(long a, long m, double inv) {
        long q = (long) Math.ceil(a * inv);
        if (q * m < a) {
            q++;
        } else if ((q - 1) * m >= a) {
            q--;
        }
        return q;
    }

    /** Longs per edge in {@link #edgeState}: K, its step per row, m, q, r, dq, dr, carry. */
    private static final int EDGE_STATE = 8;
    private final long[] edgeState = new long[3 * EDGE_STATE];

    /**
     * Sets up edge a -&gt; a + (dx, dy) for the row whose centre is {@code py} (see {@link #computeSpans}):
     * K with the top-left bias, its step ONE * dx per row, and for a non-horizontal edge m = ONE * |dy|,
     * the bound q with remainder r, their steps dq, dr, and the carry a remainder overflow adds to q.
     */
    private static void edge(long[] st, int o, long ax, long ay, long dx, long dy, long py) {
        long k = dx * (py - ay) - dy * (HALF - ax) + ((dy < 0 || (dy == 0 && dx > 0)) ? 1 : 0);
        long step = ONE * dx;
        st[o] = k;
        st[o + 1] = step;
        if (dy == 0) {
            // Horizontal: no bound to step; m = 0 marks it, and the row is in or out by the sign of K.
            st[o + 2] = 0;
            st[o + 3] = 0;
            st[o + 4] = 0;
            st[o + 5] = 0;
            st[o + 6] = 0;
            st[o + 7] = 0;
            return;
        }
        long m = ONE * Math.abs(dy);
        double inv = 1.0 / m;
        long q;
        long dq;
        if (dy > 0) {
            // Right edge: q = ceil(K/m), K = q m - r with 0 <= r < m; K grows by step per row.
            q = ceilDiv(k, m, inv);
            dq = ceilDiv(step, m, inv);
            st[o + 4] = q * m - k;
            st[o + 6] = dq * m - step;
            st[o + 7] = -1;
        } else {
            // Left edge: q = floor(N/m) = -ceil(K/m) for N = -K, N = q m + r; N shrinks by step per row.
            q = -ceilDiv(k, m, inv);
            dq = -ceilDiv(step, m, inv);
            st[o + 4] = -k - q * m;
            st[o + 6] = -step - dq * m;
            st[o + 7] = 1;
        }
        st[o + 2] = m;
        st[o + 3] = q;
        st[o + 5] = dq;
    }

    /**
     * Fills {@link #spans} for rows [rowStart, rowEnd), clipped to [colStart, colEnd).
     *
     * <p>Edge k runs from corner k to corner k+1. With E(x) = K - m x on a row (m = ONE * dY, and
     * the top-left bias folded into K: a centre exactly on a top edge, horizontal with the interior
     * below, or on a left edge, going up, counts as inside, which for integers is adding 1), a pixel is
     * inside when E(x) &gt; 0:
     * <ul>
     * <li>m &gt; 0 (a right edge): x &lt; K/m, so the first pixel outside is q = ceil(K / m);</li>
     * <li>m &lt; 0 (a left edge): x &gt; -K/|m|, so the last pixel outside is q = floor(-K / |m|);</li>
     * <li>m = 0 (horizontal): the whole row is in or out by the sign of K.</li>
     * </ul>
     * K grows by ONE * dX per row. Rather than divide on every row, each edge's q and its remainder
     * are stepped with additions only (an exact DDA), in local variables; a right edge's q drops by one
     * when its remainder overflows, a left edge's rises by one.
     */
    private void computeSpans(long ax, long ay, long bx, long by, long cx, long cy) {
        int rows = rowEnd - rowStart;
        if (spans.length < 2 * rows) {
            spans = new int[Math.max(2 * rows, 2 * spans.length)];
        }
        long py = (long) rowStart * ONE + HALF;
        long dx0 = bx - ax;
        long dy0 = by - ay;
        long dx1 = cx - bx;
        long dy1 = cy - by;
        long dx2 = ax - cx;
        long dy2 = ay - cy;
        long[] st = edgeState;
        edge(st, 0, ax, ay, dx0, dy0, py);
        edge(st, EDGE_STATE, bx, by, dx1, dy1, py);
        edge(st, 2 * EDGE_STATE, cx, cy, dx2, dy2, py);
        long k0 = st[0], s0 = st[1], m0 = st[2], q0 = st[3], r0 = st[4], dq0 = st[5], dr0 = st[6], carry0 = st[7];
        long k1 = st[8], s1 = st[9], m1 = st[10], q1 = st[11], r1 = st[12], dq1 = st[13], dr1 = st[14], carry1 = st[15];
        long k2 = st[16], s2 = st[17], m2 = st[18], q2 = st[19], r2 = st[20], dq2 = st[21], dr2 = st[22], carry2 = st[23];
        int[] out = spans;
        // The remainder overflows on a data-dependent pattern of rows, which a branch would mispredict
        // about half the time; a sign mask (all ones when r >= m) applies the carry without one. A
        // horizontal edge has m = r = dr = carry = 0, so its mask is all ones and changes nothing.
        long over;
        for (int j = 0; j < rows; j++) {
            long start = colStart;
            long end = colEnd;
            if (dy0 > 0) {
                end = Math.min(end, q0);
            } else if (dy0 < 0) {
                start = Math.max(start, q0 + 1);
            } else if (k0 <= 0) {
                end = start;
            }
            if (dy1 > 0) {
                end = Math.min(end, q1);
            } else if (dy1 < 0) {
                start = Math.max(start, q1 + 1);
            } else if (k1 <= 0) {
                end = start;
            }
            if (dy2 > 0) {
                end = Math.min(end, q2);
            } else if (dy2 < 0) {
                start = Math.max(start, q2 + 1);
            } else if (k2 <= 0) {
                end = start;
            }
            out[2 * j] = (int) start;
            out[2 * j + 1] = (int) Math.max(start, end);
            q0 += dq0;
            r0 += dr0;
            over = (m0 - 1 - r0) >> 63;
            q0 += carry0 & over;
            r0 -= m0 & over;
            q1 += dq1;
            r1 += dr1;
            over = (m1 - 1 - r1) >> 63;
            q1 += carry1 & over;
            r1 -= m1 & over;
            q2 += dq2;
            r2 += dr2;
            over = (m2 - 1 - r2) >> 63;
            q2 += carry2 & over;
            r2 -= m2 & over;
            k0 += s0;
            k1 += s1;
            k2 += s2;
        }
    }

    private long spans(Framebuffer frame, Texture texture, int uvId, boolean perspective) {
        double qBase = qPlane.base;
        double qDx = qPlane.dx;
        double qDy = qPlane.dy;
        double sBase = sPlane.base;
        double sDx = sPlane.dx;
        double sDy = sPlane.dy;
        double tBase = tPlane.base;
        double tDx = tPlane.dx;
        double tDy = tPlane.dy;
        int width = frame.width();
        int[] color = frame.color();
        float[] depth = frame.depth();
        double[] uv = frame.uv();
        int[] texels = texture.argb();
        int tw = texture.width();
        int th = texture.height();
        // Power-of-two sides wrap with a mask (exact for negative values in two's complement).
        boolean pot = (tw & (tw - 1)) == 0 && (th & (th - 1)) == 0;
        int wMask = tw - 1;
        int hMask = th - 1;
        int topRow = th - 1;
        long written = 0;
        int[] sp = spans;
        for (int y = rowStart, j = 0; y < rowEnd; y++, j += 2) {
            int spanStart = sp[j];
            int spanEnd = sp[j + 1];
            if (spanStart >= spanEnd) {
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
                        uv[3 * i] = s;
                        uv[3 * i + 1] = t;
                        uv[3 * i + 2] = uvId;
                    }
                    written++;
                }
            }
        }
        return written;
    }

    /** 2^32: texel coordinates in 32.32 fixed point. */
    private static final double FIXED_SCALE = 4294967296.0;

    /**
     * The affine fill with texel coordinates stepped in 32.32 fixed point: per pixel an integer add,
     * a shift and a mask instead of two multiply-adds, two floors and two conversions. Each row's
     * values are anchored at the triangle's own first column and reach the span by an exact integer
     * multiply, so a pixel's value depends on the triangle, the row and the column only — never on the
     * rectangle being filled — and stepping error stays below 2^-32 texel per pixel of the row.
     * Needs |s|, |t| &lt; 2^30 over the triangle.
     */
    private long spansAffineFixed(Framebuffer frame, Texture texture, int uvId) {
        double qBase = qPlane.base;
        double qDx = qPlane.dx;
        double qDy = qPlane.dy;
        double sBase = sPlane.base;
        double sDx = sPlane.dx;
        double sDy = sPlane.dy;
        double tBase = tPlane.base;
        double tDx = tPlane.dx;
        double tDy = tPlane.dy;
        int width = frame.width();
        int[] color = frame.color();
        float[] depth = frame.depth();
        double[] uv = frame.uv();
        int[] texels = texture.argb();
        int tw = texture.width();
        int th = texture.height();
        boolean pot = (tw & (tw - 1)) == 0 && (th & (th - 1)) == 0;
        int wMask = tw - 1;
        int hMask = th - 1;
        int topRow = th - 1;
        long ds = (long) Math.floor(sDx * FIXED_SCALE);
        long dt = (long) Math.floor(tDx * FIXED_SCALE);
        long written = 0;
        int[] sp = spans;
        for (int y = rowStart, j = 0; y < rowEnd; y++, j += 2) {
            int spanStart = sp[j];
            int spanEnd = sp[j + 1];
            if (spanStart >= spanEnd) {
                continue;
            }
            double qRow = qBase + qDy * y;
            long skip = spanStart - firstColumn;
            long s = (long) Math.floor((sBase + sDy * y + sDx * firstColumn) * FIXED_SCALE) + ds * skip;
            long t = (long) Math.floor((tBase + tDy * y + tDx * firstColumn) * FIXED_SCALE) + dt * skip;
            int rowOffset = y * width;
            for (int x = spanStart; x < spanEnd; x++, s += ds, t += dt) {
                float qf = (float) (qRow + qDx * x);
                int i = rowOffset + x;
                if (qf > depth[i]) {
                    depth[i] = qf;
                    // An arithmetic shift floors, negative coordinates included.
                    int si = (int) (s >> 32);
                    int ti = (int) (t >> 32);
                    int column = pot ? si & wMask : Math.floorMod(si, tw);
                    int rowFromBottom = pot ? ti & hMask : Math.floorMod(ti, th);
                    color[i] = texels[(topRow - rowFromBottom) * tw + column] | 0xFF000000;
                    if (uv != null) {
                        uv[3 * i] = s / FIXED_SCALE;
                        uv[3 * i + 1] = t / FIXED_SCALE;
                        uv[3 * i + 2] = uvId;
                    }
                    written++;
                }
            }
        }
        return written;
    }
}
