package dev.trisect.render;

import java.util.Locale;

/** The four texturing paths (see {@code docs/math.md}). */
public enum RenderMode {
    /** Every pixel interpolates u/w, v/w and 1/w linearly on screen and divides: the exact mapping. */
    PERSPECTIVE,
    /** Every pixel interpolates u and v linearly on screen: fast, and visibly warped on a floor. */
    AFFINE,
    /** Triangles are split at edge midpoints until small, then each piece is filled affinely. */
    TESSELLATED,
    /**
     * Along each row, texel coordinates exact (perspective-correct) at knots and interpolated affinely
     * between them, the knots spaced so that no pixel is displaced by more than the tessellation
     * settings' {@link TessellationSettings#maxError maxError}: Quake's span subdivision, adaptive and
     * with a proven bound.
     */
    SPANS;

    /**
     * The name used on the command line: perspective, affine, tessellated or spans.
     *
     * @return the mode's name on the command line
     */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }
}
