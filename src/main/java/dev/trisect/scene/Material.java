package dev.trisect.scene;

import dev.trisect.render.Colour;
import dev.trisect.render.Shading;
import dev.trisect.texture.Texture;
import java.util.Objects;
import java.util.OptionalInt;

/**
 * What a surface shows: a texture, or one colour where there is no texture; and how light falls on
 * it. Immutable; share it between objects freely.
 *
 * <pre>{@code
 * Material crate = Material.of(TextureReader.read(Path.of("crate.png")));
 * Material grass = Material.colour(0x3A7D2C).withShading(Shading.SMOOTH);
 * }</pre>
 *
 * <p>A material is unlit by default ({@link Shading#NONE}): it shows its texture or colour as it is,
 * whatever the scene's {@link Light}s. Lit ({@link Shading#FLAT}, {@link Shading#SMOOTH}), each
 * vertex gets OpenGL's fixed-function colour from the lights and the material's {@link #ambient()} and
 * {@link #diffuse()} colours (both white unless set), and the texture or colour is multiplied by it
 * ({@code GL_MODULATE}; docs/conventions.md, "Light and fog").
 */
public final class Material {
    private final Texture texture;
    private final OptionalInt rgb;
    private final Colour ambient;
    private final Colour diffuse;
    private final Shading shading;

    private Material(Texture texture, OptionalInt rgb, Colour ambient, Colour diffuse, Shading shading) {
        this.texture = texture;
        this.rgb = rgb;
        this.ambient = ambient;
        this.diffuse = diffuse;
        this.shading = shading;
    }

    private Material(Texture texture, OptionalInt rgb) {
        this(texture, rgb, Colour.WHITE, Colour.WHITE, Shading.NONE);
    }

    /**
     * A textured material, sampled with the frame's texture filter.
     *
     * @param texture the texture, not null
     * @return the material
     * @throws NullPointerException when {@code texture} is null
     */
    public static Material of(Texture texture) {
        Objects.requireNonNull(texture,
                "texture is null: read one with TextureReader or Texture.of, or use Material.colour(rgb)");
        return new Material(texture, OptionalInt.empty());
    }

    /**
     * A material of one opaque colour.
     *
     * @param rgb the colour as 0xRRGGBB (any alpha bits are ignored)
     * @return the material
     */
    public static Material colour(int rgb) {
        int opaque = rgb | 0xFF000000;
        return new Material(Texture.solid(String.format("colour #%06X", rgb & 0xFFFFFF), opaque),
                OptionalInt.of(rgb & 0xFFFFFF));
    }

    /**
     * The texture drawn: the material's own, or for a colour material a 1x1 texture of that colour.
     *
     * @return the texture the rasterizer samples
     */
    public Texture texture() {
        return texture;
    }

    /**
     * The colour of a colour material as 0xRRGGBB; empty for a textured material.
     *
     * @return the colour, or empty
     */
    public OptionalInt rgb() {
        return rgb;
    }

    /**
     * How a surface of this material is written, from its texture's alpha ({@link Texture#alpha()}):
     * {@link AlphaMode#OPAQUE} when every alpha is 255, {@link AlphaMode#ALPHA_TEST} when every alpha is 0
     * or 255 (a cut-out), {@link AlphaMode#BLEND} otherwise (see {@link #withOpacity}).
     *
     * @return the mode
     */
    public AlphaMode alphaMode() {
        return switch (texture.alpha()) {
            case OPAQUE -> AlphaMode.OPAQUE;
            case BINARY -> AlphaMode.ALPHA_TEST;
            case PARTIAL -> AlphaMode.BLEND;
        };
    }

    /**
     * How a surface is written, as OpenGL's fixed function writes it (docs/conventions.md, "Transparency").
     */
    public enum AlphaMode {
        /** Depth and colour written wherever the surface is nearest; alpha ignored. */
        OPAQUE,
        /**
         * Drawn only where the texel's alpha is at least 0.5 ({@code GL_ALPHA_TEST}, {@code GL_GEQUAL 0.5}),
         * then as opaque: cut-outs such as leaves and fences, in any order.
         */
        ALPHA_TEST,
        /**
         * Blended over what is behind it, {@code src·a + dst·(1 − a)} by the texel's alpha, depth-tested but
         * not writing depth; objects with such a material are drawn after the others, farthest first.
         */
        BLEND
    }

    /**
     * This material seen through: its texture's alpha multiplied by {@code opacity} (rounded to the
     * nearest of 0..255), so that below 1 it is blended ({@link AlphaMode#BLEND}).
     *
     * @param opacity 0 (invisible) to 1 (as it is)
     * @return a material of the scaled texture
     * @throws IllegalArgumentException when {@code opacity} is outside 0..1
     */
    public Material withOpacity(double opacity) {
        if (!(opacity >= 0 && opacity <= 1)) {
            throw new IllegalArgumentException("opacity must be between 0 and 1, got " + opacity);
        }
        if (opacity == 1) {
            return this;
        }
        int[] argb = texture.argb().clone();
        for (int i = 0; i < argb.length; i++) {
            int a = (int) Math.round((argb[i] >>> 24) * opacity);
            argb[i] = a << 24 | (argb[i] & 0xFFFFFF);
        }
        String name = texture.name() + String.format(java.util.Locale.ROOT, " at opacity %.3f", opacity);
        return new Material(new Texture(name, texture.width(), texture.height(), argb), rgb, ambient, diffuse, shading);
    }

    /**
     * How the material is lit.
     *
     * @return the shading, {@link Shading#NONE} unless set
     */
    public Shading shading() {
        return shading;
    }

    /**
     * The material's ambient colour: the factor of the ambient light it reflects (OpenGL's
     * {@code GL_AMBIENT}).
     *
     * @return the ambient colour, white unless set
     */
    public Colour ambient() {
        return ambient;
    }

    /**
     * The material's diffuse colour: the factor of the directional and point lights it reflects
     * (OpenGL's {@code GL_DIFFUSE}; an MTL file's {@code Kd}).
     *
     * @return the diffuse colour, white unless set
     */
    public Colour diffuse() {
        return diffuse;
    }

    /**
     * This material with another shading.
     *
     * @param shading how it is lit
     * @return the new material
     */
    public Material withShading(Shading shading) {
        return new Material(texture, rgb, ambient, diffuse, Objects.requireNonNull(shading, "shading is null"));
    }

    /**
     * This material with another ambient colour.
     *
     * @param ambient the factor of the ambient light it reflects
     * @return the new material
     */
    public Material withAmbient(Colour ambient) {
        return new Material(texture, rgb, Objects.requireNonNull(ambient, "ambient colour is null"), diffuse, shading);
    }

    /**
     * This material with another diffuse colour.
     *
     * @param diffuse the factor of the directional and point light it reflects
     * @return the new material
     */
    public Material withDiffuse(Colour diffuse) {
        return new Material(texture, rgb, ambient, Objects.requireNonNull(diffuse, "diffuse colour is null"), shading);
    }

    @Override
    public String toString() {
        return "Material(" + texture.name() + (shading == Shading.NONE ? "" : ", " + shading) + ")";
    }
}
