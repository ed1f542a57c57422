package dev.trisect.raster;

import java.util.Arrays;

/**
 * The tessellated path's one-pass fill, the part every filter shares (its loops are {@link TreeLoops},
 * generated from a template), one pass per input triangle: the input triangle's rows, as
 * {@link SpanSolver} solved them from its own snapped corners, are each cut into the segments of its
 * pieces by descending the split tree ({@link SplitTrees}) along the row, left to right, and each run
 * of affine pieces along the row is filled by one loop with each piece's texel planes in 32.32 fixed
 * point, loaded where the row crosses into the piece. Per row, each split
 * line the row meets inside its node is crossed once (one multiply-add and a ceiling), instead of
 * each piece setting up and walking its own edges: the interior edges are found once per row for the
 * two pieces that share them.
 *
 * <p>Which piece a pixel takes: the one whose region, as the tree's lines bound it, holds the pixel's
 * centre; a centre exactly on a split line goes to the right-hand piece (the lower one for a horizontal
 * line). Since the leaves of a split tree tile its triangle, every covered pixel gets exactly one
 * piece. Two pieces that share a line agree on it (both planes interpolate the same two corners),
 * and a piece's plane is evaluated only at centres inside it (up to the rounding of the crossing), so
 * no pixel is extrapolated beyond its piece — except across the input triangle's own edges, where its
 * coverage from corners snapped to 1/256 px reaches up to ~0.003 px beyond the pieces.
 *
 * <p>Depth is the input triangle's {@code 1/w} plane, as in the per-pixel path; the per-pixel
 * fallback pieces divide by it, with the input triangle's perspective planes (s/w, t/w); affine pieces
 * too large for fixed point are evaluated in doubles from their planes.
 *
 * <p>One per thread (its descent stack is scratch).
 */
final class TreeFill {
    /** 2^32: texel coordinates in 32.32 fixed point. */
    private static final double FIXED_SCALE = 4294967296.0;

    /** The descent's pending right-hand parts: reference, first column, end column. */
    private int[] stack = new int[3 * 64];

    /** A row's segments from the descent: first column, end column, piece. */
    private int[] segments = new int[3 * 64];

    /** The segments array of the last {@link #stackFor} (scratch for {@link #descend}). */
    int[] segments() {
        return segments;
    }

    /** Makes room for a descent through a tree of {@code nodes} nodes (and its segments). */
    int[] stackFor(int nodes) {
        if (stack.length < 3 * (nodes + 1)) {
            stack = Arrays.copyOf(stack, Math.max(3 * (nodes + 1), 2 * stack.length));
            segments = new int[stack.length];
        }
        return stack;
    }

    /**
     * Cuts the pixels [a, b) of pixel row {@code y} into the segments of the
     * tree's pieces, left to right: {@code segs[3i..3i+3)} is segment i's first column, end column and
     * piece. Pieces dropped off screen get no segment.
     *
     * @param st scratch of {@code 3 * (nodes + 1)} ints
     * @return 3 times the number of segments
     */
    static int descend(int root, int a, int b, int y, SplitTrees trees, int[] st, int[] segs) {
        int[] kids = trees.kids();
        double[] lines = trees.lines();
        int[] rows = trees.rows();
        int[] rowKids = trees.rowKids();
        double yd = y;
        int n = 0;
        int top = 0;
        int ref = root;
        while (true) {
            if (ref >= 0) {
                int r = 2 * ref;
                if (y < rows[r]) {
                    ref = rowKids[r];
                    continue;
                }
                if (y >= rows[r + 1]) {
                    ref = rowKids[r + 1];
                    continue;
                }
                // A split: the first column whose centre is at or right of the line goes right.
                int o = SplitTrees.LINE * ref;
                int c = Math.min(b, Math.max(a, (int) Math.ceil(lines[o] * yd + lines[o + 1])));
                int k = 2 * ref;
                // Without branches: the right part is pushed when both parts hold pixels, and the
                // descent goes on into the left part if it holds any, else into the right.
                int right = kids[k + 1];
                boolean left = c > a;
                st[top] = right;
                st[top + 1] = c;
                st[top + 2] = b;
                top += left & c < b ? 3 : 0;
                ref = left ? kids[k] : right;
                b = left ? c : b;
                continue;
            }
            segs[n] = a;
            segs[n + 1] = b;
            segs[n + 2] = -1 - ref;
            n += ref != SplitTrees.NO_PIECE ? 3 : 0;
            if (top == 0) {
                return n;
            }
            top -= 3;
            ref = st[top];
            a = st[top + 1];
            b = st[top + 2];
        }
    }

