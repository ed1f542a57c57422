package dev.trisect.raster;

import dev.trisect.render.Framebuffer;

/**
 * Draws the outline of every filled triangle (every tessellated piece) over the frame, in yellow,
 * or in magenta for a piece filled per pixel by the fallback ({@link OverlayColours}), one band of
 * rows at a time from an {@link OutlinePlan}, so that it can run per band like the fill.
 *
 * <p>An edge lights the pixel nearest to it in every column (mostly horizontal edges) or row
 * (mostly vertical ones) whose centre lies within the edge's extent. The pixel is a function of the
 * edge and that column alone, and edges are walked from a canonical end, so a shared edge drawn from
 * either triangle and in any band lights the same pixels. A line pixel is drawn where the outlined
 * triangle's own depth plane is not behind what the frame holds there (within a small relative
 * tolerance), so outlines of hidden pieces stay hidden while the visible ones show on silhouettes.
 * An edge two triangles share is walked once (see {@link OutlinePlan}).
 */
public final class BorderOverlay {
    /** The colour of an ordinary piece's outline, #FFFF00. */
    public static final int YELLOW = OverlayColours.PIECE;

    /** Relative 1/w tolerance: a line pixel may lie this much behind the stored surface and still show. */
    static final double DEPTH_TOLERANCE = 1.0 / 512;

    /** The triangle whose turn it is to walk the edge: its 1/w plane, colour and opacity. */
    private double qBase;
    private double qDx;
    private double qDy;
    private double qMin;
    private double qMax;
    private int colour;
    private double alpha;
    /** The earlier triangle sharing the edge, applied first at each pixel, when {@link #shared}. */
    private boolean shared;
    private double qBaseEarlier;
    private double qDxEarlier;
    private double qDyEarlier;
    private double qMinEarlier;
    private double qMaxEarlier;
    private int colourEarlier;
    private double alphaEarlier;
    /**
     * Whether the edge's one or two outlines are opaque and not held to a depth range (no fading, no
     * fallback piece): then a pixel is the later outline's colour where its test passes, else the
     * earlier's where its test passes, with no blending or clamping to do.
     */
    private boolean simple;
    /** The frame being drawn: its colours, depths and width. */
    private int[] color;
    private float[] depth;
    private int width;

    /**
     * Outlines the edges of {@code plan}'s band {@code band} within pixels {@code [x0, x1) x [y0, y1)},
     * which must hold that band's rows lighting (x0 &gt;= 0).
     *
     * @return number of outline pixels drawn (each once, whether one or both triangles sharing its edge drew it)
     */
    public long draw(Framebuffer frame, OutlinePlan plan, int band, int x0, int y0, int x1, int y1) {
        double[] looks = plan.looks;
        int[] colours = plan.colours;
        int[] items = plan.bins.items();
        int[] walks = plan.walks;
        double[] lines = plan.lines;
        color = frame.colour();
        depth = frame.depth();
        width = frame.width();
        long painted = 0;
        int owner = -1;
        boolean ownerSimple = false;
        for (int n = plan.bins.start(band), end = plan.bins.start(band + 1); n < end; n++) {
            int edge = items[n];
            int w = OutlinePlan.WALK * edge;
            int tri = walks[w];
            // A triangle's edges follow one another: its outline's values stay.
            if (tri != owner) {
                owner = tri;
                int l = OutlinePlan.LOOK * tri;
                qBase = looks[l];
                qDx = looks[l + 1];
                qDy = looks[l + 2];
                qMin = looks[l + 3];
                qMax = looks[l + 4];
                alpha = looks[l + 5];
                colour = colours[tri];
                ownerSimple = simple(alpha, qMin, qMax);
            }
            int earlier = walks[w + 1];
            shared = earlier >= 0;
            if (shared) {
                int l = OutlinePlan.LOOK * earlier;
                qBaseEarlier = looks[l];
                qDxEarlier = looks[l + 1];
                qDyEarlier = looks[l + 2];
                qMinEarlier = looks[l + 3];
                qMaxEarlier = looks[l + 4];
                alphaEarlier = looks[l + 5];
                colourEarlier = colours[earlier];
            }
            simple = ownerSimple && (!shared || simple(alphaEarlier, qMinEarlier, qMaxEarlier));
            int first = walks[w + 2];
            int last = walks[w + 3];
            int crossFirst = walks[w + 4];
            int crossLast = walks[w + 5];
            int k = OutlinePlan.LINE * edge;
            double xa = lines[k];
            double ya = lines[k + 1];
            double slope = lines[k + 2];
            if (walks[w + 6] != 0) {
                painted += crossFirst >= y0 && crossLast < y1 && first >= x0 && last < x1
                        ? byColumnInside(frame, xa, ya, slope, first, last)
                        : byColumn(frame, xa, ya, slope, lines[k + 3], first, last, x0, y0, x1, y1);
            } else {
                int from = Math.max(y0, first);
                int to = Math.min(y1 - 1, last);
                painted += crossFirst >= x0 && crossLast < x1 ? byRowInside(frame, xa, ya, slope, from, to)
                        : byRow(frame, xa, ya, slope, from, to, x0, x1);
            }
        }
        return painted;
    }

