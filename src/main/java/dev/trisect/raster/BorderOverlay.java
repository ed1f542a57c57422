package dev.trisect.raster;

import dev.trisect.render.Framebuffer;

/**
 * The border overlay's write: what a pixel of an outline gets. The outline of every filled triangle
 * (every tessellated piece) is drawn over the frame, in yellow, or in magenta for a piece filled per
 * pixel by the fallback ({@link OverlayColours}); its edges are line segments of an
 * {@link OutlinePlan}, whose pixels the line rasterizer's {@link Segments#CROSSING CROSSING} rule gives
 * ({@link LineCrossing}); this class decides each of those pixels, for {@link LineRaster#band}.
 *
 * <p>A line pixel is drawn where the outlined triangle's own depth plane is not behind what the frame
 * holds there (within a small relative tolerance), so outlines of hidden pieces stay hidden while the
 * visible ones show on silhouettes; no depth is written. An edge two triangles share is walked once
 * (see {@link OutlinePlan}): the earlier triangle's outline is applied first at each pixel, then the
 * later one's, each with its own test, colour and opacity.
 *
 * <p>One instance per thread: it holds the edge being drawn.
 */
public final class BorderOverlay {
    /** The colour of an ordinary piece's outline, #FFFF00. */
    public static final int YELLOW = OverlayColours.PIECE;

    /** Relative 1/w tolerance: a line pixel may lie this much behind the stored surface and still show. */
    static final double DEPTH_TOLERANCE = 1.0 / 512;

    /** The triangle whose turn it is to walk the edge. */
    private final Look later = new Look();
    /** The earlier triangle sharing the edge, applied first at each pixel, when {@link #shared}. */
    private final Look earlier = new Look();
    private boolean shared;
    /**
     * Whether the edge's one or two outlines are opaque and not held to a depth range (no fading, no
     * fallback piece): then a pixel is the later outline's colour where its test passes, else the
     * earlier's where its test passes, with no blending or clamping to do.
     */
    boolean simple;
    /** The triangle whose outline values are loaded, and its plan's looks. */
    private int owner = -1;
    private double[] ownerLooks;
    /** The frame being drawn: its colours, depths and width. */
    private int[] color;
    private float[] depth;
    int width;

    /**
     * Draws {@code plan}'s outlines within band {@code band}, rows {@code [y0, y1)} of {@code frame}:
     * its edges, by the line rasterizer ({@link LineRaster#band}) with this write.
     *
     * @return number of outline pixels drawn (each once, whether one or both triangles sharing its edge drew it)
     */
    public long draw(Framebuffer frame, OutlinePlan plan, int band, int y0, int y1) {
        return LineRaster.band(plan.segments(), plan.bins(), band, frame, this, y0, y1);
    }

    /**
     * Makes the outlines drawn next go into {@code frame}; forgets the outline values loaded (a plan
     * is prepared afresh for every frame).
     */
    void frame(Framebuffer frame) {
        owner = -1;
        ownerLooks = null;
        color = frame.colour();
        depth = frame.depth();
        width = frame.width();
    }

    /**
     * Makes the edge about to be drawn triangle {@code tri}'s of {@code plan}, shared with its
     * {@code earlierTri} triangle (or {@link OutlinePlan#ALONE}). A triangle's edges follow one another,
     * so its outline's values are loaded only when the triangle changes.
     */
    void edge(OutlinePlan plan, int tri, int earlierTri) {
        if (tri != owner || plan.looks != ownerLooks) {
            owner = tri;
            ownerLooks = plan.looks;
            later.load(plan, tri);
        }
        shared = earlierTri >= 0;
        if (shared) {
            earlier.load(plan, earlierTri);
        }
        simple = later.simple() && (!shared || earlier.simple());
    }

    /** One outlined triangle's values from its plan ({@link OutlinePlan#looks}): 1/w plane, range, colour, opacity. */
    private static final class Look {
        double qBase;
        double qDx;
        double qDy;
        double qMin;
        double qMax;
        double alpha;
        int colour;

        void load(OutlinePlan plan, int tri) {
            int l = OutlinePlan.LOOK * tri;
            qBase = plan.looks[l];
            qDx = plan.looks[l + 1];
            qDy = plan.looks[l + 2];
            qMin = plan.looks[l + 3];
            qMax = plan.looks[l + 4];
            alpha = plan.looks[l + 5];
            colour = plan.colours[tri];
        }

        /** The triangle's 1/w at pixel centre (x, y), not yet held to its range. */
        double q(double x, double y) {
            return qBase + qDx * x + qDy * y;
        }

        /** Opaque and not held to a depth range: see {@link BorderOverlay#simple}. */
        boolean simple() {
            return alpha >= 1 && qMin == Double.NEGATIVE_INFINITY && qMax == Double.POSITIVE_INFINITY;
        }
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
    int plotSimple(int i, double x, double y) {
        double limit = depth[i] * (1 - DEPTH_TOLERANCE);
        Look l = later;
        if (!(l.q(x, y) < limit)) {
            color[i] = l.colour;
            return 1;
        }
        Look e = earlier;
        if (shared && !(e.q(x, y) < limit)) {
            color[i] = e.colour;
            return 1;
        }
        return 0;
    }

    /**
     * Applies the earlier sharing triangle's outline, if any, then this one's at pixel (x, y). Where
     * this one's shows opaque it covers the earlier's, so the earlier's test is then spared.
     *
     * @return 1 when the pixel was drawn, else 0
     */
    int plot(int x, int y) {
        int i = y * width + x;
        if (simple) {
            return plotSimple(i, x, y);
        }
        double limit = depth[i] * (1 - DEPTH_TOLERANCE);
        Look l = later;
        boolean shows = !(held(l.q(x, y), l.qMin, l.qMax) < limit);
        if (shows && l.alpha >= 1) {
            color[i] = l.colour;
            return 1;
        }
        int painted = 0;
        Look e = earlier;
        if (shared && !(held(e.q(x, y), e.qMin, e.qMax) < limit)) {
            color[i] = e.alpha >= 1 ? e.colour : blend(color[i], e.colour, e.alpha);
            painted = 1;
        }
        if (shows) {
            color[i] = blend(color[i], l.colour, l.alpha);
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
