package dev.trisect.raster;

import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;

/**
 * Fills screen-space triangles into a {@link Framebuffer}, restricted to a rectangle of the frame.
 *
 * <p>Coverage is exact integer arithmetic on snapped corners: a pixel belongs to a triangle when its
 * centre is inside, and a centre exactly on an edge goes to the triangle for which that edge is a top
 * or a left edge (image coordinates, y down). Each row's covered span is solved from the edge
 * functions instead of testing every pixel of the bounding box: above the middle corner a row is
 * bounded by the two edges that leave the top corner, below it by the two that reach the bottom one
 * (the row through the middle corner looks at all three), and each edge's bound is stepped from row
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
     * [spans[2j], spans[2j + 1]); an empty row has start &gt;= end. Filled by {@link #walk}{@code (false)}
     * before every loop that reads it ({@link #spans(Framebuffer, Texture, int, boolean)}, {@link FilteredSpans},
     * {@link #countCoverage}); the nearest affine fill solves its spans on the fly and leaves it as it was.
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
            if (filter == TextureFilter.NEAREST && !divide && fixedPointSafe) {
                prepareAffine(frame, texture, ids[tri] + 1);
                written += walk(true);
                continue;
            }
            walk(false);
            if (filter != TextureFilter.NEAREST) {
                written += FilteredSpans.fill(this, frame, texture.mipChain(), ids[tri] + 1, divide,
                        fixedPointSafe, filter);
                continue;
            }
            written += spans(frame, texture, ids[tri] + 1, divide);
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
            walk(false);
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
     * Prepares triangle {@code tri} for filling within the rectangle: bounds, edge order and attribute
     * planes (the spans follow from {@link #walk}); false when it covers no pixel centre there (or has
     * no area).
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
        order(ax, ay, bx, by, cx, cy);
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

    /** Longs per edge in {@link #edgeState}: K, its step per row, m, c, r, dc, dr, side. */
    private static final int EDGE_STATE = 8;
    /** Edge slot for the binding short edge of the row through the middle corner (see {@link #midRowEdge}). */
    private static final int SLOT = 3;
    private final long[] edgeState = new long[4 * EDGE_STATE];

    /**
     * Sets up edge a -&gt; a + (dx, dy) for the row whose centre is {@code py} (see {@link #order}): K
     * with the top-left bias, its step ONE * dx per row, and for a non-horizontal edge m = ONE * |dy|,
     * c = ceil(K / m) with remainder r (K = c m - r, 0 &lt;= r &lt; m), their steps dc, dr, and the side:
     * -1 for a right edge (dy &gt; 0), 1 for a left edge, 0 for a horizontal one. Both sides step alike,
     * with no branch on the side.
     */
    private static void edge(long[] st, int o, long ax, long ay, long dx, long dy, long py) {
        // The bias is 1 for a left edge (dy < 0) or a top edge (horizontal, going right).
        long bias = (dy >>> 63) | (dy == 0 && dx > 0 ? 1 : 0);
        long k = dx * (py - ay) - dy * (HALF - ax) + bias;
        long step = ONE * dx;
        st[o] = k;
        st[o + 1] = step;
        if (dy == 0) {
            // Horizontal: no bound to step; side 0 marks it, and the row is in or out by the sign of K.
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
        long c = ceilDiv(k, m, inv);
        long dc = ceilDiv(step, m, inv);
        st[o + 2] = m;
        st[o + 3] = c;
        st[o + 4] = c * m - k;
        st[o + 5] = dc;
        st[o + 6] = dc * m - step;
        st[o + 7] = dy > 0 ? -1 : 1;
    }

    /**
     * Orders the current triangle's corners by y for {@link #walk}, which solves the covered span of
     * each row of [rowStart, rowEnd), clipped to [colStart, colEnd).
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
     * K grows by ONE * dX per row. Rather than divide on every row, c = ceil(K / |m|) and its
     * remainder are stepped with additions only (an exact DDA), in local variables, c dropping by one
     * when the remainder overflows; a right edge's q is c, a left edge's is -c.
     *
     * <p>Only two edges are stepped on a row. With the corners ordered by y as top, mid, bottom, a row
     * whose centre lies above mid is bounded by the edges top-mid and top-bottom alone: a centre
     * inside both lies in their wedge at top, below top and above mid, so it is a convex combination
     * top + a (mid - top) + b (bottom - top) with a + b &lt; 1, where the third edge's function is
     * (1 - a - b) times its value at top, which is positive: that test cannot fail. Likewise below mid
     * with mid-bottom and top-bottom. One of the two is a left edge and one a right edge (they meet at
     * top, or at bottom), so each half runs a loop with no per-row decision. Only a row whose centre
     * is exactly at mid's height needs all three edges (two of them meet on it; the top-left bias can
     * tell them apart).
     */
    private void order(long ax, long ay, long bx, long by, long cx, long cy) {
        long[] c = corners;
        c[0] = ax;
        c[1] = ay;
        c[2] = bx;
        c[3] = by;
        c[4] = cx;
        c[5] = cy;
        // Corner indices ordered by y (ties in any order: the argument above needs only <=).
        int top = ay <= by ? (ay <= cy ? 0 : 2) : (by <= cy ? 1 : 2);
        int bottom = ay > by ? (ay > cy ? 0 : 2) : (by > cy ? 1 : 2);
        if (bottom == top) {
            bottom = (top + 1) % 3;
        }
        int mid = 3 - top - bottom;
        // Edge k is opposite corner k + 2 (mod 3).
        longEdge = (mid + 1) % 3;
        upperEdge = (bottom + 1) % 3;
        lowerEdge = (top + 1) % 3;
        long midY = c[2 * mid + 1];
        // Rows before midRow have centres above mid; midRow's centre is at mid's height if exact.
        midRow = (int) -Math.floorDiv(HALF - midY, (long) ONE);
        midExact = Math.floorMod(midY - HALF, (long) ONE) == 0;
    }

    /** The edges of the current triangle that {@link #walk} uses; see {@link #order}. */
    private int longEdge;
    private int upperEdge;
    private int lowerEdge;
    /** First row whose centre is not above the middle corner. */
    private int midRow;
    /** Whether {@link #midRow}'s centre is exactly at the middle corner's height. */
    private boolean midExact;

    /**
     * Walks rows [rowStart, rowEnd) of the current triangle, section by section (see {@link #order}):
     * fills {@link #spans} ({@code fill} false, returns 0), or fills the pixels with the nearest affine
     * fixed-point loop set up by {@link #prepareAffine} ({@code fill} true, returns pixels written).
     */
    private long walk(boolean fill) {
        if (!fill) {
            int rows = rowEnd - rowStart;
            if (spans.length < 2 * rows) {
                spans = new int[Math.max(2 * rows, 2 * spans.length)];
            }
        }
        long written = 0;
        int r = rowStart;
        setEdge(longEdge, r);
        int upperEnd = Math.min(rowEnd, midRow);
        if (r < upperEnd) {
            setEdge(upperEdge, r);
            written += section(longEdge, upperEdge, r, upperEnd, fill);
            r = upperEnd;
        }
        if (midExact && r == midRow && r < rowEnd) {
            setEdge(upperEdge, r);
            setEdge(lowerEdge, r);
            if (midRowEdge(upperEdge, lowerEdge)) {
                written += section(longEdge, SLOT, r, r + 1, fill);
            } else {
                if (!fill) {
                    spans[2 * (r - rowStart)] = colStart;
                    spans[2 * (r - rowStart) + 1] = colStart;
                }
                step(longEdge);
            }
            r++;
        }
        if (r < rowEnd) {
            setEdge(lowerEdge, r);
            written += section(longEdge, lowerEdge, r, rowEnd, fill);
        }
        return written;
    }

    /** Snapped corners of the current triangle in setup order (x0, y0, x1, y1, x2, y2), sub-pixel units. */
    private final long[] corners = new long[6];

    /** Sets up edge {@code e} (corner e to corner e + 1) for the row {@code row}. */
    private void setEdge(int e, int row) {
        long[] c = corners;
        int a = 2 * e;
        int b = 2 * ((e + 1) % 3);
        edge(edgeState, e * EDGE_STATE, c[a], c[a + 1], c[b] - c[a], c[b + 1] - c[a + 1],
                (long) row * ONE + HALF);
    }

    /** Steps edge {@code e}'s bound to the next row (a non-horizontal edge). */
    private void step(int e) {
        long[] st = edgeState;
        int o = e * EDGE_STATE;
        long m = st[o + 2];
        long q = st[o + 3] + st[o + 5];
        long r = st[o + 4] + st[o + 6];
        long over = (m - 1 - r) >> 63;
        st[o + 3] = q + over;
        st[o + 4] = r - (m & over);
    }

    /**
     * For the row whose centre is at the middle corner's height, with both short edges set up for it:
     * copies the one that bounds the row into {@link #SLOT} and returns true, or returns false when a
     * horizontal short edge leaves the row empty. Both short edges meet at the middle corner on the
     * same side of the long edge (the path top, mid, bottom runs one way), so the tighter bound of the
     * two is the row's bound on that side; they differ only when a centre lies exactly on the corner,
     * where the top-left bias of each decides.
     */
    private boolean midRowEdge(int upper, int lower) {
        long[] st = edgeState;
        int ou = upper * EDGE_STATE;
        int ol = lower * EDGE_STATE;
        int pick;
        if (st[ou + 7] == 0 || st[ol + 7] == 0) {
            // A horizontal edge on this row: the row is in or out by the sign of its K; then the
            // other short edge (not horizontal, or the triangle had no area) bounds it.
            int horizontal = st[ou + 7] == 0 ? ou : ol;
            if (st[horizontal] <= 0) {
                return false;
            }
            pick = horizontal == ou ? ol : ou;
        } else {
            // Right edges end the row at c, left edges start it at 1 - c: the smaller c binds either way.
            pick = st[ou + 3] <= st[ol + 3] ? ou : ol;
        }
        System.arraycopy(st, pick, st, SLOT * EDGE_STATE, EDGE_STATE);
        return true;
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

    // The nearest affine fill's per-triangle state, set by prepareAffine and read by affineSection.
    private int[] color;
    private float[] depth;
    private double[] uvOut;
    private int width;
    private int[] texels;
    private int texWidth;
    private int texHeight;
    private boolean pot;
    private int uvId;
    private long ds;
    private long dt;

    /** Sets up the nearest affine fill of the current triangle (see {@link #affineSection}). */
    private void prepareAffine(Framebuffer frame, Texture texture, int id) {
        color = frame.color();
        depth = frame.depth();
        uvOut = frame.uv();
        width = frame.width();
        texels = texture.argb();
        texWidth = texture.width();
        texHeight = texture.height();
        // Power-of-two sides wrap with a mask (exact for negative values in two's complement).
        pot = (texWidth & (texWidth - 1)) == 0 && (texHeight & (texHeight - 1)) == 0;
        uvId = id;
        ds = (long) Math.floor(sPlane.dx * FIXED_SCALE);
        dt = (long) Math.floor(tPlane.dx * FIXED_SCALE);
    }

    /**
     * Rows [from, to) of the current triangle, bounded by edges {@code longEdge} and {@code shortEdge}
     * alone (one left, one right; both set up for row {@code from}; see {@link #order}); leaves the long
     * edge's state stepped to row {@code to}. With {@code fill} false it stores each row's span in
     * {@link #spans}; with {@code fill} true it fills the span at once, without storing it (the flag
     * is the same on every row, so its branch is always predicted), with the nearest affine loop set
     * up by {@link #prepareAffine}.
     *
     * <p>That loop steps texel coordinates in 32.32 fixed point: per pixel an integer add, a shift
     * and a mask instead of two multiply-adds, two floors and two conversions. Each row's values are
     * anchored at the triangle's own first column and reach the span by an exact integer multiply, so
     * a pixel's value depends on the triangle, the row and the column only — never on the rectangle
     * being filled — and stepping error stays below 2^-32 texel per pixel of the row. Needs |s|, |t|
     * &lt; 2^30 over the triangle.
     *
     * @return pixels written (0 when not filling)
     */
    private long section(int longEdge, int shortEdge, int from, int to, boolean fill) {
        long[] st = edgeState;
        int lo = longEdge * EDGE_STATE;
        int ro = shortEdge * EDGE_STATE;
        boolean longIsLeft = st[lo + 7] > 0;
        if (!longIsLeft) {
            int t = lo;
            lo = ro;
            ro = t;
        }
        long mL = st[lo + 2];
        long cL = st[lo + 3];
        long rL = st[lo + 4];
        long dcL = st[lo + 5];
        long drL = st[lo + 6];
        long mR = st[ro + 2];
        long cR = st[ro + 3];
        long rR = st[ro + 4];
        long dcR = st[ro + 5];
        long drR = st[ro + 6];
        long cs = colStart;
        long ce = colEnd;
        double qBase = qPlane.base;
        double qDx = qPlane.dx;
        double qDy = qPlane.dy;
        double sBase = sPlane.base;
        double sDx = sPlane.dx;
        double sDy = sPlane.dy;
        double tBase = tPlane.base;
        double tDx = tPlane.dx;
        double tDy = tPlane.dy;
        int width = this.width;
        int[] color = this.color;
        float[] depth = this.depth;
        double[] uv = uvOut;
        int[] texels = this.texels;
        int tw = texWidth;
        int th = texHeight;
        boolean pot = this.pot;
        int wMask = tw - 1;
        int hMask = th - 1;
        int topRow = th - 1;
        long ds = this.ds;
        long dt = this.dt;
        int uvId = this.uvId;
        int firstColumn = this.firstColumn;
        int[] out = spans;
        long written = 0;
        long over;
        // The remainder overflows on a data-dependent pattern of rows, which a branch would mispredict
        // about half the time; a sign mask (all ones when r >= m) applies the carry without one.
        for (int y = from, j = 2 * (from - rowStart); y < to; y++, j += 2) {
            long first = Math.max(cs, 1 - cL);
            long last = Math.min(ce, cR);
            if (!fill) {
                out[j] = (int) first;
                out[j + 1] = (int) Math.max(first, last);
            } else if (first < last) {
                int spanStart = (int) first;
                int spanEnd = (int) last;
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
            cL += dcL;
            rL += drL;
            over = (mL - 1 - rL) >> 63;
            cL += over;
            rL -= mL & over;
            cR += dcR;
            rR += drR;
            over = (mR - 1 - rR) >> 63;
            cR += over;
            rR -= mR & over;
        }
        if (longIsLeft) {
            st[lo + 3] = cL;
            st[lo + 4] = rL;
        } else {
            st[ro + 3] = cR;
            st[ro + 4] = rR;
        }
        return written;
    }
}
