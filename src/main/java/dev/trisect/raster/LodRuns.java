package dev.trisect.raster;

import dev.trisect.texture.internal.Lod;
import dev.trisect.texture.internal.Sampler;

/**
 * Trilinear's level of detail: that of the per-pixel loop ({@link PerPixelLoops}) over runs of
 * {@link #LOD_RUN} columns: lambda along x and along y exact at the columns that are multiples of
 * {@link #LOD_RUN} ({@link #lodAt}), interpolated linearly in between where the chord is provably
 * within 3/256 level of the exact value ({@link #nearlyLinear}), and exact per pixel elsewhere
 * (docs/conventions.md, "Texture filtering"). Static and allocation-free: a pixel loop calls these
 * once per run.
 */
final class LodRuns {
    /** log2 of {@link #LOD_RUN}. */
    static final int LOG2_LOD_RUN = 3;
    /**
     * Columns over which the per-pixel path interpolates lambda linearly between exact values at
     * multiples of this (docs/conventions.md, "Texture filtering").
     */
    static final int LOD_RUN = 1 << LOG2_LOD_RUN;
    /**
     * The largest change, in 1/256, of lambda along x or of lambda along y across a run that is
     * interpolated: half a level. This keeps every chord within one level of the range of levels, so
     * the clamping of {@link Lod#fixedOfSquared} (one level beyond that range) never bends a chord into a value
     * that selects differently; how close the chord is to lambda is {@link #nearlyLinear}'s test.
     */
    static final int MAX_LOD_STEP = Sampler.ONE / 2;
    /**
     * The largest bound, in levels, on how far the chord over an interpolated run may be from the exact
     * lambda along an axis ({@link #nearlyLinear}): 3/256.
     */
    static final double MAX_CHORD_ERROR = 3.0 / Sampler.ONE;
    /**
     * The largest bound on the part of that from the numerator of lambda along y that is interpolated
     * ({@link #nearlyLinear}): 1/256, so that with the two quantizations to 1/256 below the chord (the
     * ends floored by {@link Lod#fixedOfSquared}, the step floored) an interpolated lambda is still within
     * 3/256 (0.0117) level of the exact one, plus the 3e-5 of that function's logarithm.
     */
    static final double MAX_CHORD_ERROR_Y = 1.0 / Sampler.ONE;
    /** {@code LOD_RUN^2 / (8 ln 2)}: the chord error over a run per unit of |second derivative| times ln 2. */
    private static final double CHORD_FACTOR = LOD_RUN * LOD_RUN / (8 * Math.log(2));
    /** {@link #lodAt} where there is no level of detail to interpolate (16 high bits below any lambda). */
    static final int NO_RUN_LOD = Integer.MIN_VALUE;

    private LodRuns() {
    }

    /**
     * The level of detail at column {@code x} of a row whose planes are at qRow, sRow, tRow at column 0,
     * from the exact derivatives there: lambda along x (of the x derivatives, in 1/256 steps,
     * {@link Lod#fixedOfSquared}) in the high 16 bits, along y in the low 16 bits, both signed; or
     * {@link #NO_RUN_LOD} where the perspective plane has no positive 1/w (a column beyond the
     * triangle's edge) or a lambda is NaN.
     */
    static int lodAt(int x, double qRow, double sRow, double tRow, double qDx, double sDx, double sDy,
                     double tDx, double tDy, double qDxLod, double qDyLod, boolean perspective, int maxLevel) {
        double q = perspective ? qRow + qDx * x : 1.0;
        if (!(q > 0)) {
            return NO_RUN_LOD;
        }
        double rq = 1.0 / q;
        double s = (sRow + sDx * x) * rq;
        double t = (tRow + tDx * x) * rq;
        int lx = Lod.fixedOfSquared(Lod.rhoSquared(s, t, rq, sDx, tDx, qDxLod), maxLevel);
        int ly = Lod.fixedOfSquared(Lod.rhoSquared(s, t, rq, sDy, tDy, qDyLod), maxLevel);
        if (lx == Lod.NO_LAMBDA || ly == Lod.NO_LAMBDA) {
            return NO_RUN_LOD;
        }
        return lx << 16 | ly & 0xFFFF;
    }

    /**
     * OpenGL's lambda at a pixel of a perspective map, in 1/256 level ({@link Lod#fixedOfSquared} of
     * each axis, the larger), or {@link Lod#NO_LAMBDA}: the span path's level of detail at a knot.
     *
     * @param s the pixel's exact texel coordinate s = S / Q, likewise t
     * @param r 1 / Q there
     */
    static int lambdaAt(double s, double t, double r, double sDx, double sDy, double tDx, double tDy, double qDx,
                        double qDy, int maxLevel) {
        int lx = Lod.fixedOfSquared(Lod.rhoSquared(s, t, r, sDx, tDx, qDx), maxLevel);
        int ly = Lod.fixedOfSquared(Lod.rhoSquared(s, t, r, sDy, tDy, qDy), maxLevel);
        return lx == Lod.NO_LAMBDA || ly == Lod.NO_LAMBDA ? Lod.NO_LAMBDA : Math.max(lx, ly);
    }

