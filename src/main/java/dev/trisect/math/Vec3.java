package dev.trisect.math;

/**
 * A 3-component vector of doubles, used for positions and directions outside the hot loops.
 * The coordinate space is the caller's (world space for cameras and scenes).
 *
 * @param x the x component
 * @param y the y component
 * @param z the z component
 */
public record Vec3(double x, double y, double z) {

    /** The zero vector. */
    public static final Vec3 ZERO = new Vec3(0, 0, 0);
    /** The world's up direction (+y). */
    public static final Vec3 UP = new Vec3(0, 1, 0);

    /**
     * {@code this + o}.
     *
     * @param o the other vector
     * @return the sum
     */
    public Vec3 add(Vec3 o) {
        return new Vec3(x + o.x, y + o.y, z + o.z);
    }

    /**
     * {@code this - o}.
     *
     * @param o the other vector
     * @return the difference
     */
    public Vec3 sub(Vec3 o) {
        return new Vec3(x - o.x, y - o.y, z - o.z);
    }

    /**
     * {@code this * s}.
     *
     * @param s the factor
     * @return the scaled vector
     */
    public Vec3 scale(double s) {
        return new Vec3(x * s, y * s, z * s);
    }

    /**
     * The dot product.
     *
     * @param o the other vector
     * @return the dot product
     */
    public double dot(Vec3 o) {
        return x * o.x + y * o.y + z * o.z;
    }

    /**
     * The cross product {@code this x o} (right-handed).
     *
     * @param o the other vector
     * @return the cross product
     */
    public Vec3 cross(Vec3 o) {
        return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x);
    }

    /**
     * The Euclidean length.
     *
     * @return the length
     */
    public double length() {
        return Math.sqrt(dot(this));
    }

    /**
     * This vector scaled to unit length; the zero vector stays zero, and so does a vector with a
     * non-finite component.
     *
     * <p>Any finite non-zero vector gives a unit vector, however long or short: where the squared
     * length would overflow (components above about 1e154) or underflow (below about 1e-154), the
     * vector is first divided by its largest component's magnitude. Between 1e-150 and 1e150 the
     * result is {@code this / length()}, the plain formula, bit for bit.
     *
     * @return the unit vector, or zero
     */
    public Vec3 normalize() {
        double len = length();
        if (len > 1e-150 && len < 1e150) {
            return scale(1 / len);
        }
        double largest = Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
        if (largest == 0 || !Double.isFinite(largest)) {
            return largest == 0 ? this : scale(1 / len); // zero, or not finite: as the plain formula
        }
        Vec3 scaled = new Vec3(x / largest, y / largest, z / largest);
        return scaled.scale(1 / scaled.length());
    }

    /**
     * Whether every component is finite (neither NaN nor infinite).
     *
     * @return true when x, y and z are finite
     */
    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }

    /**
     * {@code this + (o - this) * t}.
     *
     * @param o the other end
     * @param t 0 gives this, 1 gives {@code o}
     * @return the interpolated vector
     */
    public Vec3 lerp(Vec3 o, double t) {
        return new Vec3(x + (o.x - x) * t, y + (o.y - y) * t, z + (o.z - z) * t);
    }

    @Override
    public String toString() {
        return x + "," + y + "," + z;
    }
}
