package dev.trisect.raster;

import dev.trisect.render.Framebuffer;
import dev.trisect.texture.Lod;
import dev.trisect.texture.MipChain;
import dev.trisect.texture.Sampler;
import dev.trisect.texture.TextureFilter;

/**
 * The pixel loops of the bilinear and trilinear filters over a set-up triangle's spans (its
 * {@link TriangleSetup} and the spans a {@link SpanSolver} solved). One loop per filter and path, so
 * each inner loop is monomorphic: the choice is made once per triangle, never per pixel. Depth test,
 * depth write and the UV output are exactly those of the nearest loops in {@link NearestSpans}; only
 * the colour differs (docs/conventions.md, "Texture filtering").
 *
 * <ul>
 * <li>Perspective path: every pixel divides, and trilinear takes its level of detail from the exact
 * derivatives of the perspective map ({@link Lod#lambdaPerspective}) at every {@link #LOD_RUN}th
 * column, interpolated linearly in between where that is provably within 3/256 level of it
 * ({@link #nearlyLinear}), per pixel elsewhere.</li>
 * <li>Affine and tessellated paths: the texel coordinates are linear on screen, so their derivatives
 * are constant over the piece and trilinear takes one level of detail per piece ({@link Lod#lambda}),
 * computed once; the levels are stepped in 32.32 fixed point like the nearest affine loop.</li>
 * </ul>
 */
final class FilteredSpans {
    /** 2^32: texel coordinates in 32.32 fixed point. */
    private static final double FIXED_SCALE = 4294967296.0;
    /** Right shift from 32.32 fixed point to the sampler's 8 fraction bits. */
    private static final int TO_SAMPLER = 32 - Sampler.FRACTION_BITS;

    /** log2 of {@link #LOD_RUN}. */
    private static final int LOG2_LOD_RUN = 3;
    /**
     * Columns over which the per-pixel path interpolates lambda linearly between exact values at
     * multiples of this (docs/conventions.md, "Texture filtering").
     */
    static final int LOD_RUN = 1 << LOG2_LOD_RUN;
    /**
     * The largest change, in 1/256, of lambda along x or of lambda along y across a run that is
     * interpolated: half a level. This keeps every chord within one level of the range of levels, so
     * the clamping of {@link Lod#fixed} (one level beyond that range) never bends a chord into a value
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
     * ends floored by {@link Lod#fixed}, the step floored) an interpolated lambda is still within 3/256
     * (0.0117) level of the exact one.
     */
    static final double MAX_CHORD_ERROR_Y = 1.0 / Sampler.ONE;
    /** {@code LOD_RUN^2 / (8 ln 2)}: the chord error over a run per unit of |second derivative| times ln 2. */
    private static final double CHORD_FACTOR = LOD_RUN * LOD_RUN / (8 * Math.log(2));
    /** {@link #lodAt} where there is no level of detail to interpolate (16 high bits below any lambda). */
    private static final int NO_RUN_LOD = Integer.MIN_VALUE;

    private FilteredSpans() {
    }

    /**
     * Fills a set-up triangle's spans with {@code filter} (bilinear or trilinear).
     *
     * @param spans       the covered pixels of each row of {@code setup} (see {@link SpanSolver#spans()})
     * @param perspective the perspective path (per-pixel division and level of detail)
     * @return pixels written
     */
    static long fill(TriangleSetup setup, int[] spans, Framebuffer frame, MipChain mips, int uvId,
                     boolean perspective, TextureFilter filter) {
        boolean trilinear = filter == TextureFilter.TRILINEAR;
        if (perspective || !setup.fixedPointSafe) {
            return perPixel(setup, spans, frame, mips, uvId, perspective, trilinear);
        }
        if (!trilinear) {
            return levelFixed(setup, spans, frame, mips, 0, 0, uvId);
        }
        int selection = Lod.select(Lod.lambda(setup.sPlane.dx, setup.tPlane.dx, setup.sPlane.dy, setup.tPlane.dy),
                mips.maxLevel());
        return levelFixed(setup, spans, frame, mips, Lod.level(selection), Lod.weight(selection), uvId);
    }

