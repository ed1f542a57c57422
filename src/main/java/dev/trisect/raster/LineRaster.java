package dev.trisect.raster;

/**
 * The loop of {@link Commands#LINE LINE} commands: segments set up by {@link LineSetup} drawn into
 * rows of a frame, depth-tested against what the rows hold; and, for one frame's lines on their own,
 * a store with its setup ({@link #begin}, {@link #add}, {@link #draw}).
 *
 * <p>Which pixels: per row, the columns inside the segment's parallelogram, solved exactly from its
 * (at most two) slanted edge functions; see {@link LineSetup} for the rule (OpenGL 1.x, section 3.4).
 *
 * <p>Depth (OpenGL 1.x, section 3.4.1: attributes of a line fragment are interpolated along the
 * segment): a fragment's 1/w is the segment's at the pixel centre's column (x-major) or row (y-major),
 * the same across the line's width, as llvmpipe interpolates. It is kept where it is not behind the
 * frame's ({@code GL_LEQUAL}: 1/w at least the stored one), and written with the colour.
 *
 * <p>Not thread-safe to set up; {@link #draw} and {@link #rows} may run on many threads at once over
 * distinct rows.
 */
public final class LineRaster {
    private static final int FIXED_ONE = LineSetup.FIXED_ONE;
    private static final int LSTRIDE = Segments.LSTRIDE;
    private static final int ISTRIDE = Segments.ISTRIDE;
    private static final int DSTRIDE = Segments.DSTRIDE;

    private final Segments segments = new Segments();
    private final LineSetup setup = new LineSetup();

    /**
     * Forgets every segment, for a frame of {@code width x height} pixels.
     *
     * @param width  pixels
     * @param height pixels
     */
    public void begin(int width, int height) {
        segments.begin(width, height);
    }

    /** Segments set up since {@link #begin} that may light a pixel. */
    public int count() {
        return segments.count();
    }

    /**
     * Sets up a segment, as {@link LineSetup#add} does into this raster's store.
     *
     * @return whether the segment may light a pixel of the frame
     */
    public boolean add(double x1, double y1, double q1, double x2, double y2, double q2, int lineWidth, int rgb) {
        return setup.add(segments, x1, y1, q1, x2, y2, q2, lineWidth, rgb);
    }

    /**
     * Draws every segment set up, in order, into frame rows {@code [y0, y1)}.
     *
     * @param color  the frame's colours, ARGB, row 0 at the top
     * @param depths the frame's 1/w
     * @return pixels written
     */
    public long draw(int[] color, float[] depths, int y0, int y1) {
        long written = 0;
        for (int s = 0; s < segments.count(); s++) {
            written += rows(segments, s, color, depths, y0, y1);
        }
        return written;
    }

    /**
     * Draws segment {@code s} of {@code segments} into its rows within {@code [y0, y1)}.
     *
     * @param color  the frame's colours, ARGB, row 0 at the top
     * @param depths the frame's 1/w
     * @return pixels written
     */
    public static long rows(Segments segments, int s, int[] color, float[] depths, int y0, int y1) {
        long written = 0;
        int i = ISTRIDE * s;
        int from = Math.max(y0, segments.ints[i + 2]);
        int to = Math.min(y1 - 1, segments.ints[i + 3]);
        for (int y = from; y <= to; y++) {
            written += row(segments, s, y, color, depths);
        }
        return written;
    }


    /** One row of segment s: its columns solved exactly from its slanted edges, then the depth test. */
    private static int row(Segments segments, int s, int y, int[] color, float[] depths) {
        int[] ints = segments.ints;
        long[] planes = segments.planes;
        double[] depth = segments.depth;
        int width = segments.width();
        int height = segments.height();
        int i = ISTRIDE * s;
        long lo = ints[i];
        long hi = ints[i + 1];
        long gy = (long) (height - 1 - y) * FIXED_ONE;
        int l = LSTRIDE * s;
        int varying = ints[i + 5] >> 1;
        for (int e = 0; e < varying; e++) {
            long a = planes[l + 3 * e + 1] * FIXED_ONE;
            long c = planes[l + 3 * e] + planes[l + 3 * e + 2] * gy;
            // Inside: c - a * col >= 1 (a is not 0 for a slanted edge).
            if (a > 0) {
                hi = Math.min(hi, floorDiv(c - 1, a));
            } else {
                lo = Math.max(lo, -floorDiv(1 - c, a));
            }
        }
        if (lo > hi) {
            return 0;
        }
        int d = DSTRIDE * s;
        double origin = depth[d];
        double q0 = depth[d + 1];
        double step = depth[d + 2];
        int rgb = ints[i + 4];
        int base = y * width;
        int written = 0;
        if ((ints[i + 5] & 1) == 1) {
            for (int x = (int) lo; x <= hi; x++) {
                float q = (float) (q0 + (x + 0.5 - origin) * step);
                int at = base + x;
                if (q >= depths[at]) {
                    depths[at] = q;
                    color[at] = rgb;
                    written++;
                }
            }
        } else {
            float q = (float) (q0 + (height - y - 0.5 - origin) * step);
            for (int x = (int) lo; x <= hi; x++) {
                int at = base + x;
                if (q >= depths[at]) {
                    depths[at] = q;
                    color[at] = rgb;
                    written++;
                }
            }
        }
        return written;
    }

    /**
     * {@code floor(n / d)} for {@code d != 0} and {@code |n| < 2^53}: by a double division, off by at
     * most one, then corrected exactly (a long division costs several times more).
     */
    private static long floorDiv(long n, long d) {
        long q = (long) Math.floor((double) n / d);
        long r = n - q * d;
        if (d > 0) {
            q += r < 0 ? -1 : r >= d ? 1 : 0;
        } else {
            q += r > 0 ? -1 : r <= d ? 1 : 0;
        }
        return q;
    }
}
