package dev.trisect.scene;

import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;

/**
 * A perspective camera as {@code gluLookAt(eye, target, up)} and
 * {@code gluPerspective(fovY, aspect, near, far)}.
 *
 * @param eye    camera position, world space
 * @param target point looked at, world space; {@link #MIN_DISTANCE} to {@link #MAX_DISTANCE} from {@code eye}
 * @param up     approximate up direction, world space; not zero and not parallel to the view direction;
 *               any finite magnitude (only its direction is used)
 * @param fovY   vertical field of view, degrees, from {@link #MIN_FOV} up to (not including) 180
 * @param near   distance to the near plane, world units, &gt; 0
 * @param far    distance to the far plane, world units, &gt; near and at most {@link #maxFar maxFar(near)}
 *               (any finite far when near is at most 0.5)
 */
public record Camera(Vec3 eye, Vec3 target, Vec3 up, double fovY, double near, double far) {

    /** Default vertical field of view, degrees. */
    public static final double DEFAULT_FOV = 60;
    /** Default near distance, world units. */
    public static final double DEFAULT_NEAR = 0.1;
    /** Default far distance, world units. */
    public static final double DEFAULT_FAR = 1000;

    /**
     * Narrowest vertical field of view, degrees. The projection scales x and y by {@code 1/tan(fov/2)},
     * 1.1e8 here; a triangle crossing the edge of the view must be clipped, and clipping is exact
     * enough only while its clip coordinates stay within about 1.7e10 times its depth (see
     * docs/reading-limits.md): at this field of view, triangles up to about 150 times their distance
     * across. At 1e-9 degrees the demo's and the floor's triangles in view were already skipped.
     */
    public static final double MIN_FOV = 1e-6;

    /** Largest distance from eye to target, world units: its square stays a finite double. */
    public static final double MAX_DISTANCE = 1e150;
    /** Smallest distance from eye to target, world units: its square stays a normal double. */
    public static final double MIN_DISTANCE = 1e-150;

    /**
     * Checks every rule above; the message names the offending value.
     *
     * @param eye    camera position, world space
     * @param target point looked at, world space
     * @param up     approximate up direction, world space
     * @param fovY   vertical field of view, degrees
     * @param near   distance to the near plane, world units
     * @param far    distance to the far plane, world units
     * @throws IllegalArgumentException when a value breaks a rule, naming it
     */
    public Camera {
        if (!eye.isFinite() || !target.isFinite() || !up.isFinite()) {
            throw new IllegalArgumentException("camera eye, target and up must be finite numbers");
        }
        if (eye.equals(target)) {
            throw new IllegalArgumentException("eye and target are the same point (" + eye + ")");
        }
        if (!(fovY > 0 && fovY < 180)) {
            throw new IllegalArgumentException("field of view must be between 0 and 180 degrees, got " + fovY);
        }
        if (fovY < MIN_FOV) {
            throw new IllegalArgumentException("field of view " + fovY + " is too narrow: at least " + MIN_FOV
                    + " degrees, where the projection's scale (1/tan(fov/2)) still lets triangles in view be clipped "
                    + "in double precision");
        }
        if (!(near > 0) || Double.isInfinite(near)) {
            throw new IllegalArgumentException("near must be a positive number, got " + near);
        }
        if (!(far > near) || Double.isInfinite(far)) {
            throw new IllegalArgumentException("near (" + near + ") must be less than far (" + far + ")");
        }
        if (!(far <= maxFar(near))) {
            throw new IllegalArgumentException("far (" + far + ") is too large for near (" + near + "): the "
                    + "projection needs 2 x near x far to be a finite double, so far may be at most " + maxFar(near));
        }
        // The view direction is target - eye normalized; its length must neither overflow nor vanish
        // (squared, as the length is computed) in double precision.
        double distance = target.sub(eye).length();
        if (!(distance <= MAX_DISTANCE)) {
            throw new IllegalArgumentException("eye " + eye + " and target " + target + " are too far apart (more "
                    + "than " + MAX_DISTANCE + " units): the view direction cannot be computed");
        }
        if (!(distance >= MIN_DISTANCE)) {
            throw new IllegalArgumentException("eye " + eye + " and target " + target + " are too close together "
                    + "(less than " + MIN_DISTANCE + " units apart): the view direction cannot be computed");
        }
        if (up.x() == 0 && up.y() == 0 && up.z() == 0) {
            throw new IllegalArgumentException("up (" + up + ") is zero: it must give the direction of up");
        }
        // Both directions unit length first, so that up's magnitude, from 1e-300 to 1e300, does not matter.
        Vec3 forward = target.sub(eye).normalize();
        if (forward.cross(up.normalize()).length() < 1e-9) {
            throw new IllegalArgumentException("up (" + up + ") is parallel to the view direction");
        }
    }

