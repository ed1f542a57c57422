package dev.trisect.light;

import dev.trisect.render.Colour;
import dev.trisect.render.Shading;
import java.util.Objects;

/**
 * How light falls on one material: its shading and its ambient and diffuse colours (the factors
 * {@code a_m}, {@code d_m} of {@link LightingEquation}).
 *
 * @param shading how it is lit; {@link Shading#NONE} not at all
 * @param ambient its ambient colour
 * @param diffuse its diffuse colour
 */
public record Surface(Shading shading, Colour ambient, Colour diffuse) {
    /** Not lit: today's look. */
    public static final Surface UNLIT = new Surface(Shading.NONE, Colour.WHITE, Colour.WHITE);

    /** Checks for nulls. */
    public Surface {
        Objects.requireNonNull(shading, "shading");
        Objects.requireNonNull(ambient, "ambient");
        Objects.requireNonNull(diffuse, "diffuse");
    }

    /** Whether the material is lit. */
    public boolean lit() {
        return shading != Shading.NONE;
    }

    /** Writes a_m then d_m, r, g, b each, at {@code into[at..at+5]} ({@link LightingEquation#MATERIAL_STRIDE}). */
    public void factors(double[] into, int at) {
        into[at] = ambient.r();
        into[at + 1] = ambient.g();
        into[at + 2] = ambient.b();
        into[at + 3] = diffuse.r();
        into[at + 4] = diffuse.g();
        into[at + 5] = diffuse.b();
    }
}
