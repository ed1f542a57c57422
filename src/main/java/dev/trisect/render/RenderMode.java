package dev.trisect.render;

import java.util.Locale;

/**
 * The four texturing paths (see {@code docs/math.md}), and what each does that the frame's stages ask
 * about: whether it divides by depth ({@link #divides}), splits triangles into pieces
 * ({@link #splits}) or places knots along rows ({@link #knots}).
 */
public enum RenderMode {
    /** Every pixel interpolates u/w, v/w and 1/w linearly on screen and divides: the exact mapping. */
    PERSPECTIVE(true, false, false),
    /** Every pixel interpolates u and v linearly on screen: fast, and visibly warped on a floor. */
    AFFINE(false, false, false),
    /**
     * Triangles are split at edge midpoints until small, then each piece is filled affinely: the split
     * policy and caps of {@link RenderSettings#tessellation()} decide the pieces.
     */
    TESSELLATED(false, true, false),
    /**
     * Along each row, texel coordinates exact (perspective-correct) at knots and interpolated affinely
     * between them, the knots spaced so that no pixel is displaced by more than
     * {@link RenderSettings#knotError()}: Quake's span subdivision, adaptive and with a proven bound.
     */
    SPANS(true, false, true);

    private final boolean divides;
    private final boolean splits;
    private final boolean knots;

    RenderMode(boolean divides, boolean splits, boolean knots) {
        this.divides = divides;
        this.splits = splits;
        this.knots = knots;
    }

    /**
     * Whether the path fills whole triangles from their perspective-correct planes (u/w, v/w, 1/w),
     * dividing at every pixel or at every knot: the per-pixel and span paths.
     *
     * @return true for {@link #PERSPECTIVE} and {@link #SPANS}
     */
    public boolean divides() {
        return divides;
    }

    /**
     * Whether the path splits triangles into pieces under the split policy (and so has pieces, a
     * per-pixel fallback, a piece budget and split levels above 0).
     *
     * @return true for {@link #TESSELLATED}
     */
    public boolean splits() {
        return splits;
    }

    /**
     * Whether the path divides only at knots along each row, spaced for {@link RenderSettings#knotError()}.
     *
     * @return true for {@link #SPANS}
     */
    public boolean knots() {
        return knots;
    }

    /**
     * The name used on the command line: perspective, affine, tessellated or spans.
     *
     * @return the mode's name on the command line
     */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }
}