    /**
     * The largest far distance a camera with this near distance can have: the projection holds
     * {@code 2 * near * far} and {@code far + near}, and both must be finite doubles. Double.MAX_VALUE
     * for every near up to 0.5; about {@code Double.MAX_VALUE / (2 * near)} above.
     *
     * @param near distance to the near plane, world units, &gt; 0 and finite
     * @return the largest far, world units
     * @throws IllegalArgumentException when near is not a positive finite number
     */
    public static double maxFar(double near) {
        if (!(near > 0) || Double.isInfinite(near)) {
            throw new IllegalArgumentException("near must be a positive number, got " + near);
        }
        double far = Math.min(Double.MAX_VALUE, Double.MAX_VALUE / (2 * near));
        // The quotient can round up by an ulp, past the last far whose product is finite.
        while (!Double.isFinite(2 * near * far) || !Double.isFinite(far + near)) {
            far = Math.nextDown(far);
        }
        return far;
    }

    /**
     * A camera with the default field of view, near and far, and +y up.
     *
     * @param eye    camera position, world space
     * @param target point looked at, world space
     * @return the camera
     * @throws IllegalArgumentException when a value breaks a rule of the constructor, naming it: among them
     *                                  an eye on the target, and a camera looking straight down or up (+y is
     *                                  then parallel to its view: give an up with {@link #looking(Vec3, Vec3, Vec3)})
     */
    public static Camera looking(Vec3 eye, Vec3 target) {
        return looking(eye, target, Vec3.UP);
    }

    /**
     * A camera with the default field of view, near and far, and the given up: a camera looking
     * straight down needs one, since +y is parallel to its view.
     *
     * <pre>{@code
     * Camera topDown = Camera.looking(new Vec3(0, 20, 0), Vec3.ZERO, new Vec3(0, 0, -1)); // -z at the top
     * }</pre>
     *
     * @param eye    camera position, world space
     * @param target point looked at, world space
     * @param up     approximate up direction, world space; not zero and not parallel to the view
     * @return the camera
     * @throws IllegalArgumentException when a value breaks a rule of the constructor, naming it
     */
    public static Camera looking(Vec3 eye, Vec3 target, Vec3 up) {
        return new Camera(eye, target, up, DEFAULT_FOV, DEFAULT_NEAR, DEFAULT_FAR);
    }

    /**
     * World space to view space.
     *
     * @return the view matrix, as {@code gluLookAt}
     */
    public Mat4 view() {
        return Mat4.lookAt(eye, target, up);
    }

    /**
     * View space to clip space for a viewport of the given aspect (width / height).
     *
     * @param aspect width / height of the viewport
     * @return the projection matrix, as {@code gluPerspective}
     */
    public Mat4 projection(double aspect) {
        return Mat4.perspective(fovY, aspect, near, far);
    }

    /**
     * World space to clip space for the viewport.
     *
     * @param viewport the frame's size, pixels
     * @return projection times view
     */
    public Mat4 viewProjection(Viewport viewport) {
        return projection(viewport.aspect()).mul(view());
    }
}
