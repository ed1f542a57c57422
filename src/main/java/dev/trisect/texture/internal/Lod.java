package dev.trisect.texture.internal;

import dev.trisect.texture.TextureFilter;

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
        return lambda(rhoSquared(s, t, r, sDx, tDx, qDx), rhoSquared(s, t, r, sDy, tDy, qDy));
    }

    /**
     * The squared length of the texel-coordinate derivative along one screen direction at one pixel of
     * a perspective map (see {@link #lambdaPerspective}): with the slopes along x,
     * {@code (ds/dx)^2 + (dt/dx)^2}; along y with the y slopes.
     *
     * @param s  the pixel's texel coordinate s = S / Q
     * @param t  the pixel's texel coordinate t = T / Q
     * @param r  1 / Q at the pixel
     * @param sD dS along the direction (plane slope), likewise tD and qD
     */
    public static double rhoSquared(double s, double t, double r, double sD, double tD, double qD) {
        double a = sD - s * qD;
        double b = tD - t * qD;
        return (a * a + b * b) * (r * r);
    }

    /**
     * lambda of one direction, {@code log2(sqrt(rhoSquared))}: {@link #lambda(double, double)} is the
     * larger of the two directions' values, exactly (the logarithm here is monotonic).
     */
    public static double lambdaOf(double rhoSquared) {
        return 0.5 * log2(rhoSquared);
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

    /** {@link #fixed} of a lambda that is NaN: no level of detail to interpolate. */
    public static final int NO_LAMBDA = Integer.MIN_VALUE;

    /**
     * lambda in 1/256 steps, {@code floor(256 lambda)}, clamped to {@code [-256, 256 (maxLevel + 1)]} (beyond
     * that range every value selects the same), or {@link #NO_LAMBDA} for NaN. For stepping the level of
     * detail along a span in integers; {@link #select(int, int)} splits it as {@link #select(double, int)}
     * splits lambda.
     */
    public static int fixed(double lambda, int maxLevel) {
        if (lambda != lambda) {
            return NO_LAMBDA;
        }
        return (int) Math.floor(Math.max(-1, Math.min(maxLevel + 1, lambda)) * Sampler.ONE);
    }

    /** Mantissa bits indexing {@link #LOG2_Q16}: 64 segments. */
    private static final int FAST_BITS = 6;
    /** {@code round(65536 log2(1 + i / 64))} for i = 0..64: log2 of a float's mantissa, in 1/65536. */
    private static final int[] LOG2_Q16 = new int[(1 << FAST_BITS) + 1];

    static {
        for (int i = 0; i < LOG2_Q16.length; i++) {
            LOG2_Q16[i] = (int) Math.round(Math.log1p(i / (double) (1 << FAST_BITS)) / Math.log(2) * 65536);
        }
    }

    /**
     * {@link #fixed}{@code (}{@link #lambdaOf}{@code (rhoSquared), maxLevel)} from the bits of a float,
     * without a logarithm: {@code floor(256 * 0.5 log2(rhoSquared))} in 1/256 level, clamped to
     * {@code [-256, 256 (maxLevel + 1)]}, {@link #NO_LAMBDA} for NaN. log2 is the float's exponent plus
     * log2 of its mantissa interpolated linearly in a 65-entry table, all in integers (the idea of
     * SwiftShader's and llvmpipe's fast log2, which take the mantissa as the fraction, made exact to
     * 5e-5: the chord of log2(1 + x) over 1/64 is within {@code (1/64)^2 / (8 ln 2)} of it, below it as
     * log2 is concave, plus the table's rounding of 2^-17; the float rounding of {@code rhoSquared},
     * relative 2^-24, adds 1e-7). So lambda is within 3e-5 of the exact one, and the floored value is
     * the exact floor except where lambda is that close to a multiple of 1/256, where it may be the
     * step next to it (0.19 % of random values, {@code LodTest}).
     *
     * @param rhoSquared {@code (ds/dx)^2 + (dt/dx)^2} or the same along y, level-0 texels per pixel, squared
     * @param maxLevel   q, the last level's index
     */
    public static int fixedOfSquared(double rhoSquared, int maxLevel) {
        int bits = Float.floatToRawIntBits((float) rhoSquared);
        int exponent = bits >>> 23;
        if (exponent - 1 >= 254) {
            // Zero or subnormal, infinity or NaN, or a negative value (the sign bit makes exponent >= 256).
            if (rhoSquared != rhoSquared) {
                return NO_LAMBDA;
            }
            return exponent == 255 ? (maxLevel + 1) * Sampler.ONE : -Sampler.ONE;
        }
        int mantissa = bits & 0x7FFFFF;
        int index = mantissa >>> (23 - FAST_BITS);
        int fraction = mantissa & (1 << 23 - FAST_BITS) - 1;
        int a = LOG2_Q16[index];
        int log2Q16 = (exponent - 127 << 16) + a + ((LOG2_Q16[index + 1] - a) * fraction >> 23 - FAST_BITS);
        // 256 * 0.5 * log2 = log2Q16 / 512, floored by the arithmetic shift.
        int lambda256 = log2Q16 >> 9;
        return Math.max(-Sampler.ONE, Math.min((maxLevel + 1) * Sampler.ONE, lambda256));
    }

    /**
     * The levels and blend weight ({@link #select(int, int)}) for the squared scale factors of both screen
     * directions, each through {@link #fixedOfSquared}: OpenGL's {@code lambda = log2(max(rho_x, rho_y))}
     * floored to 1/256; level 0 alone when either is NaN.
     *
     * @param rhoX2 {@code (ds/dx)^2 + (dt/dx)^2}, level-0 texels per pixel, squared
     * @param rhoY2 {@code (ds/dy)^2 + (dt/dy)^2}
     */
    public static int selectOfSquared(double rhoX2, double rhoY2, int maxLevel) {
        int lx = fixedOfSquared(rhoX2, maxLevel);
        int ly = fixedOfSquared(rhoY2, maxLevel);
        if (lx == NO_LAMBDA || ly == NO_LAMBDA) {
            return 0;
        }
        return select(Math.max(lx, ly), maxLevel);
    }

    /**
     * {@link #select(double, int)} for a lambda given in 1/256 steps ({@link #fixed}): the same level and
     * weight, since {@code floor(256 lambda) = 256 level + weight} for lambda in (0, maxLevel).
     */
    public static int select(int lambda256, int maxLevel) {
        if (lambda256 <= 0) {
            return 0;
        }
        if (lambda256 >= maxLevel << 8) {
            return maxLevel << 9;
        }
        return (lambda256 >>> 8) << 9 | lambda256 & 0xFF;
    }

    /** The first level of a {@link #select} result. */
    public static int level(int selection) {
        return selection >>> 9;
    }

    /** The weight of the level after {@link #level}, 0..255 in 1/256, of a {@link #select} result. */
    public static int weight(int selection) {
        return selection & 0x1FF;
    }

    /** Mantissa bits indexing {@link #LOG2_TABLE}. */
    private static final int TABLE_BITS = 10;
    /** log2(1 + i / 2^TABLE_BITS) for i = 0..2^TABLE_BITS, for {@link #log2}. */
    private static final double[] LOG2_TABLE = new double[(1 << TABLE_BITS) + 1];

    static {
        for (int i = 0; i < LOG2_TABLE.length; i++) {
            LOG2_TABLE[i] = Math.log1p(i / (double) (1 << TABLE_BITS)) / Math.log(2);
        }
    }

    /**
     * log2(x) for x &gt;= 0 (minus infinity for 0; zero, subnormal and non-finite x go to the exact
     * function): the exponent of x plus log2 of its mantissa interpolated linearly in a table of 1025
     * entries. Absolute error below 2e-7 (the curvature of log2 over a 1/1024 step), so a blend
     * weight quantized to 1/256 comes out as from the exact logarithm but within a hair of a step;
     * several times faster per pixel than {@link Math#log}.
     */
    static double log2(double x) {
        long bits = Double.doubleToRawLongBits(x);
        int exponent = (int) (bits >>> 52) & 0x7FF;
        if (exponent == 0 || exponent == 0x7FF) {
            // Zero or subnormal, infinity or NaN: leave them to the exact function.
            return Math.log(x) * (1 / Math.log(2));
        }
        long mantissa = bits & 0xFFFFFFFFFFFFFL;
        int index = (int) (mantissa >>> (52 - TABLE_BITS));
        double fraction = (mantissa & ((1L << (52 - TABLE_BITS)) - 1)) * (1.0 / (1L << (52 - TABLE_BITS)));
        double a = LOG2_TABLE[index];
        return exponent - 1023 + a + (LOG2_TABLE[index + 1] - a) * fraction;
    }
}
