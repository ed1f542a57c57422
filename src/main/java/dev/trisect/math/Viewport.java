package dev.trisect.math;

/**
 * The mapping from OpenGL normalized device coordinates to screen space, as {@code glViewport(0, 0,
 * width, height)} followed by a flip so that image row 0 is the top row.
 *
 * <p>Screen space is in pixels: x grows to the right, y grows downward, and pixel (i, j) covers
 * [i, i+1) x [j, j+1) with its centre at (i + 0.5, j + 0.5).
 *
 * @param width  frame width in pixels, &gt;= 1
 * @param height frame height in pixels, &gt;= 1
 */
public record Viewport(int width, int height) {

    /** Largest frame side accepted, in pixels. */
    public static final int MAX_SIDE = 16384;

    /**
     * Checks the size.
     *
     * @param width  pixels, 1..{@link #MAX_SIDE}
     * @param height pixels, 1..{@link #MAX_SIDE}
     * @throws IllegalArgumentException for a side out of range
     */
    public Viewport {
        if (width < 1 || height < 1 || width > MAX_SIDE || height > MAX_SIDE) {
            throw new IllegalArgumentException("frame size " + width + "x" + height + " is outside 1.." + MAX_SIDE);
        }
    }

    /**
     * Width / height, the aspect ratio given to the projection.
     *
     * @return {@code width / height}
     */
    public double aspect() {
        return (double) width / height;
    }

    /**
     * Screen x in pixels of a clip-space point (x, w); needs w &gt; 0.
     *
     * @param clipX clip-space x
     * @param clipW clip-space w
     * @return pixels from the left edge
     */
    public double screenX(double clipX, double clipW) {
        return (clipX / clipW + 1) * 0.5 * width;
    }

    /**
     * Screen y in pixels (downward) of a clip-space point (y, w); needs w &gt; 0.
     *
     * @param clipY clip-space y
     * @param clipW clip-space w
     * @return pixels from the top edge
     */
    public double screenY(double clipY, double clipW) {
        return (1 - clipY / clipW) * 0.5 * height;
    }
}
