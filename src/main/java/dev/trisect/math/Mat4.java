package dev.trisect.math;

import java.util.Arrays;
import java.util.Objects;

/**
 * An immutable 4x4 matrix of doubles in OpenGL's column-major order: element (row r, column c) is
 * {@code m[c * 4 + r]}, and points are column vectors multiplied on the right ({@code M * p}).
 *
 * <p>The factories follow the GLU reference pages exactly, so that a frame agrees with an OpenGL
 * implementation given the same camera: {@link #lookAt} as {@code gluLookAt}, {@link #perspective} as
 * {@code gluPerspective}.
 */
public final class Mat4 {
    private final double[] m;

    private Mat4(double[] m) {
        this.m = m;
    }

    /**
     * The identity matrix.
     *
     * @return the identity
     */
    public static Mat4 identity() {
        double[] m = new double[16];
        m[0] = m[5] = m[10] = m[15] = 1;
        return new Mat4(m);
    }

    /**
     * A matrix from 16 values given row by row (as one reads a matrix on paper).
     *
     * @param rows 16 values, row by row
     * @return the matrix
     */
    public static Mat4 ofRows(double... rows) {
        if (rows.length != 16) {
            throw new IllegalArgumentException("need 16 values, got " + rows.length);
        }
        double[] m = new double[16];
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 4; c++) {
                m[c * 4 + r] = rows[r * 4 + c];
            }
        }
        return new Mat4(m);
    }

    /**
     * The view matrix of {@code gluLookAt}: world space to view space, where the camera sits at the
     * origin looking down -z with +y up.
     *
     * @param eye    camera position, world space
     * @param target point looked at, world space; must differ from {@code eye}
     * @param up     approximate up direction, world space; must not be parallel to the view direction
     * @return the view matrix
     * @throws IllegalArgumentException when {@code eye} is {@code target}, a value is not finite, or
     *                                  {@code up} is zero or parallel to the view direction (no direction
     *                                  for one of the camera's axes; {@code Camera} checks the same with
     *                                  messages of its own)
     */
    public static Mat4 lookAt(Vec3 eye, Vec3 target, Vec3 up) {
        Vec3 f = target.sub(eye).normalize();
        if (!isUnit(f)) {
            throw new IllegalArgumentException("lookAt needs finite eye and target apart, got eye " + eye
                    + " and target " + target);
        }
        // An up of extreme magnitude (above 1e150 or below 1e-150) is made unit first, so that the
        // cross product neither overflows nor underflows; any other up is used as given (as gluLookAt).
        double upLength = up.length();
        Vec3 s = f.cross(upLength > 1e-150 && upLength < 1e150 ? up : up.normalize()).normalize();
        if (!isUnit(s)) {
            throw new IllegalArgumentException("lookAt needs a finite up (" + up + ") not parallel to the view "
                    + "direction " + f);
        }
        Vec3 u = s.cross(f);
        return ofRows(
                s.x(), s.y(), s.z(), -s.dot(eye),
                u.x(), u.y(), u.z(), -u.dot(eye),
                -f.x(), -f.y(), -f.z(), f.dot(eye),
                0, 0, 0, 1);
    }

    /**
     * The projection matrix of {@code gluPerspective}: view space to OpenGL clip space, where a point
     * is inside the view volume when {@code -w <= x, y, z <= w} and {@code w = -z_view}.
     *
     * @param fovYDegrees vertical field of view, degrees, in (0, 180)
     * @param aspect      width / height of the viewport
     * @param near        distance to the near plane, view-space units, &gt; 0
     * @param far         distance to the far plane, view-space units, &gt; near; the matrix holds
     *                    {@code 2 * near * far} and {@code far + near}, which must be finite doubles
     *                    (see {@code Camera.maxFar}): with a near up to 0.5, any finite far
     * @return the projection matrix
     * @throws IllegalArgumentException when a value is outside its range or not finite, or the matrix
     *                                  would not be
     */
    public static Mat4 perspective(double fovYDegrees, double aspect, double near, double far) {
        // Each as Camera checks it; here too, since a matrix of infinities or NaN would draw nothing, silently.
        if (!(fovYDegrees > 0 && fovYDegrees < 180) || !(aspect > 0 && aspect < Double.POSITIVE_INFINITY)
                || !(near > 0) || !(far > near && far < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("perspective needs fovY in (0, 180), a finite aspect > 0 and "
                    + "0 < near < far finite, got " + fovYDegrees + ", " + aspect + ", " + near + ", " + far);
        }
        double f = 1.0 / Math.tan(Math.toRadians(fovYDegrees) / 2);
        double depthScale = (far + near) / (near - far);
        // 2 * near first: 2 * far overflowed for every far above Double.MAX_VALUE / 2, and the frame drew
        // nothing (every triangle skipped). Doubling is exact, so the product's bits are unchanged otherwise.
        double depthOffset = 2 * near * far / (near - far);
        if (!Double.isFinite(depthScale) || !Double.isFinite(depthOffset)) {
            throw new IllegalArgumentException("perspective: near " + near + " and far " + far + " overflow the "
                    + "projection (2 x near x far and far + near must be finite doubles)");
        }
        return ofRows(
                f / aspect, 0, 0, 0,
                0, f, 0, 0,
                0, 0, depthScale, depthOffset,
                0, 0, -1, 0);
    }

    /** Whether {@code v} is a direction normalize() could make: finite and not zero. */
    private static boolean isUnit(Vec3 v) {
        return v.isFinite() && (v.x() != 0 || v.y() != 0 || v.z() != 0);
    }

    /**
     * Element at row {@code r}, column {@code c}.
     *
     * @param r the row, 0..3
     * @param c the column, 0..3
     * @return the element
     * @throws IndexOutOfBoundsException when {@code r} or {@code c} is outside 0..3
     */
    public double get(int r, int c) {
        // Both checked: get(4, 0) would otherwise read the element at (0, 1) of the column-major array.
        return m[Objects.checkIndex(c, 4) * 4 + Objects.checkIndex(r, 4)];
    }

    /**
     * {@code this * o}: applies {@code o} first, then {@code this}.
     *
     * @param o the matrix applied first
     * @return the product
     */
    public Mat4 mul(Mat4 o) {
        double[] r = new double[16];
        for (int c = 0; c < 4; c++) {
            for (int row = 0; row < 4; row++) {
                double s = 0;
                for (int k = 0; k < 4; k++) {
                    s += m[k * 4 + row] * o.m[c * 4 + k];
                }
                r[c * 4 + row] = s;
            }
        }
        return new Mat4(r);
    }

    /**
     * Transforms the point (x, y, z, 1) and writes (x', y', z', w') to {@code out[offset..offset+3]}.
     * Allocation-free, for the per-vertex stage.
     *
     * @param x      the point's x
     * @param y      the point's y
     * @param z      the point's z
     * @param out    receives x', y', z', w'
     * @param offset where in {@code out}
     */
    public void transformPoint(double x, double y, double z, double[] out, int offset) {
        out[offset] = m[0] * x + m[4] * y + m[8] * z + m[12];
        out[offset + 1] = m[1] * x + m[5] * y + m[9] * z + m[13];
        out[offset + 2] = m[2] * x + m[6] * y + m[10] * z + m[14];
        out[offset + 3] = m[3] * x + m[7] * y + m[11] * z + m[15];
    }

    /**
     * The normal matrix of this model matrix: the inverse transpose of its upper-left 3x3 (in the
     * upper-left 3x3 of the result, with no translation and a last row 0 0 0 1), which carries a
     * surface's normals to the transformed surface's (OpenGL 2.1 specification, section 2.11.3,
     * "Normal Transformation": the normal as a row vector times the inverse of the upper leftmost 3x3
     * of the model-view matrix). Under a rotation with uniform scale it is the same direction as the
     * matrix itself; under a non-uniform scale it is not, and only it keeps the normal perpendicular to
     * the surface.
     * It does not keep length: make the transformed normal unit length before lighting with it
     * (OpenGL's {@code GL_NORMALIZE}). Computed as the cofactor matrix over the determinant.
     *
     * @return the normal matrix; apply it with {@link #transformDirection}
     * @throws IllegalArgumentException when the 3x3 is singular or not finite (its determinant is zero,
     *                                  or the result is not finite, in double precision)
     */
    public Mat4 normalMatrix() {
        // Columns a, b, c of the 3x3; the columns of its inverse transpose are (b x c, c x a, a x b) / det.
        double ax = m[0], ay = m[1], az = m[2];
        double bx = m[4], by = m[5], bz = m[6];
        double cx = m[8], cy = m[9], cz = m[10];
        double[] r = {
            by * cz - bz * cy, bz * cx - bx * cz, bx * cy - by * cx, 0,
            cy * az - cz * ay, cz * ax - cx * az, cx * ay - cy * ax, 0,
            ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx, 0,
            0, 0, 0, 1};
        double det = ax * r[0] + ay * r[1] + az * r[2];
        for (int i = 0; i < 11; i++) {
            r[i] = i % 4 == 3 ? 0 : r[i] / det; // the zeros stay +0, whatever det's sign
        }
        for (double v : r) {
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("no normal matrix: the upper-left 3x3 is singular or not finite"
                        + " (determinant " + det + ")");
            }
        }
        return new Mat4(r);
    }

    /**
     * Transforms the direction (x, y, z, 0) by the upper-left 3x3 alone (no translation) and writes
     * (x', y', z') to {@code out[offset..offset+2]}. Allocation-free, for the per-vertex stage; with
     * {@link #normalMatrix()} it carries normals.
     *
     * @param x      the direction's x
     * @param y      the direction's y
     * @param z      the direction's z
     * @param out    receives x', y', z'
     * @param offset where in {@code out}
     */
    public void transformDirection(double x, double y, double z, double[] out, int offset) {
        out[offset] = m[0] * x + m[4] * y + m[8] * z;
        out[offset + 1] = m[1] * x + m[5] * y + m[9] * z;
        out[offset + 2] = m[2] * x + m[6] * y + m[10] * z;
    }

    /**
     * The point (x, y, z, 1) transformed and divided by w; meant for tests and setup, not hot loops.
     *
     * @param p the point
     * @return the transformed point after the division by w
     */
    public Vec3 transformProject(Vec3 p) {
        double[] o = new double[4];
        transformPoint(p.x(), p.y(), p.z(), o, 0);
        return new Vec3(o[0] / o[3], o[1] / o[3], o[2] / o[3]);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Mat4 other && Arrays.equals(m, other.m);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(m);
    }

    @Override
    public String toString() {
        StringBuilder sb = new StringBuilder();
        for (int r = 0; r < 4; r++) {
            sb.append(r == 0 ? "[" : " ");
            for (int c = 0; c < 4; c++) {
                sb.append(String.format("%10.4f", get(r, c)));
            }
            sb.append(r == 3 ? "]" : "\n");
        }
        return sb.toString();
    }
}
