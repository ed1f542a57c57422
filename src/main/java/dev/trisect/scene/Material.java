package dev.trisect.scene;

import dev.trisect.texture.Texture;
import java.util.Objects;
import java.util.OptionalInt;

/**
 * What a surface shows: a texture, or one colour where there is no texture. Immutable; share it
 * between objects freely.
 *
 * <pre>{@code
 * Material crate = Material.of(TextureReader.read(Path.of("crate.png")));
 * Material grass = Material.colour(0x3A7D2C);
 * }</pre>
 */
public final class Material {
    private final Texture texture;
    private final OptionalInt rgb;

    private Material(Texture texture, OptionalInt rgb) {
        this.texture = texture;
        this.rgb = rgb;
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

    @Override
    public String toString() {
        return "Material(" + texture.name() + ")";
    }
}
