package dev.trisect.render;

import java.util.Locale;

/**
 * Where on an edge the tessellator cuts it (see {@code docs/math.md}, "Split points").
 *
 * <p>Every choice is a point of the 3D edge, so the new vertex lies exactly on the surface: with ends
 * A and B (clip space x, y, z, w and texel s, t) it is {@code (A * kA + B * kB) / (kA + kB)}, where the
 * weights depend only on the view depths {@code wA}, {@code wB}. Clip coordinates and texel coordinates
 * are both affine along the 3D edge, so the same weights give the point's exact texel coordinates.
 */
public enum SplitPoint {
    /** The 3D midpoint: {@code kA = kB = 1}, view depth (wA + wB) / 2. Halves the edge in space, not on screen. */
    MIDPOINT,
    /**
     * The point that projects to the middle of the edge on screen: {@code kA = wB, kB = wA}, view
     * depth 2 wA wB / (wA + wB). Every cut halves the edge's screen length, so its affine error
     * bound (never more than that length) halves with each level: the default.
     */
    SCREEN,
    /**
     * The point at the geometric mean depth: {@code kA = sqrt(wB), kB = sqrt(wA)}, view depth
     * sqrt(wA wB), on screen at {@code a pA + (1 - a) pB} with {@code a = sqrt(qB) / (sqrt(qA) + sqrt(qB))},
     * q = 1/w. Issue 6 proposed this screen point as the peak of the Kamen-Shirman error; the error
     * actually peaks at the mirror point {@code 1 - a} (see docs/math.md), which cuts next to the near
     * end and converges badly. Each cut halves the edge's depth ratio in logarithm.
     */
    GEOMETRIC;

    /**
     * The name used on the command line and in the demo.
     *
     * @return the split point's name on the command line
     */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }
}
