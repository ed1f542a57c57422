package dev.trisect.tessellate;

/**
 * The worst affine texturing error along an edge.
 *
 * <p>Along an edge of screen length {@code L} whose ends have view depths {@code w0} and {@code w1},
 * affine (screen-linear) interpolation shows the texture up to
 * {@code L * (1 - sqrt(a)) / (1 + sqrt(a))} pixels away from where perspective puts it, with
 * {@code a = min(w0, w1) / max(w0, w1)} (Kamen and Shirman, "Triangle rendering using adaptive
 * subdivision", IEEE CG&amp;A 18(2), 1998). {@code docs/math.md} derives it and proves that the worst
 * error over a whole triangle lies on one of its edges, so bounding the three edges bounds the
 * triangle.
 */
public final class EdgeBound {
    private EdgeBound() {
    }

    /**
     * @param length screen length of the edge, pixels (or texels, for the texel error)
     * @param w0     view depth of one end, view-space units, &gt; 0
     * @param w1     view depth of the other end, view-space units, &gt; 0
     * @return the largest displacement along the edge, in the units of {@code length}
     */
    public static double affineError(double length, double w0, double w1) {
        // (1 - sqrt(a)) / (1 + sqrt(a)) with a = lo/hi equals (sqrt(hi) - sqrt(lo)) / (sqrt(hi) + sqrt(lo)),
        // which needs no division by a possibly tiny depth and is symmetric in the two ends.
        double r0 = Math.sqrt(w0);
        double r1 = Math.sqrt(w1);
        return length * Math.abs(r0 - r1) / (r0 + r1);
    }
}
