package dev.trisect.raster;

import dev.trisect.render.Framebuffer;

/**
 * The loop of {@link Commands#LINE LINE} commands: segments set up by {@link LineSetup} drawn into
 * rows of a frame, depth-tested against what the rows hold; and, for one frame's lines on their own,
 * a store with its setup ({@link #begin}, {@link #add}, {@link #draw}).
 *
 * <p>Which pixels: a store's segments follow one of two coverage rules ({@link Segments#rule()}). A
 * frame's lines follow OpenGL's ({@link Segments#DIAMOND DIAMOND}): per row, the columns inside the
 * segment's parallelogram, solved exactly from its (at most two) slanted edge functions; see
 * {@link LineSetup} for the rule (OpenGL 1.x, section 3.4). The border overlay's edges follow their
 * own ({@link Segments#CROSSING CROSSING}, {@link LineCrossing}), which {@link #band} dispatches to;
 * the rest of this comment is about the first.
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
     * Draws band {@code band}'s segments of {@code segments}, binned by {@code bins} (a list of line
     * segments alone, with no command word each), into rows {@code [y0, y1)} of {@code frame}: as
     * {@link #rows} for each, the store's rule read once for the band. A {@link Segments#CROSSING
     * CROSSING} store is the border overlay's, drawn through its write {@code crossing}.
     *
     * @return pixels written
     */
    public static long band(Segments segments, BandBins bins, int band, Framebuffer frame, BorderOverlay crossing,
                            int y0, int y1) {
        if (segments.rule() == Segments.CROSSING) {
            crossing.frame(frame);
            return LineCrossing.band(segments, bins, band, crossing, frame.width(), y0, y1);
        }
        int[] items = bins.items();
        long written = 0;
        for (int k = bins.start(band), end = bins.start(band + 1); k < end; k++) {
            written += rows(segments, items[k], frame.colour(), frame.depth(), y0, y1);
        }
        return written;
    }

    /**
     * Draws {@link Segments#DIAMOND DIAMOND} segment {@code s} of {@code segments} into its rows within
     * {@code [y0, y1)}.
     *
     * @param color  the frame's colours, ARGB, row 0 at the top
     * @param depths the frame's 1/w
     * @return pixels written
     */
    public static long rows(Segments segments, int s, int[] color, float[] depths, int y0, int y1) {
        if (segments.rule() != Segments.DIAMOND) {
            throw new IllegalArgumentException("a CROSSING segment is drawn with the overlay's write: LineRaster.band");
        }
        int[] ints = segments.ints;
        long[] planes = segments.planes;
        int i = ISTRIDE * s;
        int from = Math.max(y0, ints[i + 2]);
        int to = Math.min(y1 - 1, ints[i + 3]);
        if (from > to) {
            return 0;
        }
        int width = segments.width();
        int height = segments.height();
        int l = LSTRIDE * s;
        int slanted = ints[i + 5] >> 1;
        // Each slanted edge bounds the columns by Q = floor((c - 1) / |a|) (a > 0: col <= Q; a < 0:
        // col >= -Q), c = c0 + dcdy * gy falling by dcdy * 256 a row: Q is stepped exactly from row to
        // row (quotient and remainder, as a DDA), one division per edge for the first row.
        long q0 = 0;
        long r0 = 0;
        long a0 = 1;
        long bq0 = 0;
        long br0 = 0;
        long q1 = 0;
        long r1 = 0;
        long a1 = 1;
        long bq1 = 0;
        long br1 = 0;
        long gy = (long) (height - 1 - from) * FIXED_ONE;
        if (slanted > 0) {
            a0 = Math.abs(planes[l + 1] * FIXED_ONE);
            long n = planes[l] + planes[l + 2] * gy - 1;
            q0 = floorDiv(n, a0);
            r0 = n - q0 * a0;
            long b = planes[l + 2] * FIXED_ONE;
            bq0 = floorDiv(b, a0);
            br0 = b - bq0 * a0;
        }
        if (slanted > 1) {
            a1 = Math.abs(planes[l + 4] * FIXED_ONE);
            long n = planes[l + 3] + planes[l + 5] * gy - 1;
            q1 = floorDiv(n, a1);
            r1 = n - q1 * a1;
            long b = planes[l + 5] * FIXED_ONE;
            bq1 = floorDiv(b, a1);
            br1 = b - bq1 * a1;
        }
        boolean right0 = slanted > 0 && planes[l + 1] > 0;
        boolean right1 = slanted > 1 && planes[l + 4] > 0;
        int d = DSTRIDE * s;
        double[] depth = segments.depth;
        double origin = depth[d];
        double qStart = depth[d + 1];
        double step = depth[d + 2];
        int rgb = ints[i + 4];
        boolean xMajor = (ints[i + 5] & 1) == 1;
        long written = 0;
        for (int y = from; y <= to; y++) {
            long lo = ints[i];
            long hi = ints[i + 1];
            if (slanted > 0) {
                if (right0) {
                    hi = Math.min(hi, q0);
                } else {
                    lo = Math.max(lo, -q0);
                }
                q0 -= bq0;
                r0 -= br0;
                if (r0 < 0) {
                    r0 += a0;
                    q0--;
                }
            }
            if (slanted > 1) {
                if (right1) {
                    hi = Math.min(hi, q1);
                } else {
                    lo = Math.max(lo, -q1);
                }
                q1 -= bq1;
                r1 -= br1;
                if (r1 < 0) {
                    r1 += a1;
                    q1--;
                }
            }
            if (lo > hi) {
                continue;
            }
            int base = y * width;
            if (xMajor) {
                for (int x = (int) lo; x <= hi; x++) {
                    float q = (float) (qStart + (x + 0.5 - origin) * step);
                    int at = base + x;
                    if (q >= depths[at]) {
                        depths[at] = q;
                        color[at] = rgb;
                        written++;
                    }
                }
            } else {
                float q = (float) (qStart + (height - y - 0.5 - origin) * step);
                for (int at = base + (int) lo, end = base + (int) hi; at <= end; at++) {
                    if (q >= depths[at]) {
                        depths[at] = q;
                        color[at] = rgb;
                        written++;
                    }
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