    /**
     * Bilinear, or trilinear with the level of detail per pixel, coordinates in doubles: the perspective
     * path, or affine pieces whose coordinates are too large for fixed point (constant derivatives, so
     * the same level everywhere). Lambda along x and along y come from the exact derivatives at the
     * columns that are multiples of {@link #LOD_RUN} ({@link #lodAt}) and are stepped linearly in
     * between, the larger taken per pixel; a run where either changes by more than
     * {@link #MAX_LOD_STEP}, or with no positive 1/w at an end, or that is not {@link #nearlyLinear}
     * (a surface nearly edge-on, or where the texture's derivative along y nearly vanishes), takes the
     * exact lambda per pixel. The
     * runs are anchored at absolute columns, so a pixel's value never depends on the rectangle being
     * filled.
     *
     * <p>On a {@link MipChain#powerOfTwo} chain (every texture of the built-in scenes) each coordinate is
     * floored once, to 8 fraction bits on level 0 ({@code floor(256 s)}), and level d's bilinear
     * position {@code floor(256 s 2^-k) - 128} ({@link Sampler#position} of {@code s * scaleS(d)}, k =
     * log2 of 1 / scaleS(d)) is that value shifted right by k, exactly, since
     * {@code floor(floor(x) / 2^k) = floor(x / 2^k)}; a level is one packed int ({@link MipChain#shape})
     * and wraps with masks. Other chains take {@link Sampler#position} and {@link Sampler#bilinear} per
     * level. The choice is the same for every pixel of the triangle, so its branch is always predicted.
     */
    private static long perPixel(TriangleSetup setup, int[] spans, Framebuffer frame, MipChain mips, int uvId,
                                 boolean perspective, boolean trilinear) {
        double qBase = setup.qPlane.base;
        double qDx = setup.qPlane.dx;
        double qDy = setup.qPlane.dy;
        double sBase = setup.sPlane.base;
        double sDx = setup.sPlane.dx;
        double sDy = setup.sPlane.dy;
        double tBase = setup.tPlane.base;
        double tDx = setup.tPlane.dx;
        double tDy = setup.tPlane.dy;
        // Perspective: s = S / Q, so ds/dx = (S_x - s Q_x) / Q; affine: ds/dx = S_x, so take Q_x = 0
        // in the same formula and a Q of 1.
        double qDxLod = perspective ? qDx : 0;
        double qDyLod = perspective ? qDy : 0;
        int maxLevel = mips.maxLevel();
        boolean pot = mips.powerOfTwo();
        int width = frame.width();
        int[] color = frame.color();
        float[] depth = frame.depth();
        double[] uv = frame.uv();
        long written = 0;
        int[] sp = spans;
        for (int y = setup.rowStart, j = 0; y < setup.rowEnd; y++, j += 2) {
            int spanStart = sp[j];
            int spanEnd = sp[j + 1];
            double qRow = qBase + qDy * y;
            double sRow = sBase + sDy * y;
            double tRow = tBase + tDy * y;
            int rowOffset = y * width;
            // The run of LOD_RUN columns the level of detail was last set up for: lambda along x and
            // along y (1/256 steps) at its first column, their changes to the next run's first column, and
            // whether to interpolate them (else the exact lambda per pixel).
            int runEnd = Integer.MIN_VALUE;
            int lodEnd = 0;
            int lambdaX = 0;
            int lambdaY = 0;
            int stepX = 0;
            int stepY = 0;
            boolean interpolate = false;
            for (int x = spanStart; x < spanEnd; x++) {
                double q = qRow + qDx * x;
                float qf = (float) q;
                int i = rowOffset + x;
                if (qf > depth[i]) {
                    depth[i] = qf;
                    double rq = perspective ? 1.0 / q : 1.0;
                    double s = (sRow + sDx * x) * rq;
                    double t = (tRow + tDx * x) * rq;
                    long sFixed = (long) Math.floor(s * Sampler.ONE);
                    long tFixed = (long) Math.floor(t * Sampler.ONE);
                    int selection = 0;
                    if (trilinear) {
                        if (x >= runEnd) {
                            int runStart = x & -LOD_RUN;
                            int lodStart = runStart == runEnd ? lodEnd
                                    : lodAt(runStart, qRow, sRow, tRow, qDx, sDx, sDy, tDx, tDy, qDxLod, qDyLod,
                                    perspective, maxLevel);
                            runEnd = runStart + LOD_RUN;
                            lodEnd = lodAt(runEnd, qRow, sRow, tRow, qDx, sDx, sDy, tDx, tDy, qDxLod, qDyLod,
                                    perspective, maxLevel);
                            lambdaX = lodStart >> 16;
                            lambdaY = (short) lodStart;
                            stepX = (lodEnd >> 16) - lambdaX;
                            stepY = (short) lodEnd - lambdaY;
                            interpolate = lodStart != NO_RUN_LOD && lodEnd != NO_RUN_LOD
                                    && Math.abs(stepX) <= MAX_LOD_STEP && Math.abs(stepY) <= MAX_LOD_STEP
                                    && nearlyLinear(runStart, qRow, sRow, tRow, qDx, sDx, sDy, tDx, tDy, qDxLod,
                                    qDyLod, perspective);
                        }
                        int k = x & (LOD_RUN - 1);
                        selection = interpolate
                                ? Lod.select(Math.max(lambdaX + (stepX * k >> LOG2_LOD_RUN),
                                lambdaY + (stepY * k >> LOG2_LOD_RUN)), maxLevel)
                                : Lod.select(Lod.lambdaPerspective(s, t, rq, sDx, sDy, tDx, tDy, qDxLod, qDyLod),
                                maxLevel);
                    }
                    int d = Lod.level(selection);
                    int c = pot ? samplePowerOfTwo(mips.texels(d), mips.shape(d), sFixed, tFixed)
                            : sample(mips, d, s, t);
                    int weight = Lod.weight(selection);
                    if (weight != 0) {
                        int e = d + 1;
                        c = Sampler.lerp(c, pot ? samplePowerOfTwo(mips.texels(e), mips.shape(e), sFixed, tFixed)
                                : sample(mips, e, s, t), weight);
                    }
                    color[i] = c;
                    if (uv != null) {
                        uv[3 * i] = s;
                        uv[3 * i + 1] = t;
                        uv[3 * i + 2] = uvId;
                    }
                    written++;
                }
            }
        }
        return written;
    }

