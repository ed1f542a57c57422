package dev.trisect.raster;

/**
 * Solves the covered span of each row of a set-up triangle: {@link #walk} fills {@link #spans()}
 * with, for row {@code rowStart + j}, the pixels [spans[2j], spans[2j + 1]) whose centres the
 * triangle covers within the rectangle it was set up for (an empty row has start &gt;= end).
 *
 * <p>A pixel belongs to a triangle when its centre is inside, and a centre exactly on an edge goes to
 * the triangle for which that edge is a top or a left edge (image coordinates, y down). Rather than
 * test every pixel of the bounding box, each edge's bound is stepped from row to row with integer
 * additions (an exact DDA, set up per triangle), so the span is exactly the set of centres that a
 * per-pixel test would accept.
 *
 * <p>Edge k runs from corner k to corner k+1. With E(x) = K - m x on a row (m = ONE * dY, and the
 * top-left bias folded into K: a centre exactly on a top edge, horizontal with the interior below, or
 * on a left edge, going up, counts as inside, which for integers is adding 1), a pixel is inside when
 * E(x) &gt; 0:
 * <ul>
 * <li>m &gt; 0 (a right edge): x &lt; K/m, so the first pixel outside is q = ceil(K / m);</li>
 * <li>m &lt; 0 (a left edge): x &gt; -K/|m|, so the last pixel outside is q = floor(-K / |m|);</li>
 * <li>m = 0 (horizontal): the whole row is in or out by the sign of K.</li>
 * </ul>
 * K grows by ONE * dX per row. Rather than divide on every row, c = ceil(K / |m|) and its
 * remainder are stepped with additions only, in local variables, c dropping by one when the
 * remainder overflows; a right edge's q is c, a left edge's is -c.
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
 *
 * <p>One per thread; nothing is allocated per triangle once the span array has grown.
 */
final class SpanSolver {
    private static final int ONE = FixedPoint.ONE;
    private static final int HALF = FixedPoint.HALF;
    /** Longs per edge in {@link #edgeState}: K, its step per row, m, c, r, dc, dr, side. */
    private static final int EDGE_STATE = 8;
    /** Edge slot for the binding short edge of the row through the middle corner (see {@link #midRowEdge}). */
    private static final int SLOT = 3;

    private final long[] edgeState = new long[4 * EDGE_STATE];
    private int[] spans = new int[64];
    /** The triangle being walked. */
    private TriangleSetup triangle;
    /** The edges of the triangle that bound its rows: see the class comment. */
    private int longEdge;
    private int upperEdge;
    private int lowerEdge;
    /** First row whose centre is not above the middle corner. */
    private int midRow;
    /** Whether {@link #midRow}'s centre is exactly at the middle corner's height. */
    private boolean midExact;

    /**
     * The covered pixels of each row of the triangle last walked: row {@code rowStart + j} covers
     * [spans[2j], spans[2j + 1]). The array may be longer than the triangle's rows.
     */
    int[] spans() {
        return spans;
    }

    /** Solves the spans of rows [rowStart, rowEnd) of {@code t}, within columns [colStart, colEnd). */
    void walk(TriangleSetup t) {
        triangle = t;
        order(t.corners);
        int rowStart = t.rowStart;
        int rowEnd = t.rowEnd;
        int rows = rowEnd - rowStart;
        if (spans.length < 2 * rows) {
            spans = new int[Math.max(2 * rows, 2 * spans.length)];
        }
        int r = rowStart;
        setEdge(longEdge, r);
        int upperEnd = Math.min(rowEnd, midRow);
        if (r < upperEnd) {
            setEdge(upperEdge, r);
            section(longEdge, upperEdge, r, upperEnd);
            r = upperEnd;
        }
        if (midExact && r == midRow && r < rowEnd) {
            setEdge(upperEdge, r);
            setEdge(lowerEdge, r);
            if (midRowEdge(upperEdge, lowerEdge)) {
                section(longEdge, SLOT, r, r + 1);
            } else {
                spans[2 * (r - rowStart)] = t.colStart;
                spans[2 * (r - rowStart) + 1] = t.colStart;
                step(longEdge);
            }
            r++;
        }
        if (r < rowEnd) {
            setEdge(lowerEdge, r);
            section(longEdge, lowerEdge, r, rowEnd);
        }
    }

    /** Orders the corners by y and picks the long, upper and lower edges (see the class comment). */
    private void order(long[] c) {
        long ay = c[1];
        long by = c[3];
        long cy = c[5];
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
        // Floor division and remainder by ONE as a shift and a mask (exact for every long).
        midRow = (int) -((HALF - midY) >> FixedPoint.BITS);
        midExact = ((midY - HALF) & (ONE - 1)) == 0;
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

    /**
     * Sets up edge a -&gt; a + (dx, dy) for the row whose centre is {@code py}: K with the top-left
     * bias, its step ONE * dx per row, and for a non-horizontal edge m = ONE * |dy|, c = ceil(K / m)
     * with remainder r (K = c m - r, 0 &lt;= r &lt; m), their steps dc, dr, and the side: -1 for a
     * right edge (dy &gt; 0), 1 for a left edge, 0 for a horizontal one. Both sides step alike, with
     * no branch on the side.
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

    /** Sets up edge {@code e} (corner e to corner e + 1) for the row {@code row}. */
    private void setEdge(int e, int row) {
        long[] c = triangle.corners;
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

    /**
     * Stores the spans of rows [from, to), bounded by edges {@code longEdge} and {@code shortEdge}
     * alone (one left, one right; both set up for row {@code from}); leaves the long edge's state
     * stepped to row {@code to}.
     */
    private void section(int longEdge, int shortEdge, int from, int to) {
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
        long cs = triangle.colStart;
        long ce = triangle.colEnd;
        int[] out = spans;
        long over;
        // The remainder overflows on a data-dependent pattern of rows, which a branch would mispredict
        // about half the time; a sign mask (all ones when r >= m) applies the carry without one.
        for (int j = 2 * (from - triangle.rowStart), end = 2 * (to - triangle.rowStart); j < end; j += 2) {
            long first = Math.max(cs, 1 - cL);
            long last = Math.min(ce, cR);
            out[j] = (int) first;
            out[j + 1] = (int) Math.max(first, last);
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
    }
}
