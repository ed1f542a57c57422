package dev.trisect.math;

/**
 * A rotation as a unit quaternion {@code w + xi + yj + zk}, immutable. Rotations are right-handed: a
 * positive angle about an axis turns counter-clockwise when the axis points at the viewer (as
 * {@code glRotate}).
 *
 * <p>The factories return unit quaternions; {@link #of} normalizes what it is given. Any finite,
 * non-zero components are a rotation, also 1e-200 or 1e200 (they are scaled by a power of two before
 * they are squared, as {@link Vec3#normalize} does), so {@link #matrix()} is always finite. Composition
 * follows matrices: {@code a.mul(b)} rotates by {@code b} first, then by {@code a}.
 *
 * @param x the i component
 * @param y the j component
 * @param z the k component
 * @param w the real component
 */
public record Quaternion(double x, double y, double z, double w) {

    /** No rotation. */
    public static final Quaternion IDENTITY = new Quaternion(0, 0, 0, 1);

    /**
     * Checks that the components are finite and not all zero.
     *
     * @param x the vector part's x
     * @param y the vector part's y
     * @param z the vector part's z
     * @param w the scalar part
     * @throws IllegalArgumentException otherwise
     */
    public Quaternion {
        if (!(Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z) && Double.isFinite(w))) {
            throw new IllegalArgumentException("quaternion components must be finite, got " + x + ", " + y + ", "
                    + z + ", " + w);
        }
        if (x == 0 && y == 0 && z == 0 && w == 0) {
            throw new IllegalArgumentException("the zero quaternion is not a rotation");
        }
    }

    /**
     * The quaternion (x, y, z, w) scaled to unit length.
     *
     * @param x the vector part's x
     * @param y the vector part's y
     * @param z the vector part's z
     * @param w the scalar part
     * @return the unit quaternion
     */
    public static Quaternion of(double x, double y, double z, double w) {
        Quaternion q = new Quaternion(x, y, z, w).balanced();
        double n = Math.sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
        return new Quaternion(q.x / n, q.y / n, q.z / n, q.w / n);
    }

    /**
     * This quaternion, or when the sum of its squared components would overflow or lose its precision
     * (components beyond about 1e150 or below 1e-150, which describe a rotation as well as any), the
     * same one scaled by a power of two (exactly) so that its largest component is between 1 and 2:
     * as {@link Vec3#normalize} divides by the largest component first.
     */
    private Quaternion balanced() {
        double n = x * x + y * y + z * z + w * w;
        if (n >= 0x1p-500 && n <= 0x1p500) {
            return this;
        }
        double largest = Math.max(Math.max(Math.abs(x), Math.abs(y)), Math.max(Math.abs(z), Math.abs(w)));
        // getExponent of a subnormal is MIN_EXPONENT - 1: take it from the value scaled up (exactly) first.
        int e = largest >= Double.MIN_NORMAL ? Math.getExponent(largest) : Math.getExponent(largest * 0x1p60) - 60;
        return new Quaternion(Math.scalb(x, -e), Math.scalb(y, -e), Math.scalb(z, -e), Math.scalb(w, -e));
    }

    /**
     * A rotation by {@code degrees} about {@code axis}.
     *
     * @param axis    the axis, any non-zero length
     * @param degrees the angle, degrees, counter-clockwise looking down the axis toward the origin
     * @return the rotation
     */
    public static Quaternion axisAngle(Vec3 axis, double degrees) {
        if (!axis.isFinite() || (axis.x() == 0 && axis.y() == 0 && axis.z() == 0)) {
            throw new IllegalArgumentException("rotation axis must be a finite non-zero vector, got " + axis);
        }
        double len = axis.length();
        if (!(len > 1e-150 && len < 1e150)) {
            // Its squared length overflows or underflows: its direction, as Vec3.normalize finds it.
            axis = axis.normalize();
            len = 1;
        }
        if (!Double.isFinite(degrees)) {
            throw new IllegalArgumentException("rotation angle must be finite, got " + degrees);
        }
        double half = Math.toRadians(degrees) / 2;
        double s = Math.sin(half) / len;
        return of(axis.x() * s, axis.y() * s, axis.z() * s, Math.cos(half));
    }

    /**
     * A rotation by {@code degrees} about +x.
     *
     * @param degrees the angle, counter-clockwise looking down +x toward the origin
     * @return the rotation
     */
    public static Quaternion ofX(double degrees) {
        return axisAngle(new Vec3(1, 0, 0), degrees);
    }

    /**
     * A rotation by {@code degrees} about +y.
     *
     * @param degrees the angle, counter-clockwise looking down +y toward the origin
     * @return the rotation
     */
    public static Quaternion ofY(double degrees) {
        return axisAngle(new Vec3(0, 1, 0), degrees);
    }

    /**
     * A rotation by {@code degrees} about +z.
     *
     * @param degrees the angle, counter-clockwise looking down +z toward the origin
     * @return the rotation
     */
    public static Quaternion ofZ(double degrees) {
        return axisAngle(new Vec3(0, 0, 1), degrees);
    }

    /**
     * {@code this * o}: the rotation {@code o} followed by this one (Hamilton product, renormalized).
     *
     * @param o the rotation applied first
     * @return the combined rotation
     */
    public Quaternion mul(Quaternion o) {
        // Of the balanced factors: 1e200 times 1e200 would overflow, though each is a rotation.
        Quaternion a = balanced();
        Quaternion b = o.balanced();
        return a.product(b);
    }

    private Quaternion product(Quaternion o) {
        return of(w * o.x + x * o.w + y * o.z - z * o.y,
                w * o.y - x * o.z + y * o.w + z * o.x,
                w * o.z + x * o.y - y * o.x + z * o.w,
                w * o.w - x * o.x - y * o.y - z * o.z);
    }

    /**
     * The inverse rotation.
     *
     * @return the conjugate
     */
    public Quaternion inverse() {
        return of(-x, -y, -z, w);
    }

    /**
     * {@code v} rotated.
     *
     * @param v the vector
     * @return the rotated vector
     */
    public Vec3 rotate(Vec3 v) {
        Mat4 m = matrix();
        return new Vec3(m.get(0, 0) * v.x() + m.get(0, 1) * v.y() + m.get(0, 2) * v.z(),
                m.get(1, 0) * v.x() + m.get(1, 1) * v.y() + m.get(1, 2) * v.z(),
                m.get(2, 0) * v.x() + m.get(2, 1) * v.y() + m.get(2, 2) * v.z());
    }

    /**
     * The rotation as a matrix (the upper-left 3x3 of a 4x4 with no translation).
     *
     * @return the rotation matrix
     */
    public Mat4 matrix() {
        // The standard unit-quaternion rotation matrix (Shoemake, "Animating rotation with quaternion
        // curves", SIGGRAPH 1985), normalized here so that a slightly off-unit value still rotates, and
        // balanced first so that components of 1e200 or 1e-200 rotate too (their squares would not).
        Quaternion q = balanced();
        if (q != this) {
            return q.matrix();
        }
        double n = x * x + y * y + z * z + w * w;
        double s = 2 / n;
        double xx = x * x * s;
        double yy = y * y * s;
        double zz = z * z * s;
        double xy = x * y * s;
        double xz = x * z * s;
        double yz = y * z * s;
        double wx = w * x * s;
        double wy = w * y * s;
        double wz = w * z * s;
        return Mat4.ofRows(
                1 - yy - zz, xy - wz, xz + wy, 0,
                xy + wz, 1 - xx - zz, yz - wx, 0,
                xz - wy, yz + wx, 1 - xx - yy, 0,
                0, 0, 0, 1);
    }
}