    /**
     * The bilinear sample of the level described by {@code shape} ({@link MipChain#shape}) at level-0
     * texel coordinates {@code floor(256 s)}, {@code floor(256 t)}.
     */
    private static int samplePowerOfTwo(int[] texels, int shape, long sFixed, long tFixed) {
        return Sampler.bilinearPowerOfTwo(texels, shape >>> 16 & 0xFF, shape >>> 24,
                (sFixed >> (shape & 0xFF)) - Sampler.ONE / 2, (tFixed >> (shape >>> 8 & 0xFF)) - Sampler.ONE / 2);
    }

    /**
     * The level of detail at column {@code x} of a row whose planes are at qRow, sRow, tRow at column 0,
     * from the exact derivatives there: lambda along x ({@link Lod#lambdaOf} of the x derivatives, in
     * 1/256 steps, {@link Lod#fixed}) in the high 16 bits, along y in the low 16 bits, both signed; or
     * {@link #NO_RUN_LOD} where the perspective plane has no positive 1/w (a column beyond the
     * triangle's edge) or a lambda is NaN.
     */
    private static int lodAt(int x, double qRow, double sRow, double tRow, double qDx, double sDx, double sDy,
                             double tDx, double tDy, double qDxLod, double qDyLod, boolean perspective, int maxLevel) {
        double q = perspective ? qRow + qDx * x : 1.0;
        if (!(q > 0)) {
            return NO_RUN_LOD;
        }
        double rq = 1.0 / q;
        double s = (sRow + sDx * x) * rq;
        double t = (tRow + tDx * x) * rq;
        int lx = Lod.fixed(Lod.lambdaOf(Lod.rhoSquared(s, t, rq, sDx, tDx, qDxLod)), maxLevel);
        int ly = Lod.fixed(Lod.lambdaOf(Lod.rhoSquared(s, t, rq, sDy, tDy, qDyLod)), maxLevel);
        if (lx == Lod.NO_LAMBDA || ly == Lod.NO_LAMBDA) {
            return NO_RUN_LOD;
        }
        return lx << 16 | ly & 0xFFFF;
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
     * moves. The quantizations move the interpolated value down by less than 2/256, so it is within
     * {@code (-E_n - 2/256, E_q + E_n]} of the exact lambda: within 3/256 with these limits.
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

    /** The bilinear sample of level {@code d} of any chain at level-0 texel coordinates (s, t). */
    private static int sample(MipChain mips, int d, double s, double t) {
        return Sampler.bilinear(mips.texels(d), mips.width(d), mips.height(d),
                Sampler.position(s * mips.scaleS(d)), Sampler.position(t * mips.scaleT(d)));
    }

    /**
     * The affine fill, bilinear on {@code level}, blended with weight/256 of {@code level + 1} when
     * weight &gt; 0 (trilinear with the piece's one level of detail). Texel coordinates are stepped in
     * 32.32 fixed point, anchored per row at the triangle's first column as in the nearest affine
     * loop, so a pixel's value never depends on the rectangle being filled: level 0's for the UV
     * output, and each sampled level's, moved by the half texel of {@link Sampler#position}.
     */
    private static long levelFixed(TriangleSetup setup, int[] spans, Framebuffer frame, MipChain mips, int level,
                                   int weight, int uvId) {
        double qBase = setup.qPlane.base;
        double qDx = setup.qPlane.dx;
        double qDy = setup.qPlane.dy;
        double sBase = setup.sPlane.base;
        double sDx = setup.sPlane.dx;
        double sDy = setup.sPlane.dy;
        double tBase = setup.tPlane.base;
        double tDx = setup.tPlane.dx;
        double tDy = setup.tPlane.dy;
        int width = frame.width();
        int[] color = frame.color();
        float[] depth = frame.depth();
        double[] uv = frame.uv();
        int level2 = weight == 0 ? level : level + 1;
        int[] texels = mips.texels(level);
        int tw = mips.width(level);
        int th = mips.height(level);
        int[] texels2 = mips.texels(level2);
        int tw2 = mips.width(level2);
        int th2 = mips.height(level2);
        double ks = mips.scaleS(level) * FIXED_SCALE;
        double kt = mips.scaleT(level) * FIXED_SCALE;
        double ks2 = mips.scaleS(level2) * FIXED_SCALE;
        double kt2 = mips.scaleT(level2) * FIXED_SCALE;
        long ds0 = (long) Math.floor(sDx * FIXED_SCALE);
        long dt0 = (long) Math.floor(tDx * FIXED_SCALE);
        long ds = (long) Math.floor(sDx * ks);
        long dt = (long) Math.floor(tDx * kt);
        long ds2 = (long) Math.floor(sDx * ks2);
        long dt2 = (long) Math.floor(tDx * kt2);
        long half = 1L << 31;
        int firstColumn = setup.firstColumn;
        long written = 0;
        int[] sp = spans;
        for (int y = setup.rowStart, j = 0; y < setup.rowEnd; y++, j += 2) {
            int spanStart = sp[j];
            int spanEnd = sp[j + 1];
            if (spanStart >= spanEnd) {
                continue;
            }
            double qRow = qBase + qDy * y;
            long skip = spanStart - firstColumn;
            double sAnchor = sBase + sDy * y + sDx * firstColumn;
            double tAnchor = tBase + tDy * y + tDx * firstColumn;
            long s0 = (long) Math.floor(sAnchor * FIXED_SCALE) + ds0 * skip;
            long t0 = (long) Math.floor(tAnchor * FIXED_SCALE) + dt0 * skip;
            long s = (long) Math.floor(sAnchor * ks) - half + ds * skip;
            long t = (long) Math.floor(tAnchor * kt) - half + dt * skip;
            long s2 = (long) Math.floor(sAnchor * ks2) - half + ds2 * skip;
            long t2 = (long) Math.floor(tAnchor * kt2) - half + dt2 * skip;
            int rowOffset = y * width;
            for (int x = spanStart; x < spanEnd; x++, s0 += ds0, t0 += dt0, s += ds, t += dt, s2 += ds2, t2 += dt2) {
                float qf = (float) (qRow + qDx * x);
                int i = rowOffset + x;
                if (qf > depth[i]) {
                    depth[i] = qf;
                    int c = Sampler.bilinear(texels, tw, th, s >> TO_SAMPLER, t >> TO_SAMPLER);
                    if (weight != 0) {
                        c = Sampler.lerp(c, Sampler.bilinear(texels2, tw2, th2, s2 >> TO_SAMPLER, t2 >> TO_SAMPLER),
                                weight);
                    }
                    color[i] = c;
                    if (uv != null) {
                        uv[3 * i] = s0 / FIXED_SCALE;
                        uv[3 * i + 1] = t0 / FIXED_SCALE;
                        uv[3 * i + 2] = uvId;
                    }
                    written++;
                }
            }
        }
        return written;
    }
}
