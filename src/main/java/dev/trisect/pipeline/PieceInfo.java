package dev.trisect.pipeline;

import dev.trisect.tessellate.Slivers;

/**
 * One filled triangle of the last frame (a tessellated piece, or a clipped triangle in the other
 * paths), as the pixel inspector shows it.
 *
 * @param index    its position among the frame's filled triangles, in drawing order
 * @param triangle the input triangle it came from, 0-based
 * @param level    split level: times its most-halved edge was halved (0 unsplit)
 * @param fallback filled per pixel (perspective-correct): a sliver, or a cap stopped its splitting short
 * @param screen   corners x0, y0, x1, y1, x2, y2, screen pixels
 * @param attributes per corner 1/w, s, t (view-space units^-1, level-0 texels)
 * @param colours  per corner the lit colour r, g, b (0..1) of a frame that carries one, else null
 */
public record PieceInfo(int index, int triangle, int level, boolean fallback, double[] screen, double[] attributes,
                        double[] colours) {

    /** A piece of a frame without colours. */
    public PieceInfo(int index, int triangle, int level, boolean fallback, double[] screen, double[] attributes) {
        this(index, triangle, level, fallback, screen, attributes, null);
    }

    /**
     * The colour r, g, b at screen point (x, y) as the fill interpolates it: perspective-correctly
     * (weighted by each corner's 1/w), or screen-linearly; null without colours.
     */
    public double[] colourAt(double x, double y, boolean perspective) {
        if (colours == null) {
            return null;
        }
        double[] p = screen;
        double det = (p[2] - p[0]) * (p[5] - p[1]) - (p[4] - p[0]) * (p[3] - p[1]);
        double b1 = ((x - p[0]) * (p[5] - p[1]) - (p[4] - p[0]) * (y - p[1])) / det;
        double b2 = ((p[2] - p[0]) * (y - p[1]) - (x - p[0]) * (p[3] - p[1])) / det;
        double[] w = {1 - b1 - b2, b1, b2};
        if (perspective) {
            double sum = 0;
            for (int k = 0; k < 3; k++) {
                w[k] *= attributes[3 * k];
                sum += w[k];
            }
            for (int k = 0; k < 3; k++) {
                w[k] /= sum;
            }
        }
        double[] c = new double[3];
        for (int k = 0; k < 3; k++) {
            for (int ch = 0; ch < 3; ch++) {
                c[ch] += w[k] * colours[3 * k + ch];
            }
        }
        return c;
    }

    /** Whether it is a sliver by the tessellator's rule ({@link Slivers#sliver}): thinner than 1/16 px. */
    public boolean sliver() {
        return Slivers.sliver(screen[0], screen[1], screen[2], screen[3], screen[4], screen[5]);
    }

    /**
     * The level-0 texel coordinates' screen derivatives over this piece as its affine fill sees them:
     * {ds/dx, dt/dx, ds/dy, dt/dy}, texels per pixel.
     */
    public double[] affineDerivatives() {
        double[] p = screen;
        double[] a = attributes;
        double ex1 = p[2] - p[0];
        double ey1 = p[3] - p[1];
        double ex2 = p[4] - p[0];
        double ey2 = p[5] - p[1];
        double det = ex1 * ey2 - ex2 * ey1;
        double ds1 = a[4] - a[1];
        double ds2 = a[7] - a[1];
        double dt1 = a[5] - a[2];
        double dt2 = a[8] - a[2];
        // Plane slopes by Cramer's rule: value(x, y) = v0 + dx * (x - x0) + dy * (y - y0).
        return new double[] {(ds1 * ey2 - ds2 * ey1) / det, (dt1 * ey2 - dt2 * ey1) / det,
            (ex1 * ds2 - ex2 * ds1) / det, (ex1 * dt2 - ex2 * dt1) / det};
    }
}
