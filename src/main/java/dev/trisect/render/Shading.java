package dev.trisect.render;

/**
 * How a material is lit (OpenGL's shade model, with lighting off for {@link #NONE}).
 */
public enum Shading {
    /** Not lit: the texture or colour as it is, whatever the lights (the default). */
    NONE,
    /**
     * Lit per vertex, one colour per triangle: that of its last corner, OpenGL's provoking vertex
     * ({@code GL_FLAT}).
     */
    FLAT,
    /** Lit per vertex, the colours interpolated across the triangle ({@code GL_SMOOTH}). */
    SMOOTH
}
