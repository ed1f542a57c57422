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

    /**
     * The first pixel (row or column) whose centre is at or after {@code v} sub-pixel steps:
     * ceil((v - HALF) / ONE), by a shift (an arithmetic shift is floor division by a power of two for
     * every int, where {@link Math#floorDiv} by the constant costs a division's fix-ups and a branch, per
     * triangle and band).
     */
    static int firstCentre(int v) {
        return -((HALF - v) >> BITS);
    }

    /** One past the last pixel whose centre is at or before {@code v} sub-pixel steps: floor((v - HALF) / ONE) + 1. */
    static int endCentre(int v) {
        return ((v - HALF) >> BITS) + 1;
    }

    /** A screen coordinate in pixels snapped to the grid, rounding to nearest (ties to even, as lrint). */
    public static int snap(double pixels) {
        return (int) Math.rint(pixels * ONE);
    }
}
