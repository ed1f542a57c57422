package dev.trisect.texture;

import java.util.Locale;

/**
 * How a texture is sampled, each exactly as the OpenGL filter it is named after with {@code GL_REPEAT}
 * (docs/conventions.md, "Texture filtering").
 */
public enum TextureFilter {
    /** {@code GL_NEAREST}: the texel whose square holds the sample point. */
    NEAREST,
    /** {@code GL_LINEAR}: the four texels around the sample point on level 0, weighted by distance. */
    BILINEAR,
    /**
     * {@code GL_LINEAR_MIPMAP_LINEAR} with a {@code GL_LINEAR} magnification filter: bilinear on the two
     * mipmap levels nearest the level of detail, blended by its fraction.
     */
    TRILINEAR;

    /**
     * The name used on the command line: nearest, bilinear or trilinear.
     *
     * @return the filter's name on the command line and in statistics
     */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }
}