    /**
     * The end (exclusive, an index into {@code segs}) of the run of segments from {@code g} on whose
     * pieces are {@link SplitTrees#AFFINE} and which follow one another without a gap (a gap would be
     * a piece dropped off screen, which holds no pixel centre of the frame; the run ends there to be safe).
     * Segment {@code g}'s piece must be affine.
     */
    static int affineRun(int[] segs, int g, int n, byte[] kinds) {
        int k = g + 3;
        while (k < n && kinds[segs[k + 2]] == SplitTrees.AFFINE && segs[k] == segs[k - 2]) {
            k += 3;
        }
        return k;
    }

    /**
     * A texel coordinate at column {@code x} of row {@code y} of a piece, in 32.32 fixed point, from its
     * plane at {@code planes[o..o+3)} (base, dx, dy): anchored at the piece's first column {@code fc}
     * and stepped from there by {@code step}, exactly as {@link FixedLoops} and
     * {@link TreeLoops}'s filtered loops do for a piece's row, so that the pixel takes the bits it took when pieces
     * were filled one by one.
     */
    static long start(double[] planes, int o, int y, int fc, long step, int x) {
        long skip = x - fc;
        return (long) Math.floor((planes[o] + planes[o + 2] * y + planes[o + 1] * fc) * FIXED_SCALE) + step * skip;
    }

    /** A segment of a per-pixel or wide piece, as a {@link TriangleSetup} of one row ({@link #oneRow}). */
    private final TriangleSetup segment = new TriangleSetup();
    /** That segment's span, first column and end column: the spans of {@link #segment}. */
    final int[] segmentSpan = new int[2];

    /**
     * Pixels [a, b) of row y of {@code piece}, a per-pixel fallback piece or an affine piece too large
     * for fixed point, as a setup of one row for the loops that fill whole triangles
     * ({@link PerPixelLoops}; its span in {@link #segmentSpan}):
     * the input triangle's depth, and its perspective-correct planes for a fallback piece (so that
     * the pixel is the per-pixel path's), the piece's own affine planes (doubles) for the other.
     */
    TriangleSetup oneRow(TriangleSetup input, SplitTrees trees, int piece, int y, int a, int b) {
        TriangleSetup one = segment;
        copy(input.qPlane, one.qPlane);
        int varyings = input.planeCount - 1;
        if (trees.kinds()[piece] == SplitTrees.PER_PIXEL) {
            for (int k = 1; k <= varyings; k++) {
                copy(input.planes[k], one.planes[k]);
            }
        } else {
            double[] planes = trees.planes();
            for (int k = 1, po = trees.planeStride() * piece; k <= varyings; k++, po += SplitTrees.PLANE) {
                Plane p = one.planes[k];
                p.base = planes[po];
                p.dx = planes[po + 1];
                p.dy = planes[po + 2];
            }
        }
        one.planeCount = input.planeCount;
        one.red16 = input.red16;
        one.green16 = input.green16;
        one.blue16 = input.blue16;
        one.colourKey = input.colourKey;
        one.firstColumn = trees.firstColumns()[piece];
        one.fixedPointSafe = false;
        one.rowStart = y;
        one.rowEnd = y + 1;
        segmentSpan[0] = a;
        segmentSpan[1] = b;
        return one;
    }

    private static void copy(Plane from, Plane to) {
        to.base = from.base;
        to.dx = from.dx;
        to.dy = from.dy;
    }

    /**
     * Adds 1 to {@code counts[y * width + x]} for each pixel of the set-up input triangle's spans that
     * the descent gives a piece (not {@link SplitTrees#NO_PIECE}).
     *
     * @return the number of pixels counted
     */
    long count(TriangleSetup setup, int[] spans, SplitTrees trees, int root, int nodes, int[] counts, int width) {
        int[] st = stackFor(nodes);
        long covered = 0;
        for (int y = setup.rowStart, j = 0; y < setup.rowEnd; y++, j += 2) {
            int a = spans[j];
            int b = spans[j + 1];
            if (a >= b) {
                continue;
            }
            int n = descend(root, a, b, y, trees, st, segments);
            for (int g = 0; g < n; g += 3) {
                for (int x = segments[g]; x < segments[g + 1]; x++) {
                    counts[y * width + x]++;
                }
                covered += segments[g + 1] - segments[g];
            }
        }
        return covered;
    }
}
