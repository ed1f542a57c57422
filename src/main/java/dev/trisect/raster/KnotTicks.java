package dev.trisect.raster;

import dev.trisect.render.Framebuffer;

/**
 * The span path's part of the border overlay: the knots, drawn as short vertical ticks. Knots lie on
 * every row, a few pixels to a few hundred apart; drawn on every row they would cover the image, so
 * only the rows in the middle of each band of {@link #ROW_SPACING} rows (8, 24, 40, ...) show theirs,
 * each knot as a tick {@code 2 * }{@link #HALF_HEIGHT}{@code + 1} pixels tall centred on its pixel.
 * The ticks' spacing along those rows is the knot spacing (dense where depth changes fast along a
 * row, one tick at each end where it does not), and the ticks of the rows between are left out.
 *
 * <p>The knots are those the fill placed ({@link KnotSpacing#next} from each row's first covered
 * column within the frame to its last). A tick pixel is drawn, like an outline pixel, where its
 * triangle's own 1/w plane is not behind the frame there (within {@link BorderOverlay}'s tolerance),
 * in the triangle's outline colour and opacity from the {@link OutlinePlan}; when colouring by bound,
 * in the bound colour of the larger Kamen–Shirman bound of the (one or two) segments the knot ends,
 * over the knot error: green for a short segment, yellow for one the bound limited. A tick never leaves
 * its band of rows (rows 6 to 10 of 16), so bands are drawn independently on any thread.
 *
 * <p>One per thread: it holds the triangle being ticked.
 */
public final class KnotTicks {
    /** Rows between two rows with ticks; ticked rows are those {@code ROW_SPACING / 2} mod this. */
    public static final int ROW_SPACING = 16;
    /** Pixels a tick reaches above and below its row. */
    public static final int HALF_HEIGHT = 2;
    /** Relative 1/w tolerance of the depth test, as the outlines'. */
    private static final double DEPTH_TOLERANCE = 1.0 / 512;

    private final TriangleSetup setup = new TriangleSetup();
    private final SpanSolver solver = new SpanSolver();

    /** Whether row {@code y} shows its knots. */
    public static boolean ticked(int y) {
        return Math.floorMod(y, ROW_SPACING) == ROW_SPACING / 2;
    }

    /**
     * Draws the knot ticks of the {@link Commands#TRIANGLE} commands of band {@code band} of
     * {@code list} (in order) on the ticked rows of rows [y0, y1), within those rows.
     *
     * @param plan     the outline plan of the list's triangles: which are outlined, in which colour and opacity
     * @param byBound  colour each tick by its segments' bound over {@code knotError}
     * @param knotError the span path's knot error, pixels
     * @return tick pixels drawn
     */
    public long draw(Framebuffer frame, Commands list, int band, OutlinePlan plan, boolean byBound, double knotError,
                     int y0, int y1) {
        long painted = 0;
        ScreenTriangles triangles = list.triangles();
        int[] items = list.bins().items();
        int from = list.bins().start(band);
        int to = list.bins().start(band + 1);
        int first = y0 + Math.floorMod(ROW_SPACING / 2 - y0, ROW_SPACING);
        for (int row = first; row < y1; row += ROW_SPACING) {
            for (int n = from; n < to; n++) {
                int command = list.command(items[n]);
                int tri = Commands.ref(command);
                if (Commands.kind(command) == Commands.TRIANGLE && plan.colours[tri] != 0
                        && setup.prepare(triangles, tri, true, 0, row, frame.width(), row + 1)) {
                    solver.walk(setup);
                    painted += row(frame, row, plan.colours[tri], plan.alpha(tri), byBound, knotError, y0, y1);
                }
            }
        }
        return painted;
    }

    /** The ticks of the set-up triangle's one row. */
    private long row(Framebuffer frame, int y, int colour, double alpha, boolean byBound, double knotError, int y0,
                     int y1) {
        int[] sp = solver.spans();
        int start = sp[0];
        int last = sp[1] - 1;
        if (start > last) {
            return 0;
        }
        double qDx = setup.qPlane.dx;
        double qRow = setup.qPlane.base + setup.qPlane.dy * y;
        double scale = KnotSpacing.scale(qDx, knotError);
        double offset = KnotSpacing.offset(qDx, knotError);
        double unbounded = KnotSpacing.unbounded(qDx, knotError);
        long painted = 0;
        double before = 0;
        for (int a = start; ; ) {
            double qa = qRow + qDx * a;
            int b = a < last ? KnotSpacing.next(a, qa, qRow, qDx, scale, offset, unbounded, last) : a;
            double after = b > a + 1 ? KnotSpacing.bound(qa, qRow + qDx * b, b - a) : 0;
            int c = byBound ? OverlayColours.bound(Math.max(before, after) / knotError) : colour;
            painted += tick(frame, a, y, c, alpha, y0, y1);
            if (b == a) {
                return painted;
            }
            before = after;
            a = b;
        }
    }

    /** One tick at column x of row y, clipped to rows [y0, y1). */
    private int tick(Framebuffer frame, int x, int y, int colour, double alpha, int y0, int y1) {
        int[] color = frame.colour();
        float[] depth = frame.depth();
        int width = frame.width();
        int painted = 0;
        for (int r = Math.max(y0, y - HALF_HEIGHT), end = Math.min(y1, y + HALF_HEIGHT + 1); r < end; r++) {
            int i = r * width + x;
            double q = setup.qPlane.base + setup.qPlane.dx * x + setup.qPlane.dy * r;
            if (!(q < depth[i] * (1 - DEPTH_TOLERANCE))) {
                color[i] = alpha >= 1 ? colour : BorderOverlay.blend(color[i], colour, alpha);
                painted++;
            }
        }
        return painted;
    }
}
