package dev.trisect.pipeline;

import static dev.trisect.tessellate.VertexLayout.W;
import static dev.trisect.tessellate.VertexLayout.X;
import static dev.trisect.tessellate.VertexLayout.Y;
import static dev.trisect.tessellate.VertexLayout.Z;

import dev.trisect.tessellate.VertexLayout;

/**
 * Clips a triangle in homogeneous clip space (Sutherland-Hodgman), before the divide by w.
 *
 * <p>Planes: near {@code z >= -w} and far {@code z <= w} exactly as OpenGL; left/right/bottom/top
 * against a guard band {@code |x| <= gx * w}, {@code |y| <= gy * w} that lies far outside the
 * viewport. Clipping x and y only at the guard band creates no new edge on screen, so the pixels are
 * those of clipping at the frustum sides, while screen coordinates stay small enough for exact
 * fixed-point edge functions.
 *
 * <p>An intersection is always computed from the edge's inside end toward its outside end, so the two
 * triangles that share an edge get bit-identical new vertices and the clipped mesh keeps no cracks.
 * Vertices are {@link VertexLayout#clipStride()} doubles of the layout set ({@link #layout}): clip x, y, z, w and
 * the varyings (texel s, t first), the tessellator's input; every slot is interpolated alike.
 *
 * <p>An intersection {@code in + t (out - in)} of an edge whose ends are far larger than the new
 * vertex cancels: with corners at 1e17 units and a near plane at 0.1 the new vertex is made of
 * rounding error only. Each operation rounds by at most 2<sup>-53</sup> of its magnitude (Higham,
 * "Accuracy and Stability of Numerical Algorithms", 2nd ed., section 2.2), so a vertex made from
 * corners no larger than M is off by a few units of 2<sup>-53</sup> M per plane; {@link #representable}
 * refuses a result where that error, taken as {@link #ROUNDING_UNITS} such units, exceeds
 * {@link #MAX_RELATIVE_ERROR} of a vertex's own w, i.e. of its screen position in normalised device
 * coordinates.
 */
final class Clipper {
    static final int NEAR = 1;
    static final int FAR = 2;
    static final int LEFT = 4;
    static final int RIGHT = 8;
    static final int BOTTOM = 16;
    static final int TOP = 32;
    /** At most 3 + one vertex per plane. */
    private static final int MAX_VERTICES = 9;

    /**
     * Largest error of a clipped vertex's clip coordinates accepted, as a fraction of its w: in
     * normalised device coordinates, so 2<sup>-16</sup> is 0.06 px on an 8192-pixel-wide image.
     */
    static final double MAX_RELATIVE_ERROR = 0x1p-16;
    /** Units of 2<sup>-53</sup> M taken as a clipped vertex's error: the rounding of the transform and of each plane's intersection. */
    static final double ROUNDING_UNITS = 8;

    /** Room for the vertices of the largest layout. */
    private static final int ROOM = (VertexLayout.FIRST_VARYING + VertexLayout.MAX_VARYINGS) * MAX_VERTICES;

    private double[] current = new double[ROOM];
    private double[] next = new double[ROOM];
    /** Doubles per vertex: the layout's {@link VertexLayout#clipStride()}. */
    private int stride = VertexLayout.CLIP_STRIDE;
    private double guardX = 1;
    private double guardY = 1;

    /** Sets the layout of the vertices that follow ({@link VertexLayout#TEXTURED} until set). */
    void layout(VertexLayout layout) {
        stride = layout.clipStride();
    }

    /** Sets the guard band, as multiples of the view volume's half-width and half-height. */
    void guardBand(double gx, double gy) {
        guardX = gx;
        guardY = gy;
    }

