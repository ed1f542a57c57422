package dev.trisect.raster;

/**
 * Draws the outline of every filled triangle (every tessellated piece) over the frame, in yellow,
 * or in magenta for a piece filled per pixel by the fallback ({@link OverlayColours}), restricted to a
 * rectangle so that it can run per band like the fill.
 *
 * <p>An edge lights the pixel nearest to it in every column (mostly horizontal edges) or row
 * (mostly vertical ones) whose centre lies within the edge's extent. The pixel is a function of the
 * edge and that column alone, and edges are walked from a canonical end, so a shared edge drawn from
 * either triangle and in any band lights the same pixels. A line pixel is drawn where the outlined
 * triangle's own depth plane is not behind what the frame holds there (within a small relative
 * tolerance), so outlines of hidden pieces stay hidden while the visible ones show on silhouettes.
 */
public final class BorderOverlay {
    /** The colour of an ordinary piece's outline, #FFFF00. */
    public static final int YELLOW = OverlayColours.PIECE;

    /** Relative 1/w tolerance: a line pixel may lie this much behind the stored surface and still show. */
    private static final double DEPTH_TOLERANCE = 1.0 / 512;

    private final Plane depth = new Plane();
    /** Outline colour of the triangle being drawn. */
    private int colour = YELLOW;
    /** Opacity of the triangle being drawn, 0..1, and its screen area in square pixels. */
    private double alpha = 1;
    private double area;

    /**
     * Outlines triangles {@code order[from..to)} within pixels {@code [x0, x1) x [y0, y1)}.
     *
     * @return number of pixels painted
     */
    public long draw(Framebuffer frame, ScreenTriangles triangles, int[] order, int from, int to,
                     int x0, int y0, int x1, int y1) {
        return draw(frame, triangles, order, from, to, x0, y0, x1, y1, BorderStyle.plain(), 0, 1);
    }

    /**
     * Outlines triangles {@code order[from..to)} within pixels {@code [x0, x1) x [y0, y1)} in a style.
     *
     * @param maxLevel the depth cap, drawn red when colouring by depth
     * @param maxError the Max error threshold in pixels, drawn yellow when colouring by bound
     * @return number of pixels painted
     */
    public long draw(Framebuffer frame, ScreenTriangles triangles, int[] order, int from, int to,
                     int x0, int y0, int x1, int y1, BorderStyle style, int maxLevel, double maxError) {
        int[] f = triangles.fixed();
        long painted = 0;
        for (int n = from; n < to; n++) {
            int tri = order[n];
            if (style.onlyFallback() && !triangles.perPixel()[tri] || !depthPlane(triangles, tri)) {
                continue;
            }
            colour = style.colouring() == BorderStyle.Colouring.YELLOW ? OverlayColours.of(triangles, tri)
                    : OverlayColours.of(triangles, tri, style.colouring(), maxLevel, maxError);
            alpha = style.fade() ? fadeAlpha(area, perimeter(triangles, tri)) : 1;
            int o = tri * ScreenTriangles.FIXED_STRIDE;
            for (int e = 0; e < 3; e++) {
                int a = o + 2 * e;
                int b = o + 2 * ((e + 1) % 3);
                painted += line(frame, f[a], f[a + 1], f[b], f[b + 1], x0, y0, x1, y1);
            }
        }
        return painted;
    }

    /** Pieces whose inscribed circle has at least this radius, pixels, are outlined opaque when fading. */
    static final double FADE_RADIUS = 2;
    /** The faintest a faded outline gets, so that even the smallest pieces still show a trace. */
    static final double MIN_ALPHA = 0.02;

    /**
     * Opacity of a faded outline for a piece of {@code area} square pixels and {@code perimeter}
     * pixels: the square of its inscribed circle's radius {@code 2 * area / perimeter} over {@link #FADE_RADIUS}. The
     * outline covers about {@code perimeter} pixels of the piece's {@code area}, so the share of line
     * ink is about {@code 1 / radius}: fading by the radius keeps the ink per pixel level, and the
     * texture readable, where pieces crowd or thin to slivers near the horizon.
     */
    static double fadeAlpha(double area, double perimeter) {
        if (!(perimeter > 0)) {
            return 1;
        }
        double r = Math.min(1, 2 * area / perimeter / FADE_RADIUS);
        // Squared: where pieces are far thinner than a pixel, many outlines stack on each pixel, and
        // their opacities add up.
        return Math.max(MIN_ALPHA, r * r);
    }

