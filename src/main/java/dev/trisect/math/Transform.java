package dev.trisect.math;

import java.util.Objects;

/**
 * Where an object is: a translation, a rotation and a scale, applied to its points as
 * {@code T * R * S} — scaled first (in object space), then rotated, then moved. Immutable; every
 * {@code with...} returns a new value.
 *
 * <pre>{@code
 * Transform t = Transform.translation(0, 0.5, 0).withRotation(Quaternion.ofY(30)).withScale(2);
 * }</pre>
 *
 * @param translation the offset, in the parent's units (world units for an object at the top of a scene)
 * @param rotation    the rotation about the object's origin
 * @param scale       the scale along the object's own x, y and z axes, each finite, non-zero and at most
 *                    {@link #MAX_SCALE} in magnitude
 */
public record Transform(Vec3 translation, Quaternion rotation, Vec3 scale) {

    /** No translation, no rotation, unit scale. */
    public static final Transform IDENTITY = new Transform(Vec3.ZERO, Quaternion.IDENTITY, new Vec3(1, 1, 1));

    /**
     * The largest scale on an axis: half the largest double, so that a rotation matrix's entries (at
     * most 1 and a few units of rounding) times the scale stay finite.
     */
    public static final double MAX_SCALE = Double.MAX_VALUE / 2;

    /**
     * Checks the parts.
     *
     * @param translation where the object's origin goes, parent's units
     * @param rotation    the rotation about the object's origin
     * @param scale       the scale per axis, applied first
     * @throws NullPointerException     for a missing part
     * @throws IllegalArgumentException for a non-finite translation, or a scale that is not finite, is zero or
     *                                  exceeds {@link #MAX_SCALE} on an axis
     */
    public Transform {
        Objects.requireNonNull(translation, "transform translation is null");
        Objects.requireNonNull(rotation, "transform rotation is null");
        Objects.requireNonNull(scale, "transform scale is null");
        if (!translation.isFinite()) {
            throw new IllegalArgumentException("translation must be finite, got " + translation);
        }
        if (!scale.isFinite() || scale.x() == 0 || scale.y() == 0 || scale.z() == 0) {
            throw new IllegalArgumentException("scale must be finite and non-zero on every axis, got " + scale);
        }
        if (Math.max(Math.abs(scale.x()), Math.max(Math.abs(scale.y()), Math.abs(scale.z()))) > MAX_SCALE) {
            throw new IllegalArgumentException("scale " + scale + " is too large: at most " + MAX_SCALE
                    + " on an axis, so that the rotated scale in the matrix stays a finite double");
        }
    }


    /**
     * A translation alone.
     *
     * @param x the move along x, parent's units
     * @param y the move along y
     * @param z the move along z
     * @return the transform
     */
    public static Transform translation(double x, double y, double z) {
        return IDENTITY.withTranslation(new Vec3(x, y, z));
    }

    /**
     * A rotation alone.
     *
     * @param rotation the rotation
     * @return the transform
     */
    public static Transform rotation(Quaternion rotation) {
        return IDENTITY.withRotation(rotation);
    }

    /**
     * A uniform scale alone.
     *
     * @param factor the scale on every axis
     * @return the transform
     */
    public static Transform scale(double factor) {
        return IDENTITY.withScale(factor);
    }

    /**
     * A copy with another translation.
     *
     * @param t the translation
     * @return the copy
     */
    public Transform withTranslation(Vec3 t) {
        return new Transform(t, rotation, scale);
    }

    /**
     * A copy with another translation.
     *
     * @param x the translation's x
     * @param y the translation's y
     * @param z the translation's z
     * @return the copy
     */
    public Transform withTranslation(double x, double y, double z) {
        return withTranslation(new Vec3(x, y, z));
    }

    /**
     * A copy with another rotation.
     *
     * @param r the rotation
     * @return the copy
     */
    public Transform withRotation(Quaternion r) {
        return new Transform(translation, r, scale);
    }

    /**
     * A copy with another scale per axis.
     *
     * @param s the scale per axis
     * @return the copy
     */
    public Transform withScale(Vec3 s) {
        return new Transform(translation, rotation, s);
    }

    /**
     * A copy with a uniform scale.
     *
     * @param factor the scale on every axis
     * @return the copy
     */
    public Transform withScale(double factor) {
        return withScale(new Vec3(factor, factor, factor));
    }

    /**
     * A copy rotated further by {@code r} (about the object's origin, after its present rotation).
     *
     * @param r the further rotation
     * @return the copy
     */
    public Transform rotatedBy(Quaternion r) {
        return withRotation(r.mul(rotation));
    }

    /**
     * A copy moved further by (dx, dy, dz), in the parent's units.
     *
     * @param dx the move along x
     * @param dy the move along y
     * @param dz the move along z
     * @return the copy
     */
    public Transform movedBy(double dx, double dy, double dz) {
        return withTranslation(translation.add(new Vec3(dx, dy, dz)));
    }

    /**
     * The matrix {@code T * R * S}: object space to the parent's space.
     *
     * @return the matrix
     */
    public Mat4 matrix() {
        Mat4 r = rotation.matrix();
        double sx = scale.x();
        double sy = scale.y();
        double sz = scale.z();
        return Mat4.ofRows(
                r.get(0, 0) * sx, r.get(0, 1) * sy, r.get(0, 2) * sz, translation.x(),
                r.get(1, 0) * sx, r.get(1, 1) * sy, r.get(1, 2) * sz, translation.y(),
                r.get(2, 0) * sx, r.get(2, 1) * sy, r.get(2, 2) * sz, translation.z(),
                0, 0, 0, 1);
    }

    /**
     * The point {@code p} of object space in the parent's space.
     *
     * @param p the point, object space
     * @return the point in the parent's space
     */
    public Vec3 apply(Vec3 p) {
        return translation.add(rotation.rotate(new Vec3(p.x() * scale.x(), p.y() * scale.y(), p.z() * scale.z())));
    }
}
