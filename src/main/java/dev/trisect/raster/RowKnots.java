package dev.trisect.raster;

import java.util.Arrays;

/**
 * The knots of one row of one screen triangle in the span path, as the fill places them: for the
 * pixel inspector, which shows the segments of the inspected row. Allocates; one query at a time.
 *
 * @param y       the row
 * @param columns the knot columns, ascending: the row's first covered column within the frame, ...,
 *                its last (one column for a row of one pixel; none when the triangle covers no pixel
 *                of the row within the frame)
 * @param bounds  per segment (between {@code columns[k]} and {@code columns[k + 1]}), the Kamen–Shirman
 *                bound of its pixels' displacement, pixels (0 for adjacent knots)
 */
public record RowKnots(int y, int[] columns, double[] bounds) {
    /**
     * The knots of row {@code y} of triangle {@code tri} of {@code triangles} in a frame {@code width}
     * pixels wide, spaced for {@code knotError} pixels.
     */
    public static RowKnots of(ScreenTriangles triangles, int tri, int width, int y, double knotError) {
        TriangleSetup setup = new TriangleSetup();
        if (!setup.prepare(triangles, tri, true, 0, y, width, y + 1)) {
            return new RowKnots(y, new int[0], new double[0]);
        }
        SpanSolver solver = new SpanSolver();
        solver.walk(setup);
        int first = solver.spans()[0];
        int last = solver.spans()[1] - 1;
        if (first > last) {
            return new RowKnots(y, new int[0], new double[0]);
        }
        double qDx = setup.qPlane.dx;
        double qRow = setup.qPlane.base + setup.qPlane.dy * y;
        double scale = KnotSpacing.scale(qDx, knotError);
        double offset = KnotSpacing.offset(qDx, knotError);
        double unbounded = KnotSpacing.unbounded(qDx, knotError);
        int[] columns = new int[16];
        double[] bounds = new double[16];
        int n = 0;
        for (int a = first; ; ) {
            if (n == columns.length) {
                columns = Arrays.copyOf(columns, 2 * n);
                bounds = Arrays.copyOf(bounds, 2 * n);
            }
            columns[n] = a;
            if (a == last) {
                n++;
                break;
            }
            double qa = qRow + qDx * a;
            int b = KnotSpacing.next(a, qa, qRow, qDx, scale, offset, unbounded, last);
            bounds[n++] = b > a + 1 ? KnotSpacing.bound(qa, qRow + qDx * b, b - a) : 0;
            a = b;
        }
        return new RowKnots(y, Arrays.copyOf(columns, n), Arrays.copyOf(bounds, n - 1));
    }

    /** The index of the segment holding column x (the last knot at or before it), or -1 outside the row. */
    public int segmentOf(int x) {
        if (columns.length == 0 || x < columns[0] || x > columns[columns.length - 1]) {
            return -1;
        }
        int k = Arrays.binarySearch(columns, x);
        int at = k >= 0 ? k : -k - 2;
        return Math.min(at, bounds.length - 1);
    }
}
