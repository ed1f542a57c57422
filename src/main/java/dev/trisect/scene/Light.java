package dev.trisect.scene;

import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.render.Colour;
import java.util.Objects;

/**
 * A light in a {@link Scene}, lighting every object whose material is lit ({@link Material#shading()})
 * as OpenGL's fixed function does, per vertex, without specular (docs/conventions.md, "Light and
 * fog"): the ambient lights sum to the scene's ambient colour; a directional light shines from a
 * direction; a point light shines from a position and fades with distance d by
 * {@code 1 / (kc + kl·d + kq·d²)}. A light is a node: a group's transform moves a point light and
 * turns a directional one, and hiding it turns it off. Any number may shine at once. One that its
 * groups' transforms place beyond double range (a point light at 1e200 in a group scaled 1e200, a
 * direction in groups whose scales multiply below 1e-308) does not shine.
 *
 * <pre>{@code
 * scene.add(Light.ambient(Colour.grey(0.2)),
 *         Light.directional(new Vec3(1, 2, 3), Colour.WHITE),
 *         Light.point(new Vec3(0, 2, 0), new Colour(1, 0.8, 0.5), 1, 0.2, 0.05));
 * scene.add(new SceneObject(Primitives.box(1, 1, 1), Material.of(crate).withShading(Shading.SMOOTH)));
 * }</pre>
 *
 * <p>Every method may be called from any thread, also while a renderer draws the scene.
 */
public final class Light extends Node {
    /** The three kinds of light. */
    public enum Kind {
        /** Adds to the scene's ambient colour; has no place or direction. */
        AMBIENT,
        /** Shines from a direction, as the sun, unattenuated. */
        DIRECTIONAL,
        /** Shines from a position, attenuated by distance. */
        POINT
    }

    /** The light's values, swapped as one. */
    private record Values(Vec3 vector, Colour colour, double kc, double kl, double kq) {
    }

    private final Kind kind;
    private volatile Values values;

    private Light(Kind kind, Values values) {
        super(null);
        this.kind = kind;
        this.values = values;
    }

    /**
     * An ambient light: its colour adds to the scene's ambient colour, which lights every lit surface
     * evenly (OpenGL's {@code GL_LIGHT_MODEL_AMBIENT}).
     *
     * @param colour the colour
     * @return the light
     * @throws NullPointerException when {@code colour} is null
     */
    public static Light ambient(Colour colour) {
        return new Light(Kind.AMBIENT, new Values(Vec3.ZERO, Objects.requireNonNull(colour, "colour is null"), 1, 0, 0));
    }

    /**
     * A directional light shining from direction {@code towards} (a vector pointing at the light, in
     * its parent's space; any length but zero), with diffuse colour {@code colour}.
     *
     * @param towards the direction towards the light
     * @param colour  its diffuse colour
     * @return the light
     * @throws NullPointerException     when {@code towards} or {@code colour} is null
     * @throws IllegalArgumentException when {@code towards} is zero or not finite
     */
    public static Light directional(Vec3 towards, Colour colour) {
        return new Light(Kind.DIRECTIONAL, new Values(direction(towards), Objects.requireNonNull(colour,
                "colour is null"), 1, 0, 0));
    }

    /**
     * A point light at {@code position} (in its parent's space) with diffuse colour {@code colour},
     * unattenuated.
     *
     * @param position where it is
     * @param colour   its diffuse colour
     * @return the light
     * @throws NullPointerException     when {@code position} or {@code colour} is null
     * @throws IllegalArgumentException for a non-finite position
     */
    public static Light point(Vec3 position, Colour colour) {
        return point(position, colour, 1, 0, 0);
    }

    /**
     * A point light at {@code position} (in its parent's space) with diffuse colour {@code colour},
     * attenuated by {@code 1 / (kc + kl·d + kq·d²)} at distance d (world-space units).
     *
     * @param position where it is
     * @param colour   its diffuse colour
     * @param kc       constant attenuation, at least 0
     * @param kl       linear attenuation, at least 0
     * @param kq       quadratic attenuation, at least 0 (not all three 0)
     * @return the light
     * @throws NullPointerException     when {@code position} or {@code colour} is null
     * @throws IllegalArgumentException for a non-finite position or bad attenuation
     */
    public static Light point(Vec3 position, Colour colour, double kc, double kl, double kq) {
        return new Light(Kind.POINT, values(position(position), colour, kc, kl, kq));
    }

    /**
     * What kind of light this is.
     *
     * @return the kind
     */
    public Kind kind() {
        return kind;
    }

    /**
     * The light's colour (diffuse for directional and point lights).
     *
     * @return the colour
     */
    public Colour colour() {
        return values.colour();
    }