    /**
     * Walks a mostly horizontal edge: in column c, the pixel on row floor(ya + (c + 0.5 - xa) * slope).
     * Only the columns whose rows can fall within [y0, y1) are visited, solved with the slope's
     * {@code inverse} and a column of margin; the exact test decides.
     */
    private int byColumn(Framebuffer frame, double xa, double ya, double slope, double inverse, int first, int last,
                         int x0, int y0, int x1, int y1) {
        double from = first;
        double to = last;
        if (slope != 0) {
            double c0 = xa - 0.5 + (y0 - ya) * inverse;
            double c1 = xa - 0.5 + (y1 - ya) * inverse;
            from = Math.max(from, Math.floor(Math.min(c0, c1)) - 1);
            to = Math.min(to, Math.ceil(Math.max(c0, c1)) + 1);
        }
        int c = (int) Math.max(from, x0);
        int end = (int) Math.min(to, x1 - 1);
        int painted = 0;
        for (; c <= end; c++) {
            double r = ya + (c + 0.5 - xa) * slope;
            // r >= y0 >= 0, so the cast floors.
            if (r >= y0 && r < y1) {
                painted += plot(frame, c, (int) r);
            }
        }
        return painted;
    }

    /** {@link #byColumn} for an edge whose pixels all lie within the band and the frame. */
    private int byColumnInside(Framebuffer frame, double xa, double ya, double slope, int first, int last) {
        if (simple) {
            return byColumnSimple(xa, ya, slope, first, last);
        }
        int painted = 0;
        for (int c = first; c <= last; c++) {
            // At least the edge's first row, >= 0, so the cast floors.
            painted += plot(frame, c, (int) (ya + (c + 0.5 - xa) * slope));
        }
        return painted;
    }

    /** {@link #byRow} for an edge whose pixels all lie within the frame's columns. */
    private int byRowInside(Framebuffer frame, double xa, double ya, double slope, int first, int last) {
        if (simple) {
            return byRowSimple(xa, ya, slope, first, last);
        }
        int painted = 0;
        for (int r = first; r <= last; r++) {
            painted += plot(frame, (int) (xa + (r + 0.5 - ya) * slope), r);
        }
        return painted;
    }

    /** Walks a mostly vertical edge over rows first..last: in row r, the pixel in column floor(xa + (r + 0.5 - ya) * slope). */
    private int byRow(Framebuffer frame, double xa, double ya, double slope, int first, int last, int x0, int x1) {
        int painted = 0;
        for (int r = first; r <= last; r++) {
            double c = xa + (r + 0.5 - ya) * slope;
            // c >= x0 >= 0, so the cast floors.
            if (c >= x0 && c < x1) {
                painted += plot(frame, (int) c, r);
            }
        }
        return painted;
    }

    /**
     * {@link #byColumnInside} of a {@link #simple} edge, {@link #plot} written into the loop. Each
     * value is the same double as there: column c and c + 0.5 are counted up exactly in doubles.
     */
    private int byColumnSimple(double xa, double ya, double slope, int first, int last) {
        int painted = 0;
        double x = first;
        for (int c = first; c <= last; c++, x++) {
            double y = Math.floor(ya + (x + 0.5 - xa) * slope);
            painted += plotSimple((int) y * width + c, x, y);
        }
        return painted;
    }

    /** {@link #byRowInside} of a {@link #simple} edge, as {@link #byColumnSimple}. */
    private int byRowSimple(double xa, double ya, double slope, int first, int last) {
        int painted = 0;
        double y = first;
        for (int r = first; r <= last; r++, y++) {
            double x = Math.floor(xa + (y + 0.5 - ya) * slope);
            painted += plotSimple(r * width + (int) x, x, y);
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

    /**
     * {@link #plot} of a {@link #simple} edge at pixel index {@code i}, column x and row y: what the
     * general case does when both outlines are opaque and not held.
     */
    private int plotSimple(int i, double x, double y) {
        double limit = depth[i] * (1 - DEPTH_TOLERANCE);
        if (!(qBase + qDx * x + qDy * y < limit)) {
            color[i] = colour;
            return 1;
        }
        if (shared && !(qBaseEarlier + qDxEarlier * x + qDyEarlier * y < limit)) {
            color[i] = colourEarlier;
            return 1;
        }
        return 0;
    }

    /** Whether an outline of opacity {@code a} held to 1/w range [min, max] is opaque and not held. */
    private static boolean simple(double a, double min, double max) {
        return a >= 1 && min == Double.NEGATIVE_INFINITY && max == Double.POSITIVE_INFINITY;
    }

    /**
     * Applies the earlier sharing triangle's outline, if any, then this one's at pixel (x, y). Where
     * this one's shows opaque it covers the earlier's, so the earlier's test is then spared.
     *
     * @return 1 when the pixel was drawn, else 0
     */
    private int plot(Framebuffer frame, int x, int y) {
        int i = y * width + x;
        if (simple) {
            return plotSimple(i, x, y);
        }
        double limit = depth[i] * (1 - DEPTH_TOLERANCE);
        boolean shows = !(held(qBase + qDx * x + qDy * y, qMin, qMax) < limit);
        if (shows && alpha >= 1) {
            color[i] = colour;
            return 1;
        }
        int painted = 0;
        if (shared && !(held(qBaseEarlier + qDxEarlier * x + qDyEarlier * y, qMinEarlier, qMaxEarlier) < limit)) {
            color[i] = alphaEarlier >= 1 ? colourEarlier : blend(color[i], colourEarlier, alphaEarlier);
            painted = 1;
        }
        if (shows) {
            color[i] = blend(color[i], colour, alpha);
            painted = 1;
        }
        return painted;
    }

    /** {@code q} held to [min, max] (see {@link OutlinePlan#looks}); NaN stays NaN. */
    private static double held(double q, double min, double max) {
        return q < min ? min : q > max ? max : q;
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
