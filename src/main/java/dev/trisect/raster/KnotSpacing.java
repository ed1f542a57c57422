package dev.trisect.raster;

/**
 * Where the span path puts its knots along a row (docs/math.md, "The span path"): the knots are
 * pixel centres where the texel coordinates are exact (perspective-correct), and between two knots
 * they are interpolated affinely. A segment from a knot at column {@code a} to one at {@code b}
 * shows at each pixel the texture of a point of the 3D segment between the two knots' surface
 * points, which projects onto the same row, so the displacement is horizontal and at most the
 * Kamen–Shirman bound of that segment,
 * <pre>
 *   E = L (sqrt(q_hi) - sqrt(q_lo)) / (sqrt(q_hi) + sqrt(q_lo)),   L = b - a,
 * </pre>
 * q the {@code 1/w} of the two knots. Along a row {@code q = q_a + g (x - a)} is linear, and with
 * {@code rho = sqrt(q_b / q_a)} this is {@code E = q_a (rho - 1)^2 / |g|}, so {@code E <= knotError}
 * exactly when {@code |rho - 1| <= delta = sqrt(knotError |g| / q_a)}, that is when
 * <pre>
 *   L &lt;= 2 sqrt(knotError q_a / |g|) + knotError   (g &gt; 0: the row comes nearer)
 *   L &lt;= 2 sqrt(knotError q_a / |g|) - knotError   (g &lt; 0: it recedes; any L when delta &gt;= 1)
 * </pre>
 * The next knot is the farthest column within that reach (at least the next column, at most
 * {@link #MAX_LENGTH} columns on), or the row's last covered column if that comes first: a shorter
 * segment from the same knot has a smaller bound, since E grows with L. Static and allocation-free: a pixel loop computes {@link #scale},
 * {@link #offset} and {@link #unbounded} once per triangle and calls {@link #next} at every knot.
 */
final class KnotSpacing {
    /**
     * The longest segment, pixels, even where the bound allows more (1/w constant along a row): the
     * pixel loops step texel coordinates in 32.32 fixed point with a step rounded to 2^-33 texel, so
     * a pixel of a segment is at most {@code MAX_LENGTH * 2^-33} texel (3e-8) from the exact chord,
     * which is below 0.001 px wherever a texel covers fewer than 33,000 pixels.
     */
    static final int MAX_LENGTH = 256;

    private KnotSpacing() {
    }

    /**
     * {@code 2 sqrt(knotError / |qDx|)}: the reach's factor of {@code sqrt(q)} (infinite when 1/w is
     * constant along rows).
     *
     * @param qDx      the change of 1/w per pixel along a row (view-space units^-1 per pixel)
     * @param knotError the largest displacement allowed, pixels, &gt; 0
     */
    static double scale(double qDx, double knotError) {
        return 2 * Math.sqrt(knotError / Math.abs(qDx));
    }

    /** {@code +knotError} when the rows come nearer to the right ({@code qDx > 0}), else {@code -knotError}. */
    static double offset(double qDx, double knotError) {
        return qDx > 0 ? knotError : -knotError;
    }

    /**
     * The 1/w at or below which a receding row's reach has no limit ({@code delta >= 1}, that is
     * {@code q <= knotError |qDx|}): minus infinity when the row does not recede.
     */
    static double unbounded(double qDx, double knotError) {
        return qDx < 0 ? -qDx * knotError : Double.NEGATIVE_INFINITY;
    }

    /**
     * The column of the knot after the one at column {@code a}, on a row whose 1/w at column x is
     * {@code qRow + qDx x} and whose last covered column is {@code last} (&gt; a): the farthest within
     * the reach {@code scale sqrt(q_a) + offset} (floored; at least a + 1, at most
     * {@link #MAX_LENGTH} on), or {@code last}. A knot
     * carries texel coordinates only where 1/w is positive: when the column chosen has none (a
     * centre covered just beyond the triangle's edge, where a plane nearly edge-on reaches 1/w = 0),
     * or the knot at a has none, the next column is the knot, so no pixel is interpolated towards it.
     */
    static int next(int a, double qa, double qRow, double qDx, double scale, double offset, double unbounded,
                    int last) {
        int remaining = Math.min(last - a, MAX_LENGTH);
        double reach = qa <= unbounded ? remaining : scale * Math.sqrt(qa) + offset;
        int b = reach >= remaining ? a + remaining : reach >= 2 ? a + (int) reach : a + 1;
        if (b > a + 1 && !(qRow + qDx * b > 0)) {
            return a + 1;
        }
        return b;
    }

    /**
     * The last knot at or before column {@code from} of a row whose knots start at column {@code first}
     * (a rectangle narrower than the frame may start inside a segment): knots from {@code first} by
     * {@link #next} until the next would pass {@code from}.
     */
    static int knotAtOrBefore(int from, int first, double qRow, double qDx, double scale, double offset,
                              double unbounded, int last) {
        int a = first;
        while (a < from) {
            int n = next(a, qRow + qDx * a, qRow, qDx, scale, offset, unbounded, last);
            if (n > from) {
                break;
            }
            a = n;
        }
        return a;
    }

    /**
     * The step per pixel from a knot's 32.32 fixed-point coordinate {@code from} to the next one's,
     * {@code length} pixels on: the difference over the length, rounded to the nearest unit (half up).
     */
    static long step(long from, long to, int length) {
        return Math.floorDiv(to - from + (length >> 1), length);
    }

    /**
     * The Kamen–Shirman bound of a segment of {@code length} pixels between knots with 1/w
     * {@code qa} and {@code qb} (both &gt; 0): the largest displacement, pixels, of a pixel between them.
     */
    static double bound(double qa, double qb, int length) {
        double ra = Math.sqrt(qa);
        double rb = Math.sqrt(qb);
        return length * Math.abs(ra - rb) / (ra + rb);
    }
}