    /** The 1/w plane over pixel centres; false for a triangle with no area. */
    private boolean depthPlane(ScreenTriangles triangles, int tri) {
        double[] sc = triangles.screen();
        double[] at = triangles.attributes();
        int s = tri * ScreenTriangles.SCREEN_STRIDE;
        int a = tri * ScreenTriangles.ATTRIBUTE_STRIDE;
        double x0 = sc[s];
        double y0 = sc[s + 1];
        double ex1 = sc[s + 2] - x0;
        double ey1 = sc[s + 3] - y0;
        double ex2 = sc[s + 4] - x0;
        double ey2 = sc[s + 5] - y0;
        double det = ex1 * ey2 - ex2 * ey1;
        if (det == 0 || !Double.isFinite(det)) {
            return false;
        }
        area = Math.abs(det) / 2;
        depth.fit(x0, y0, ex1, ey1, ex2, ey2, 1 / det, at[a], at[a + 3], at[a + 6]);
        return true;
    }

    private long line(Framebuffer frame, long ax, long ay, long bx, long by, int x0, int y0, int x1, int y1) {
        // Canonical direction: from the smaller (x, y) end, so both triangles sharing the edge agree.
        if (ax > bx || (ax == bx && ay > by)) {
            long t = ax;
            ax = bx;
            bx = t;
            t = ay;
            ay = by;
            by = t;
        }
        double xa = ax / (double) FixedPoint.ONE;
        double ya = ay / (double) FixedPoint.ONE;
        double xb = bx / (double) FixedPoint.ONE;
        double yb = by / (double) FixedPoint.ONE;
        double dx = xb - xa;
        double dy = yb - ya;
        long painted = 0;
        if (Math.abs(dx) >= Math.abs(dy)) {
            if (dx == 0) {
                return 0;
            }
            double slope = dy / dx;
            int first = Math.max(x0, (int) Math.ceil(xa - 0.5));
            int last = Math.min(x1 - 1, (int) Math.floor(xb - 0.5));
            for (int c = first; c <= last; c++) {
                int r = (int) Math.floor(ya + (c + 0.5 - xa) * slope);
                if (r >= y0 && r < y1) {
                    painted += plot(frame, c, r);
                }
            }
        } else {
            double slope = dx / dy;
            double yLow = Math.min(ya, yb);
            double yHigh = Math.max(ya, yb);
            int first = Math.max(y0, (int) Math.ceil(yLow - 0.5));
            int last = Math.min(y1 - 1, (int) Math.floor(yHigh - 0.5));
            for (int r = first; r <= last; r++) {
                int c = (int) Math.floor(xa + (r + 0.5 - ya) * slope);
                if (c >= x0 && c < x1) {
                    painted += plot(frame, c, r);
                }
            }
        }
        return painted;
    }

    private int plot(Framebuffer frame, int x, int y) {
        int i = y * frame.width() + x;
        double q = depth.base + depth.dx * x + depth.dy * y;
        if (q < frame.depth()[i] * (1 - DEPTH_TOLERANCE)) {
            return 0;
        }
        if (alpha >= 1) {
            frame.color()[i] = colour;
        } else {
            frame.color()[i] = blend(frame.color()[i], colour, alpha);
        }
        return 1;
    }

    private static double perimeter(ScreenTriangles triangles, int tri) {
        double[] sc = triangles.screen();
        int s = tri * ScreenTriangles.SCREEN_STRIDE;
        return Math.hypot(sc[s + 2] - sc[s], sc[s + 3] - sc[s + 1]) + Math.hypot(sc[s + 4] - sc[s + 2],
                sc[s + 5] - sc[s + 3]) + Math.hypot(sc[s] - sc[s + 4], sc[s + 1] - sc[s + 5]);
    }

    /** {@code over} laid on {@code under} with opacity {@code a}, per sRGB channel, opaque result. */
    static int blend(int under, int over, double a) {
        int out = 0xFF000000;
        for (int shift = 16; shift >= 0; shift -= 8) {
            int u = under >> shift & 0xFF;
            int o = over >> shift & 0xFF;
            out |= (int) (u + (o - u) * a + 0.5) << shift;
        }
        return out;
    }
}