    /**
     * The position of a point light, or the unit direction towards a directional light, in the
     * parent's space; zero for an ambient light.
     *
     * @return the position or direction
     */
    public Vec3 vector() {
        return values.vector();
    }

    /**
     * A point light's attenuation kc, kl, kq as (x, y, z); (1, 0, 0) for the other kinds.
     *
     * @return the attenuation
     */
    public Vec3 attenuation() {
        Values v = values;
        return new Vec3(v.kc(), v.kl(), v.kq());
    }

    /**
     * Changes the colour from the next frame on.
     *
     * @param colour the new colour
     * @throws NullPointerException when {@code colour} is null
     */
    public void setColour(Colour colour) {
        Objects.requireNonNull(colour, "colour is null");
        Values v = values;
        set(new Values(v.vector(), colour, v.kc(), v.kl(), v.kq()));
    }

    /**
     * Moves a point light, or turns a directional one, from the next frame on (its group's transform
     * still applies).
     *
     * @param vector a point light's position, or the direction towards a directional light
     * @throws NullPointerException     when {@code vector} is null
     * @throws IllegalArgumentException for a non-finite position, or a zero or non-finite direction
     * @throws IllegalStateException    for an ambient light
     */
    public void setVector(Vec3 vector) {
        Values v = values;
        Vec3 checked = switch (kind) {
            case POINT -> position(vector);
            case DIRECTIONAL -> direction(vector);
            case AMBIENT -> throw new IllegalStateException("an ambient light has no position or direction");
        };
        set(new Values(checked, v.colour(), v.kc(), v.kl(), v.kq()));
    }

    /**
     * Changes a point light's attenuation from the next frame on.
     *
     * @param kc constant attenuation, at least 0
     * @param kl linear attenuation, at least 0
     * @param kq quadratic attenuation, at least 0 (not all three 0)
     * @throws IllegalStateException    for a light that is not a point light
     * @throws IllegalArgumentException for bad attenuation
     */
    public void setAttenuation(double kc, double kl, double kq) {
        if (kind != Kind.POINT) {
            throw new IllegalStateException("only a point light is attenuated");
        }
        Values v = values;
        set(values(v.vector(), v.colour(), kc, kl, kq));
    }

    private void set(Values v) {
        LOCK.lock();
        try {
            if (v.equals(values)) {
                return;
            }
            values = v;
            changed();
        } finally {
            LOCK.unlock();
        }
    }

    /**
     * The light as placed by {@code world} (its parent's space to world space), read under the lock by
     * {@link Scene#capture()}: a position goes through the matrix, a direction through its upper 3x3
     * (as OpenGL transforms a light's position with w = 0) and is normalised again.
     */
    Scene.PlacedLight placed(Mat4 world) {
        Values v = values;
        Vec3 p = v.vector();
        Vec3 w = switch (kind) {
            case AMBIENT -> Vec3.ZERO;
            case POINT -> world.transformProject(p);
            case DIRECTIONAL -> new Vec3(
                    world.get(0, 0) * p.x() + world.get(0, 1) * p.y() + world.get(0, 2) * p.z(),
                    world.get(1, 0) * p.x() + world.get(1, 1) * p.y() + world.get(1, 2) * p.z(),
                    world.get(2, 0) * p.x() + world.get(2, 1) * p.y() + world.get(2, 2) * p.z()).normalize();
        };
        return new Scene.PlacedLight(this, kind, w, v.colour(), v.kc(), v.kl(), v.kq());
    }

    private static Values values(Vec3 position, Colour colour, double kc, double kl, double kq) {
        Objects.requireNonNull(colour, "colour is null");
        if (!Double.isFinite(kc + kl + kq) || !(kc >= 0 && kl >= 0 && kq >= 0) || kc + kl + kq == 0) {
            throw new IllegalArgumentException("attenuation needs finite kc, kl, kq >= 0, not all 0: " + kc + ", "
                    + kl + ", " + kq);
        }
        return new Values(position, colour, kc, kl, kq);
    }

    private static Vec3 position(Vec3 p) {
        Objects.requireNonNull(p, "position is null");
        if (!p.isFinite()) {
            throw new IllegalArgumentException("a point light's position must be finite, not " + p);
        }
        return p;
    }

    /** {@code d} at unit length: any finite non-zero vector, however long or short ({@link Vec3#normalize()}). */
    private static Vec3 direction(Vec3 d) {
        Objects.requireNonNull(d, "direction is null");
        Vec3 unit = d.isFinite() ? d.normalize() : Vec3.ZERO;
        if (unit.length() == 0) {
            throw new IllegalArgumentException("a directional light needs a non-zero finite direction, not " + d);
        }
        return unit;
    }
}
