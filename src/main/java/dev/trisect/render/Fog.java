package dev.trisect.render;

import java.util.Objects;

/**
 * OpenGL's fog (OpenGL 2.1 specification, section 3.10 "Fog"): every pixel's colour C is blended
 * towards the fog colour by its eye-space depth z (the distance from the eye along the view direction,
 * view-space units), as {@code f·C + (1 - f)·fog} with f clamped to [0, 1]:
 * {@link Mode#LINEAR} {@code f = (end - z) / (end - start)}, {@link Mode#EXP} {@code f = exp(-density·z)},
 * {@link Mode#EXP2} {@code f = exp(-(density·z)²)}.
 *
 * <pre>{@code
 * Fog haze = Fog.linear(10, 80, Colour.of(0x9DB8D3));
 * Fog murk = Fog.exp(0.05, Colour.grey(0.5));
 * }</pre>
 *
 * @param mode    the equation
 * @param start   {@link Mode#LINEAR}: depth where fog begins; 0 otherwise
 * @param end     {@link Mode#LINEAR}: depth where only fog is left; 0 otherwise
 * @param density {@link Mode#EXP}, {@link Mode#EXP2}: density per view-space unit; 0 for linear
 * @param colour  the fog's colour (channels above 1 act as 1)
 */
public record Fog(Mode mode, double start, double end, double density, Colour colour) {
    /** OpenGL's three fog equations. */
    public enum Mode {
        /** Linear in depth between a start and an end ({@code GL_LINEAR}). */
        LINEAR,
        /** Exponential in depth ({@code GL_EXP}). */
        EXP,
        /** Exponential in depth squared ({@code GL_EXP2}). */
        EXP2
    }

    /**
     * Checks the values.
     *
     * @param mode    the equation
     * @param start   linear: where fog begins
     * @param end     linear: where only fog is left
     * @param density exp, exp2: the density
     * @param colour  the fog's colour
     * @throws NullPointerException     when {@code mode} or {@code colour} is null
     * @throws IllegalArgumentException for a value that is not finite; a linear fog whose end is not
     *                                  beyond its start, whose end - start is not finite, or whose density
     *                                  is not 0; an exp or exp2 fog whose density is negative, or whose
     *                                  start or end is not 0
     */
    public Fog {
        Objects.requireNonNull(mode, "fog mode is null");
        Objects.requireNonNull(colour, "fog colour is null");
        if (!(Double.isFinite(start) && Double.isFinite(end) && Double.isFinite(density))) {
            throw new IllegalArgumentException("fog values must be finite");
        }
        if (mode == Mode.LINEAR) {
            if (!(end > start)) {
                throw new IllegalArgumentException("linear fog needs end > start, not " + start + ".." + end);
            }
            // factor() divides by end - start: beyond the double range every depth would be all fog.
            if (!Double.isFinite(end - start)) {
                throw new IllegalArgumentException("linear fog's end - start must be finite, not " + start + ".." + end);
            }
            if (density != 0) {
                throw new IllegalArgumentException("linear fog has no density (give 0), not " + density);
            }
        } else {
            if (!(density >= 0)) {
                throw new IllegalArgumentException("fog density must be >= 0, not " + density);
            }
            if (start != 0 || end != 0) {
                throw new IllegalArgumentException(mode.name().toLowerCase(java.util.Locale.ROOT)
                        + " fog has no start or end (give 0), not " + start + ".." + end);
            }
        }
    }

    /**
     * Linear fog from {@code start} to {@code end}.
     *
     * @param start  depth where fog begins, view-space units
     * @param end    depth where only fog is left, beyond {@code start}
     * @param colour the fog's colour
     * @return the fog
     */
    public static Fog linear(double start, double end, Colour colour) {
        return new Fog(Mode.LINEAR, start, end, 0, colour);
    }

    /**
     * Exponential fog.
     *
     * @param density per view-space unit, at least 0
     * @param colour  the fog's colour
     * @return the fog
     */
    public static Fog exp(double density, Colour colour) {
        return new Fog(Mode.EXP, 0, 0, density, colour);
    }

    /**
     * Exponential-squared fog.
     *
     * @param density per view-space unit, at least 0
     * @param colour  the fog's colour
     * @return the fog
     */
    public static Fog exp2(double density, Colour colour) {
        return new Fog(Mode.EXP2, 0, 0, density, colour);
    }

    /**
     * How much of a surface's own colour is left at eye-space depth {@code z}.
     *
     * @param z eye-space depth, view-space units
     * @return f in [0, 1]: 1 no fog, 0 fog colour alone
     */
    public double factor(double z) {
        double f = switch (mode) {
            case LINEAR -> (end - z) / (end - start);
            case EXP -> Math.exp(-density * z);
            case EXP2 -> Math.exp(-(density * z) * (density * z));
        };
        return f < 0 ? 0 : f > 1 ? 1 : f;
    }
}