    /** Outcode of a vertex against the planes this clipper clips at (guard band for x and y). */
    int clipCode(double x, double y, double z, double w) {
        int code = 0;
        if (z < -w) {
            code |= NEAR;
        }
        if (z > w) {
            code |= FAR;
        }
        double gw = guardX * w;
        if (x < -gw) {
            code |= LEFT;
        }
        if (x > gw) {
            code |= RIGHT;
        }
        double hw = guardY * w;
        if (y < -hw) {
            code |= BOTTOM;
        }
        if (y > hw) {
            code |= TOP;
        }
        return code;
    }

    /** Outcode of a vertex against the exact view volume, for culling. */
    static int frustumCode(double x, double y, double z, double w) {
        int code = 0;
        if (z < -w) {
            code |= NEAR;
        }
        if (z > w) {
            code |= FAR;
        }
        if (x < -w) {
            code |= LEFT;
        }
        if (x > w) {
            code |= RIGHT;
        }
        if (y < -w) {
            code |= BOTTOM;
        }
        if (y > w) {
            code |= TOP;
        }
        return code;
    }

    /**
     * Clips the triangle (a, b, c), given at offsets of {@code src}, against the planes in
     * {@code planes}. The result is in {@link #vertices()}.
     *
     * @return the number of vertices of the clipped polygon: 0, or 3 to 9
     */
    int clip(double[] src, int a, int b, int c, int planes) {
        double[] in = current;
        VertexLayout.copy(src, a, in, 0, stride);
        VertexLayout.copy(src, b, in, stride, stride);
        VertexLayout.copy(src, c, in, 2 * stride, stride);
        int n = 3;
        for (int plane = NEAR; plane <= TOP && n > 0; plane <<= 1) {
            if ((planes & plane) != 0) {
                n = clipPlane(n, plane);
            }
        }
        return n < 3 ? 0 : n;
    }

    /** The clipped polygon's vertices after {@link #clip}. */
    double[] vertices() {
        return current;
    }

    /**
     * Whether the {@code n} vertices of the last {@link #clip}, made from corners whose largest
     * clip coordinate has magnitude {@code largest}, are placed to within {@link #MAX_RELATIVE_ERROR}
     * of their w. When not, the triangle's corners are too far from its part in view for double
     * precision, and it is to be skipped and counted rather than drawn wrong.
     */
    boolean representable(int n, double largest) {
        double error = ROUNDING_UNITS * 0x1p-53 * largest;
        for (int i = 0; i < n; i++) {
            if (!(error <= MAX_RELATIVE_ERROR * Math.abs(current[i * stride + W]))) {
                return false;
            }
        }
        return true;
    }

    private int clipPlane(int n, int plane) {
        double[] in = current;
        double[] out = next;
        int m = 0;
        for (int i = 0; i < n; i++) {
            int p = i * stride;
            int q = ((i + 1) % n) * stride;
            double dp = distance(in, p, plane);
            double dq = distance(in, q, plane);
            boolean pInside = dp >= 0;
            if (pInside) {
                VertexLayout.copy(in, p, out, m * stride, stride);
                m++;
            }
            if (pInside != (dq >= 0)) {
                int inside = pInside ? p : q;
                int outside = pInside ? q : p;
                double dIn = pInside ? dp : dq;
                double dOut = pInside ? dq : dp;
                double t = dIn / (dIn - dOut);
                int o = m * stride;
                for (int k = 0; k < stride; k++) {
                    out[o + k] = in[inside + k] + t * (in[outside + k] - in[inside + k]);
                }
                m++;
            }
        }
        current = out;
        next = in;
        return m;
    }

    /** Signed distance to a plane in clip space; inside when &gt;= 0. */
    private double distance(double[] v, int o, int plane) {
        double x = v[o + X];
        double y = v[o + Y];
        double z = v[o + Z];
        double w = v[o + W];
        switch (plane) {
            case NEAR:
                return z + w;
            case FAR:
                return w - z;
            case LEFT:
                return x + guardX * w;
            case RIGHT:
                return guardX * w - x;
            case BOTTOM:
                return y + guardY * w;
            default:
                return guardY * w - y;
        }
    }
}
