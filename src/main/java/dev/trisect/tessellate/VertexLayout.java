package dev.trisect.tessellate;

/**
 * The one vertex layout of the geometry stages: doubles per vertex in a primitive array, at these
 * offsets from the vertex's start. The clipper's vertices and the tessellator's input are
 * {@link #CLIP_STRIDE} doubles (clip space and texel coordinates); the tessellator's vertices, which a
 * {@link PieceSink} reads, are {@link #PROJECTED_STRIDE} doubles, the same followed by the screen position.
 */
public final class VertexLayout {
    /** Clip-space x, y, z, w (OpenGL's clip coordinates; w is the view depth, &gt; 0 once clipped). */
    public static final int X = 0;
    public static final int Y = 1;
    public static final int Z = 2;
    public static final int W = 3;
    /** Texel coordinates s = u * width, t = v * height of the material's texture, level-0 texels. */
    public static final int S = 4;
    public static final int T = 5;
    /** Doubles per vertex in clip space with texel coordinates: x, y, z, w, s, t. */
    public static final int CLIP_STRIDE = 6;
    /** Screen position in pixels, x right and y down (see {@link dev.trisect.math.Viewport}). */
    public static final int SCREEN_X = 6;
    public static final int SCREEN_Y = 7;
    /** Doubles per projected vertex: x, y, z, w, s, t, screen x, screen y. */
    public static final int PROJECTED_STRIDE = 8;

    private VertexLayout() {
    }
}
