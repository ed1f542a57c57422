package dev.trisect.light;

import java.util.Arrays;

/**
 * A frame's lights, world space, as primitive arrays for the per-vertex stage: the scene's ambient
 * colour, directional lights (a unit vector towards the light) and point lights (a position and
 * constant, linear and quadratic attenuation), each with an ambient and a diffuse colour. Colours are
 * linear r, g, b, 1 meaning full intensity; they are not clamped (OpenGL does not clamp a light's
 * colour, only the lit result). Immutable; build one with {@link #builder()}.
 */
public final class Lights {
    /** Doubles per directional light in {@link #directional()}: tx, ty, tz, ar, ag, ab, dr, dg, db. */
    public static final int DIRECTIONAL_STRIDE = 9;
    /** Doubles per point light in {@link #point()}: x, y, z, ar, ag, ab, dr, dg, db, kc, kl, kq. */
    public static final int POINT_STRIDE = 12;

    /** No light at all: black ambient, no sources. */
    public static final Lights NONE = builder().build();

    private final double[] ambient;
    private final double[] directional;
    private final double[] point;

    private Lights(double[] ambient, double[] directional, double[] point) {
        this.ambient = ambient;
        this.directional = directional;
        this.point = point;
    }

    /** A builder with black ambient and no sources. */
    public static Builder builder() {
        return new Builder();
    }

    /** The scene's ambient colour r, g, b (a copy). */
    public double[] ambient() {
        return ambient.clone();
    }

    /** Directional lights, {@link #DIRECTIONAL_STRIDE} doubles each (a copy). */
    public double[] directional() {
        return directional.clone();
    }

    /** Point lights, {@link #POINT_STRIDE} doubles each (a copy). */
    public double[] point() {
        return point.clone();
    }

    /** Number of directional lights. */
    public int directionalCount() {
        return directional.length / DIRECTIONAL_STRIDE;
    }

    /** Number of point lights. */
    public int pointCount() {
        return point.length / POINT_STRIDE;
    }

    /** The arrays themselves, for the per-vertex loop in this package: never written. */
    double[] ambientArray() {
        return ambient;
    }

    double[] directionalArray() {
        return directional;
    }

    double[] pointArray() {
        return point;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Lights l && Arrays.equals(ambient, l.ambient) && Arrays.equals(directional, l.directional)
                && Arrays.equals(point, l.point);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(ambient) * 31 * 31 + Arrays.hashCode(directional) * 31 + Arrays.hashCode(point);
    }

    @Override
    public String toString() {
        return "Lights(ambient " + Arrays.toString(ambient) + ", " + directionalCount() + " directional, "
                + pointCount() + " point)";
    }

    /** Collects lights; {@link #build()} may be called more than once. */
    public static final class Builder {
        private final double[] ambient = new double[3];
        private double[] directional = new double[0];
        private double[] point = new double[0];

        private Builder() {
        }

        /** Adds r, g, b to the scene's ambient colour (ambient lights sum). */
        public Builder ambient(double r, double g, double b) {
            ambient[0] += finite(r);
            ambient[1] += finite(g);
            ambient[2] += finite(b);
            return this;
        }

        /**
         * A directional light shining from direction (x, y, z), world space (as OpenGL's light position
         * with w = 0); the direction is normalised here.
         *
         * @param ambient its ambient colour r, g, b
         * @param diffuse its diffuse colour r, g, b
         * @throws IllegalArgumentException for a zero or non-finite direction
         */
        public Builder directional(double x, double y, double z, double[] ambient, double[] diffuse) {
            double length = Math.sqrt(x * x + y * y + z * z);
            if (!(length > 0) || !Double.isFinite(length)) {
                throw new IllegalArgumentException("a directional light needs a non-zero finite direction, not "
                        + x + "," + y + "," + z);
            }
            int at = directional.length;
            directional = Arrays.copyOf(directional, at + DIRECTIONAL_STRIDE);
            directional[at] = x / length;
            directional[at + 1] = y / length;
            directional[at + 2] = z / length;
            colours(directional, at + 3, ambient, diffuse);
            return this;
        }

        /**
         * A point light at (x, y, z), world space, attenuated by {@code 1 / (kc + kl d + kq d^2)} at
         * distance d.
         *
         * @throws IllegalArgumentException for a non-finite position, negative attenuation or all three zero
         */
        public Builder point(double x, double y, double z, double[] ambient, double[] diffuse,
                             double kc, double kl, double kq) {
            finite(x);
            finite(y);
            finite(z);
            if (!(finite(kc) >= 0 && finite(kl) >= 0 && finite(kq) >= 0) || kc + kl + kq == 0) {
                throw new IllegalArgumentException("attenuation needs kc, kl, kq >= 0, not all zero: "
                        + kc + "," + kl + "," + kq);
            }
            int at = point.length;
            point = Arrays.copyOf(point, at + POINT_STRIDE);
            point[at] = x;
            point[at + 1] = y;
            point[at + 2] = z;
            colours(point, at + 3, ambient, diffuse);
            point[at + 9] = kc;
            point[at + 10] = kl;
            point[at + 11] = kq;
            return this;
        }

        /** The lights added so far. */
        public Lights build() {
            return new Lights(ambient.clone(), directional.clone(), point.clone());
        }

        private static void colours(double[] into, int at, double[] ambient, double[] diffuse) {
            for (int i = 0; i < 3; i++) {
                into[at + i] = finite(ambient[i]);
                into[at + 3 + i] = finite(diffuse[i]);
            }
        }

        private static double finite(double v) {
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("light values must be finite, not " + v);
            }
            return v;
        }
    }
}
