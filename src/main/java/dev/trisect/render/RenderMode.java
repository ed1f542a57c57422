package dev.trisect.render;

import java.util.Locale;

/** The three texturing paths (see {@code docs/math.md}). */
public enum RenderMode {
    /** Every pixel interpolates u/w, v/w and 1/w linearly on screen and divides: the exact mapping. */
    PERSPECTIVE,
    /** Every pixel interpolates u and v linearly on screen: fast, and visibly warped on a floor. */
    AFFINE,
    /** Triangles are split at edge midpoints until small, then each piece is filled affinely. */
    TESSELLATED;

    /** The name used on the command line: perspective, affine or tessellated. */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }
}
