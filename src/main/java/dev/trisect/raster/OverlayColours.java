package dev.trisect.raster;

/**
 * The colours the border overlay draws a triangle's outline in, chosen in this one place so that
 * further colourings (by depth, by bound) extend it rather than the drawing code.
 */
public final class OverlayColours {
    /** An ordinary piece (or triangle): yellow, #FFFF00. */
    public static final int PIECE = 0xFFFFFF00;
    /**
     * A piece a cap stopped short of its split policy, filled per pixel by the fallback: magenta,
     * #FF00FF, which no ordinary outline uses and which stands out on most textures.
     */
    public static final int FALLBACK = 0xFFFF00FF;

    private OverlayColours() {
    }

    /** The outline colour of triangle {@code tri}, ARGB with opaque alpha. */
    static int of(ScreenTriangles triangles, int tri) {
        return triangles.perPixel()[tri] ? FALLBACK : PIECE;
    }
}
