package dev.trisect.raster;

import java.util.Arrays;

/**
 * The pieces of one input triangle within one rectangle of the frame (a band), set up in bulk for
 * the one-pass fill ({@link OnePassSpans}): per piece its attribute planes, its fixed-point anchor
 * column and steps, how it is filled, and its covered span on each row; then, per row, the pieces'
 * spans sorted along the row, the segments one pixel loop runs across.
 *
 * <p>Each piece is set up by {@link TriangleSetup} and walked by {@link SpanSolver} exactly as the
 * piece-by-piece fill does, so its coverage and its planes are those of that fill, bit for bit. Pieces
 * of one triangle share their edges' snapped corners, so their spans on a row meet without gap or
 * overlap (the top-left rule gives each centre on a shared edge to one of them); a row where they
 * overlap all the same (a piece cap left a T-junction) is marked, and filled piece by piece in order.
 *
 * <p>Pixel (x, y) has its centre at (x + 0.5, y + 0.5) in pixels, row 0 at the top. One per thread;
 * its arrays grow to the largest triangle and are reused.
 */
final class PieceRows {
    /** Filled affinely, texel coordinates stepped in 32.32 fixed point ({@link NearestSpans#affineFixed}). */
    static final byte FIXED = 0;
    /** Filled per pixel, perspective-correct: a fallback piece. */
    static final byte PERSPECTIVE = 1;
    /** Filled affinely with texel coordinates in doubles: too large for fixed point. */
    static final byte AFFINE_DOUBLE = 2;
    /** Doubles per piece in {@link #planes}: the q, s and t planes' base, dx and dy in turn. */
    static final int PLANE_STRIDE = 9;

    /** Pieces set up. */
    int count;
    /** Per piece: {@link #FIXED}, {@link #PERSPECTIVE} or {@link #AFFINE_DOUBLE}. */
    byte[] kind = new byte[64];
    /** Per piece: its own first column, the anchor of its fixed-point stepping (see {@link TriangleSetup#firstColumn}). */
    int[] firstColumn = new int[64];
    /** Per piece: the planes of {@link TriangleSetup}, {@link #PLANE_STRIDE} doubles. */
    double[] planes = new double[64 * PLANE_STRIDE];
    /** Per piece: its s and t steps per pixel, 32.32 fixed point. */
    long[] steps = new long[64 * 2];
    /** Per piece: its triangle in the {@link ScreenTriangles}, for the level of detail of filtered fills. */
    int[] triangle = new int[64];

    /** First row of the rectangle; rows [rowBase, rowBase + rows) are bucketed. */
    int rowBase;
    int rows;
    /** Per row r: its segments are [rowFirst[r], rowFirst[r + 1]), sorted by start once {@link #build} ran. */
    int[] rowFirst = new int[17];
    int[] segStart = new int[256];
    int[] segEnd = new int[256];
    int[] segPiece = new int[256];
    /** Per row: its segments overlap (fill them piece by piece, in order). */
    boolean[] overlap = new boolean[16];

    /** Per piece: rows [pieceRowStart, pieceRowEnd) of its spans in {@link #pieceSpans}, from pieceSpanAt. */
    private int[] pieceRowStart = new int[64];
    private int[] pieceRowEnd = new int[64];
    private int[] pieceSpanAt = new int[64];
    private int[] pieceSpans = new int[1024];
    private int spanCount;

    /** Starts a new triangle in rows [y0, y1). */
    void begin(int y0, int y1) {
        count = 0;
        spanCount = 0;
        rowBase = y0;
        rows = y1 - y0;
        if (rowFirst.length < rows + 1) {
            rowFirst = new int[rows + 1];
            overlap = new boolean[rows];
        }
        Arrays.fill(rowFirst, 0, rows + 1, 0);
    }

