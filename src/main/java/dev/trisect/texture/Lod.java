package dev.trisect.texture;

/**
 * Level of detail for {@link TextureFilter#TRILINEAR}, as OpenGL defines it (OpenGL 4.6 core spec,
 * §8.14.1 "Scale Factor and Level of Detail", eq. 8.6–8.7, and §8.14.3 "Mipmapping"):
 * {@code lambda = log2(rho)} with
 * <pre>
 *   rho = max( sqrt((ds/dx)^2 + (dt/dx)^2), sqrt((ds/dy)^2 + (dt/dy)^2) )
 * </pre>
 * where s, t are level-0 texel coordinates ({@code u * W}, {@code v * H}) and x, y are window
 * pixels. Without a bias or clamps, lambda &gt; c selects minification; with a {@code GL_LINEAR}
 * magnification filter and {@code GL_LINEAR_MIPMAP_LINEAR} minification c = 0 (§8.14.4), so
 * {@code lambda <= 0} samples level 0 bilinearly. Above it, levels {@code d1 = floor(lambda)} and
 * {@code d2 = d1 + 1} (both clamped to the last level q) are sampled bilinearly and blended with
 * weight {@code frac(lambda)} on d2 (eq. 8.12–8.13), quantized to {@link Sampler#FRACTION_BITS} bits.
 *
 * <p>The selection is packed into one int so span loops stay allocation-free:
 * {@code level << 9 | weight}, weight 0..255 of level + 1.
 */
public final class Lod {
    private Lod() {
    }

    /**
     * lambda from the squared scale factors: {@code log2(sqrt(max(rhoX2, rhoY2)))}; minus infinity
     * for zero derivatives.
     *
     * @param rhoX2 {@code (ds/dx)^2 + (dt/dx)^2}, level-0 texels per pixel, squared
     * @param rhoY2 {@code (ds/dy)^2 + (dt/dy)^2}
     */
    public static double lambda(double rhoX2, double rhoY2) {
        return 0.5 * log2(Math.max(rhoX2, rhoY2));
    }

    /** lambda of an affine map with constant derivatives (a piece filled affinely). */
    public static double lambda(double dsdx, double dtdx, double dsdy, double dtdy) {
        return lambda(dsdx * dsdx + dtdx * dtdx, dsdy * dsdy + dtdy * dtdy);
    }

    /**
     * lambda at one pixel of a perspective map, from the exact derivatives of
     * {@code s = S(x, y) / Q(x, y)}, {@code t = T(x, y) / Q(x, y)} with S, T, Q linear on screen:
     * {@code ds/dx = (S_x - s Q_x) / Q} (quotient rule), likewise for t and y.
     *
     * @param s   the pixel's texel coordinate s = S / Q
     * @param t   the pixel's texel coordinate t = T / Q
     * @param r   1 / Q at the pixel
     * @param sDx dS/dx, and so on: the plane slopes
     */
    public static double lambdaPerspective(double s, double t, double r, double sDx, double sDy, double tDx,
                                           double tDy, double qDx, double qDy) {
        double a = sDx - s * qDx;
        double b = tDx - t * qDx;
        double c = sDy - s * qDy;
        double d = tDy - t * qDy;
        return lambda((a * a + b * b) * (r * r), (c * c + d * d) * (r * r));
    }

    /**
     * The levels and blend weight for {@code lambda}: {@code level << 9 | weight} with level the first
     * level (d1) and weight 0..255 the share of level + 1 in 1/256; weight 0 means level alone. Level 0
     * with weight 0 for magnification (lambda &lt;= 0, or NaN), the last level alone for lambda &gt;= q.
     *
     * @param maxLevel q, the last level's index
     */
    public static int select(double lambda, int maxLevel) {
        if (!(lambda > 0)) {
            return 0;
        }
        if (lambda >= maxLevel) {
            return maxLevel << 9;
        }
        int level = (int) lambda;
        int weight = (int) ((lambda - level) * Sampler.ONE);
        return level << 9 | weight;
    }

    /** The first level of a {@link #select} result. */
    public static int level(int selection) {
        return selection >>> 9;
    }

    /** The weight of the level after {@link #level}, 0..255 in 1/256, of a {@link #select} result. */
    public static int weight(int selection) {
        return selection & 0x1FF;
    }

    /** log2(x), minus infinity for 0. */
    static double log2(double x) {
        return Math.log(x) * (1 / Math.log(2));
    }
}
