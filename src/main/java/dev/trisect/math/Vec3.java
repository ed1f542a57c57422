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

    /** {@code this + o}. */
    public Vec3 add(Vec3 o) {
        return new Vec3(x + o.x, y + o.y, z + o.z);
    }

    /** {@code this - o}. */
    public Vec3 sub(Vec3 o) {
        return new Vec3(x - o.x, y - o.y, z - o.z);
    }

    /** {@code this * s}. */
    public Vec3 scale(double s) {
        return new Vec3(x * s, y * s, z * s);
    }

    /** The dot product. */
    public double dot(Vec3 o) {
        return x * o.x + y * o.y + z * o.z;
    }

    /** The cross product {@code this x o} (right-handed). */
    public Vec3 cross(Vec3 o) {
        return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x);
    }

    /** The Euclidean length. */
    public double length() {
        return Math.sqrt(dot(this));
    }

    /** This vector scaled to unit length; the zero vector stays zero. */
    public Vec3 normalize() {
        double len = length();
        return len == 0 ? this : scale(1 / len);
    }

    /** Whether every component is finite (neither NaN nor infinite). */
    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }

    /** {@code this + (o - this) * t}. */
    public Vec3 lerp(Vec3 o, double t) {
        return new Vec3(x + (o.x - x) * t, y + (o.y - y) * t, z + (o.z - z) * t);
    }

    @Override
    public String toString() {
        return x + "," + y + "," + z;
    }
}