    /**
     * Adds a piece set up by {@code setup} and walked by {@code solver}, with its triangle and kind.
     */
    void add(TriangleSetup setup, int[] spans, int tri, byte how) {
        int p = count;
        if (p == kind.length) {
            grow();
        }
        kind[p] = how;
        triangle[p] = tri;
        firstColumn[p] = setup.firstColumn;
        int o = p * PLANE_STRIDE;
        double[] pl = planes;
        pl[o] = setup.qPlane.base;
        pl[o + 1] = setup.qPlane.dx;
        pl[o + 2] = setup.qPlane.dy;
        pl[o + 3] = setup.sPlane.base;
        pl[o + 4] = setup.sPlane.dx;
        pl[o + 5] = setup.sPlane.dy;
        pl[o + 6] = setup.tPlane.base;
        pl[o + 7] = setup.tPlane.dx;
        pl[o + 8] = setup.tPlane.dy;
        steps[2 * p] = (long) Math.floor(setup.sPlane.dx * OnePassSpans.FIXED_SCALE);
        steps[2 * p + 1] = (long) Math.floor(setup.tPlane.dx * OnePassSpans.FIXED_SCALE);
        int n = 2 * (setup.rowEnd - setup.rowStart);
        if (spanCount + n > pieceSpans.length) {
            pieceSpans = Arrays.copyOf(pieceSpans, Math.max(spanCount + n, 2 * pieceSpans.length));
        }
        System.arraycopy(spans, 0, pieceSpans, spanCount, n);
        pieceRowStart[p] = setup.rowStart;
        pieceRowEnd[p] = setup.rowEnd;
        pieceSpanAt[p] = spanCount;
        spanCount += n;
        int[] first = rowFirst;
        for (int j = 0, r = setup.rowStart - rowBase + 1; j < n; j += 2, r++) {
            if (spans[j] < spans[j + 1]) {
                first[r]++;
            }
        }
        count = p + 1;
    }

    /** Buckets the pieces' spans by row, sorts each row's along it, and marks rows where they overlap. */
    void build() {
        int[] first = rowFirst;
        for (int r = 0; r < rows; r++) {
            first[r + 1] += first[r];
        }
        int total = first[rows];
        if (segStart.length < total) {
            int n = Math.max(total, 2 * segStart.length);
            segStart = new int[n];
            segEnd = new int[n];
            segPiece = new int[n];
        }
        // first[r] runs up to first[r + 1] as row r fills, then is restored below.
        for (int p = 0; p < count; p++) {
            int at = pieceSpanAt[p];
            for (int y = pieceRowStart[p]; y < pieceRowEnd[p]; y++, at += 2) {
                int start = pieceSpans[at];
                int end = pieceSpans[at + 1];
                if (start < end) {
                    int k = first[y - rowBase]++;
                    segStart[k] = start;
                    segEnd[k] = end;
                    segPiece[k] = p;
                }
            }
        }
        for (int r = rows; r > 0; r--) {
            first[r] = first[r - 1];
        }
        first[0] = 0;
        for (int r = 0; r < rows; r++) {
            overlap[r] = sortRow(first[r], first[r + 1]);
        }
    }

    /**
     * Sorts segments [from, to) by start (insertion sort: few, and nearly in order when the tree is
     * walked left to right); returns whether any two overlap.
     */
    private boolean sortRow(int from, int to) {
        int[] st = segStart;
        int[] en = segEnd;
        int[] pc = segPiece;
        for (int i = from + 1; i < to; i++) {
            int s = st[i];
            if (s >= st[i - 1]) {
                continue;
            }
            int e = en[i];
            int p = pc[i];
            int j = i - 1;
            while (j >= from && st[j] > s) {
                st[j + 1] = st[j];
                en[j + 1] = en[j];
                pc[j + 1] = pc[j];
                j--;
            }
            st[j + 1] = s;
            en[j + 1] = e;
            pc[j + 1] = p;
        }
        for (int i = from + 1; i < to; i++) {
            if (en[i - 1] > st[i]) {
                return true;
            }
        }
        return false;
    }

    private void grow() {
        int n = 2 * kind.length;
        kind = Arrays.copyOf(kind, n);
        firstColumn = Arrays.copyOf(firstColumn, n);
        planes = Arrays.copyOf(planes, n * PLANE_STRIDE);
        steps = Arrays.copyOf(steps, n * 2);
        triangle = Arrays.copyOf(triangle, n);
        pieceRowStart = Arrays.copyOf(pieceRowStart, n);
        pieceRowEnd = Arrays.copyOf(pieceRowEnd, n);
        pieceSpanAt = Arrays.copyOf(pieceSpanAt, n);
    }
}
