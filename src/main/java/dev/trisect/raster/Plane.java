package dev.trisect.raster;

/**
 * An attribute that is linear in screen space, over pixel centres: its value at pixel (x, y) is
 * {@code base + dx * x + dy * y}, the centre being at (x + 0.5, y + 0.5) in pixels.
 */
final class Plane {
    double base;
    double dx;
    double dy;

    /**
     * Fits the plane through three corners: value {@code v0} at corner 0, (x0, y0) in pixels, and
     * {@code v1}, {@code v2} at the corners offset by (ex1, ey1) and (ex2, ey2) from it.
     *
     * @param inv {@code 1 / (ex1 * ey2 - ex2 * ey1)}, shared by the planes of one triangle
     */
    void fit(double x0, double y0, double ex1, double ey1, double ex2, double ey2, double inv,
             double v0, double v1, double v2) {
        double d1 = v1 - v0;
        double d2 = v2 - v0;
        dx = (d1 * ey2 - d2 * ey1) * inv;
        dy = (d2 * ex1 - d1 * ex2) * inv;
        base = v0 + dx * (0.5 - x0) + dy * (0.5 - y0);
    }
}
