package dev.trisect.raster;

/**
 * The sub-pixel grid that vertices are snapped to before edge setup: 8 fractional bits, 1/256 pixel.
 *
 * <p>Snapping makes the edge functions exact integers, so a shared edge is evaluated bit-identically
 * from both of its triangles and the top-left rule can give every pixel centre on it to exactly one
 * of them (Giesen, "The barycentric conspiracy" and "Triangle rasterization in practice", 2013).
 */
public final class FixedPoint {
    /** Fractional bits of a snapped coordinate. */
    public static final int BITS = 8;
    /** Sub-pixel steps per pixel. */
    public static final int ONE = 1 << BITS;
    /** A pixel centre's offset within its pixel, in sub-pixel steps. */
    public static final int HALF = ONE / 2;

    private FixedPoint() {
    }

    /** A screen coordinate in pixels snapped to the grid, rounding to nearest (ties to even, as lrint). */
    public static int snap(double pixels) {
        return (int) Math.rint(pixels * ONE);
    }
}