    /**
     * Whether lambda along x and along y are close enough to linear over the run of columns
     * [x0, x0 + LOD_RUN] of a row (planes at qRow, sRow, tRow at column 0) to be interpolated within
     * 3/256 level: {@code E_q + E_n <= }{@link #MAX_CHORD_ERROR} and {@code E_n <= }
     * {@link #MAX_CHORD_ERROR_Y}, the two bounds below (both 0 for an affine map). Both ends must
     * have a positive 1/w (Q linear, so positive over the run).
     *
     * <p>Why: with s = S/Q, t = T/Q and S, T, Q linear on screen, the numerators of the derivatives
     * along y, {@code A = S_y Q - S Q_y} and {@code B = T_y Q - T Q_y}, are linear in x along a row
     * (slopes {@code A_x = S_y Q_x - S_x Q_y}, likewise B_x), and {@code lambda_y = f - 2 log2 Q} with
     * {@code f = 0.5 log2 N}, {@code N = A^2 + B^2 = a u^2 + m} (u the distance to the column where N
     * is least, {@code a = A_x^2 + B_x^2}). Along x the numerators are constant along the row, so
     * {@code lambda_x = c - 2 log2 Q}. The chord of a function over h columns is within
     * {@code h^2/8 max|g''|} of it, on the side of the chord where g is convex. {@code -2 log2 Q} is
     * convex, {@code (-2 log2 Q)'' = 2 Q_x^2 / (ln2 Q^2)}, largest at the end with the smaller Q: its
     * chord is above it by at most {@code E_q = h^2 / (8 ln2) 2 Q_x^2 / Q_min^2}.
     * {@code f'' = a (m - a u^2) / (ln2 N^2)}, so {@code |f''| <= a / (ln2 N) <= a / (ln2 N_min)}
     * with N_min the least N over the run (at the column nearest the unconstrained least): its chord
     * is within {@code E_n = h^2 / (8 ln2) a / N_min} either way. So the chord of lambda along x is
     * within [0, E_q] above it and that of lambda along y within [-E_n, E_q + E_n]; the larger of the
     * two (OpenGL's lambda) likewise, since {@code max} moves by at most the larger of its arguments'
     * moves. The quantizations move the interpolated value down by less than 2/256, and the ends'
     * logarithm from the float's bits ({@link Lod#fixedOfSquared}) is within 3e-5 of the exact one, so it
     * is within {@code (-E_n - 2/256 - 3e-5, E_q + E_n + 3e-5]} of the exact lambda: within 3/256 + 3e-5
     * with these limits.
     */
    static boolean nearlyLinear(int x0, double qRow, double sRow, double tRow, double qDx, double sDx, double sDy,
                                double tDx, double tDy, double qDxLod, double qDyLod, boolean perspective) {
        int x1 = x0 + LOD_RUN;
        double q0 = perspective ? qRow + qDx * x0 : 1.0;
        double q1 = perspective ? qRow + qDx * x1 : 1.0;
        double qMin = Math.min(q0, q1);
        double qMin2 = qMin * qMin;
        // E_q = CHORD_FACTOR * qCurvature / qMin^2.
        double qCurvature = 2 * qDxLod * qDxLod;
        // A and B at column x0 and their slopes along the row.
        double a0 = sDy * q0 - (sRow + sDx * x0) * qDyLod;
        double b0 = tDy * q0 - (tRow + tDx * x0) * qDyLod;
        double ax = sDy * qDxLod - sDx * qDyLod;
        double bx = tDy * qDxLod - tDx * qDyLod;
        double a = ax * ax + bx * bx;
        if (!(a > 0)) {
            // N constant along the row: E_n = 0.
            return CHORD_FACTOR * qCurvature <= MAX_CHORD_ERROR * qMin2;
        }
        // a * N_min without a division: N(u) = n0 + 2 p u + a u^2 over u in [0, LOD_RUN] is least at
        // u = -p / a clamped to the run, where a N = a n0 - p^2.
        double n0 = a0 * a0 + b0 * b0;
        double p = a0 * ax + b0 * bx;
        double aNMin = p >= 0 ? a * n0
                : p <= -a * LOD_RUN ? a * (n0 + LOD_RUN * (2 * p + a * LOD_RUN))
                : a * n0 - p * p;
        if (!(aNMin > 0)) {
            return false;
        }
        // E_n = CHORD_FACTOR * a^2 / aNMin; both limits multiplied through by aNMin qMin^2 > 0.
        double en = CHORD_FACTOR * a * a;
        return en <= MAX_CHORD_ERROR_Y * aNMin
                && CHORD_FACTOR * qCurvature * aNMin + en * qMin2 <= MAX_CHORD_ERROR * aNMin * qMin2;
    }
}
