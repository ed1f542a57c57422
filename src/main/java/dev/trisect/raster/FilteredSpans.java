package dev.trisect.raster;

import dev.trisect.render.Framebuffer;
import dev.trisect.texture.internal.LaneSampler;
import dev.trisect.texture.internal.Lod;
import dev.trisect.texture.MipChain;
import dev.trisect.texture.internal.Sampler;
import dev.trisect.texture.internal.TexelLanes;
import dev.trisect.texture.TextureFilter;

/**
 * The pixel loops of the bilinear and trilinear filters over a set-up triangle's spans (its
 * {@link TriangleSetup} and the spans a {@link SpanSolver} solved). One loop per filter and path, so
 * each inner loop is monomorphic: the choice is made once per triangle, never per pixel. Depth test,
 * depth write and the UV output are exactly those of the nearest loops ({@link PerPixelNearest}, {@link FixedNearest}); only
 * the colour differs (docs/conventions.md, "Texture filtering"). Every sample is taken by
 * {@link LaneSampler} on the chain's {@link TexelLanes}: the packed blend with 8-bit weights.
 *
 * <ul>
 * <li>Perspective path: every pixel divides, and trilinear takes its level of detail from the exact
 * derivatives of the perspective map at every {@link LodRuns#LOD_RUN}th column, interpolated
 * linearly in between where that is provably within 3/256 level of it ({@link LodRuns}), per pixel
 * elsewhere.</li>
 * <li>Affine and tessellated paths: the texel coordinates are linear on screen, so their derivatives
 * are constant over the piece and trilinear takes one level of detail per piece
 * ({@link Lod#selectOfSquared}), computed once; the levels are stepped in 32.32 fixed point like
 * the nearest affine loop.</li>
 * </ul>
 */
final class FilteredSpans {
    /** 2^32: texel coordinates in 32.32 fixed point. */
    private static final double FIXED_SCALE = 4294967296.0;
    /** Right shift from 32.32 fixed point to the sampler's 8 fraction bits. */
    private static final int TO_SAMPLER = 32 - Sampler.FRACTION_BITS;


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
            return trilinear || !mips.powerOfTwo()
                    ? perPixel(setup, spans, frame, mips, uvId, perspective, trilinear)
                    : perPixelBilinear(setup, spans, frame, TexelLanes.of(mips), uvId, perspective);
        }
        if (!trilinear) {
            return levelFixed(setup, spans, frame, mips, 0, 0, uvId);
        }
        double sDx = setup.sPlane.dx;
        double tDx = setup.tPlane.dx;
        double sDy = setup.sPlane.dy;
        double tDy = setup.tPlane.dy;
        int selection = Lod.selectOfSquared(sDx * sDx + tDx * tDx, sDy * sDy + tDy * tDy, mips.maxLevel());
        return levelFixed(setup, spans, frame, mips, Lod.level(selection), Lod.weight(selection), uvId);
    }

    /**
     * Bilinear, or trilinear with the level of detail per pixel, coordinates in doubles: the perspective
     * path, or affine pieces whose coordinates are too large for fixed point (constant derivatives, so
     * the same level everywhere). Lambda along x and along y come from the exact derivatives at the
     * columns that are multiples of {@link LodRuns#LOD_RUN} ({@link LodRuns#lodAt}) and are stepped
     * linearly in between, the larger taken per pixel; a run where either changes by more than
     * {@link LodRuns#MAX_LOD_STEP}, or with no positive 1/w at an end, or that is not
     * {@link LodRuns#nearlyLinear} (a surface nearly edge-on, or where the texture's derivative along y
     * nearly vanishes), takes the exact lambda per pixel ({@link Lod#selectOfSquared}). The runs are
     * anchored at absolute columns, so a pixel's value never depends on the rectangle being filled.
     *
     * <p>On a {@link MipChain#powerOfTwo} chain (every texture of the built-in scenes) each coordinate is
     * floored once, to 8 fraction bits on level 0 ({@code floor(256 s)}), and level d's bilinear
     * position {@code floor(256 s 2^-k) - 128} ({@link Sampler#position} of {@code s * scaleS(d)}, k =
     * log2 of 1 / scaleS(d)) is that value shifted right by k, exactly, since
     * {@code floor(floor(x) / 2^k) = floor(x / 2^k)}: {@link LaneSampler#bilinearPowerOfTwo} on the
     * chain's {@link TexelLanes}, whose levels wrap with masks, blended as
     * {@link LaneSampler#trilinearPowerOfTwo} does; the two levels' descriptors are held in locals and
     * reloaded only when the level changes (2-5 % of the trilinear frame). Other chains take {@link Sampler#position}
     * and {@link LaneSampler#bilinear} per level. The choice is the same for every pixel of the triangle,
     * so its branch is always predicted.
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
        TexelLanes lanes = TexelLanes.of(mips);
        long[] lz = lanes.lanes();
        int[] lv = lanes.levels();
        int level = -1;
        int off1 = 0;
        int stride1 = 0;
        int wm1 = 0;
        int hm1 = 0;
        int ss1 = 0;
        int ts1 = 0;
        int off2 = 0;
        int stride2 = 0;
        int wm2 = 0;
        int hm2 = 0;
        int ss2 = 0;
        int ts2 = 0;
        int width = frame.width();
        int[] color = frame.colour();
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
            // The column as a double counter, not (double) x: see PerPixelNearest.
            double xd = spanStart;
            for (int x = spanStart; x < spanEnd; x++, xd++) {
                double q = qRow + qDx * xd;
                float qf = (float) q;
                int i = rowOffset + x;
                if (qf > depth[i]) {
                    depth[i] = qf;
                    double rq = perspective ? 1.0 / q : 1.0;
                    double s = (sRow + sDx * xd) * rq;
                    double t = (tRow + tDx * xd) * rq;
                    long sFixed = (long) Math.floor(s * Sampler.ONE);
                    long tFixed = (long) Math.floor(t * Sampler.ONE);
                    int selection = 0;
                    if (trilinear) {
                        if (x >= runEnd) {
                            int runStart = x & -LodRuns.LOD_RUN;
                            int lodStart = runStart == runEnd ? lodEnd
                                    : LodRuns.lodAt(runStart, qRow, sRow, tRow, qDx, sDx, sDy, tDx, tDy, qDxLod, qDyLod,
                                    perspective, maxLevel);
                            runEnd = runStart + LodRuns.LOD_RUN;
                            lodEnd = LodRuns.lodAt(runEnd, qRow, sRow, tRow, qDx, sDx, sDy, tDx, tDy, qDxLod, qDyLod,
                                    perspective, maxLevel);
                            lambdaX = lodStart >> 16;
                            lambdaY = (short) lodStart;
                            stepX = (lodEnd >> 16) - lambdaX;
                            stepY = (short) lodEnd - lambdaY;
                            interpolate = lodStart != LodRuns.NO_RUN_LOD && lodEnd != LodRuns.NO_RUN_LOD
                                    && Math.abs(stepX) <= LodRuns.MAX_LOD_STEP
                                    && Math.abs(stepY) <= LodRuns.MAX_LOD_STEP
                                    && LodRuns.nearlyLinear(runStart, qRow, sRow, tRow, qDx, sDx, sDy, tDx, tDy,
                                    qDxLod, qDyLod, perspective);
                        }
                        int k = x & (LodRuns.LOD_RUN - 1);
                        selection = interpolate
                                ? Lod.select(Math.max(lambdaX + (stepX * k >> LodRuns.LOG2_LOD_RUN),
                                lambdaY + (stepY * k >> LodRuns.LOG2_LOD_RUN)), maxLevel)
                                : Lod.selectOfSquared(Lod.rhoSquared(s, t, rq, sDx, tDx, qDxLod),
                                Lod.rhoSquared(s, t, rq, sDy, tDy, qDyLod), maxLevel);
                    }
                    int c;
                    if (pot) {
                        int d = Lod.level(selection);
                        if (d != level) {
                            // The two levels' descriptors, reloaded only when the level changes.
                            level = d;
                            int o = d * TexelLanes.LEVEL_INTS;
                            int o2 = Math.min(d + 1, maxLevel) * TexelLanes.LEVEL_INTS;
                            off1 = lv[o + TexelLanes.OFFSET];
                            stride1 = lv[o + TexelLanes.STRIDE];
                            wm1 = lv[o + TexelLanes.WIDTH_MASK];
                            hm1 = lv[o + TexelLanes.HEIGHT_MASK];
                            ss1 = lv[o + TexelLanes.SHIFT_S];
                            ts1 = lv[o + TexelLanes.SHIFT_T];
                            off2 = lv[o2 + TexelLanes.OFFSET];
                            stride2 = lv[o2 + TexelLanes.STRIDE];
                            wm2 = lv[o2 + TexelLanes.WIDTH_MASK];
                            hm2 = lv[o2 + TexelLanes.HEIGHT_MASK];
                            ss2 = lv[o2 + TexelLanes.SHIFT_S];
                            ts2 = lv[o2 + TexelLanes.SHIFT_T];
                        }
                        long l = LaneSampler.bilinearPowerOfTwo(lz, off1, stride1, wm1, hm1,
                                (sFixed >> ss1) - Sampler.ONE / 2, (tFixed >> ts1) - Sampler.ONE / 2);
                        int weight = Lod.weight(selection);
                        if (weight != 0) {
                            l = LaneSampler.lerp(l, LaneSampler.bilinearPowerOfTwo(lz, off2, stride2, wm2, hm2,
                                    (sFixed >> ss2) - Sampler.ONE / 2, (tFixed >> ts2) - Sampler.ONE / 2), weight);
                        }
                        c = TexelLanes.argb(l);
                    } else {
                        int d = Lod.level(selection);
                        long l = sample(lz, lv, mips, d, s, t);
                        int weight = Lod.weight(selection);
                        if (weight != 0) {
                            l = LaneSampler.lerp(l, sample(lz, lv, mips, d + 1, s, t), weight);
                        }
                        c = TexelLanes.argb(l);
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
     * Bilinear on level 0 of a {@link MipChain#powerOfTwo} chain with the texel coordinates in doubles:
     * the perspective path, or affine pieces whose coordinates are too large for fixed point. Each
     * coordinate is floored once to 8 fraction bits, {@code floor(256 s) - 128 = floor(256 (s - 1/2))},
     * the position {@link LaneSampler} takes. A loop of its own, without the level of detail and the
     * general wrap of {@link #perPixel}: 13 % less CPU time for the demo's bilinear frame.
     */
    private static long perPixelBilinear(TriangleSetup setup, int[] spans, Framebuffer frame, TexelLanes lanes,
                                         int uvId, boolean perspective) {
        double qBase = setup.qPlane.base;
        double qDx = setup.qPlane.dx;
        double qDy = setup.qPlane.dy;
        double sBase = setup.sPlane.base;
        double sDx = setup.sPlane.dx;
        double sDy = setup.sPlane.dy;
        double tBase = setup.tPlane.base;
        double tDx = setup.tPlane.dx;
        double tDy = setup.tPlane.dy;
        long[] lz = lanes.lanes();
        int[] lv = lanes.levels();
        int stride = lv[TexelLanes.STRIDE];
        int wMask = lv[TexelLanes.WIDTH_MASK];
        int hMask = lv[TexelLanes.HEIGHT_MASK];
        int width = frame.width();
        int[] color = frame.colour();
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
            // The column as a double counter, not (double) x: see PerPixelNearest.
            double xd = spanStart;
            for (int x = spanStart; x < spanEnd; x++, xd++) {
                double q = qRow + qDx * xd;
                float qf = (float) q;
                int i = rowOffset + x;
                if (qf > depth[i]) {
                    depth[i] = qf;
                    double rq = perspective ? 1.0 / q : 1.0;
                    double s = (sRow + sDx * xd) * rq;
                    double t = (tRow + tDx * xd) * rq;
                    color[i] = TexelLanes.argb(LaneSampler.bilinearPowerOfTwo(lz, 0, stride, wMask, hMask,
                            (long) Math.floor(s * Sampler.ONE) - Sampler.ONE / 2,
                            (long) Math.floor(t * Sampler.ONE) - Sampler.ONE / 2));
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

    /** The bilinear sample of level {@code d} of any chain at level-0 texel coordinates (s, t). */
    static long sample(long[] lanes, int[] levels, MipChain mips, int d, double s, double t) {
        int o = d * TexelLanes.LEVEL_INTS;
        return LaneSampler.bilinear(lanes, levels[o + TexelLanes.OFFSET], levels[o + TexelLanes.STRIDE],
                levels[o + TexelLanes.WIDTH], levels[o + TexelLanes.HEIGHT],
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
        int[] color = frame.colour();
        float[] depth = frame.depth();
        double[] uv = frame.uv();
        int level2 = weight == 0 ? level : level + 1;
        TexelLanes lanes = TexelLanes.of(mips);
        long[] lz = lanes.lanes();
        int[] lv = lanes.levels();
        int o1 = level * TexelLanes.LEVEL_INTS;
        int o2 = level2 * TexelLanes.LEVEL_INTS;
        int off = lv[o1 + TexelLanes.OFFSET];
        int stride = lv[o1 + TexelLanes.STRIDE];
        int tw = lv[o1 + TexelLanes.WIDTH];
        int th = lv[o1 + TexelLanes.HEIGHT];
        int wm = lv[o1 + TexelLanes.WIDTH_MASK];
        int hm = lv[o1 + TexelLanes.HEIGHT_MASK];
        int off2 = lv[o2 + TexelLanes.OFFSET];
        int stride2 = lv[o2 + TexelLanes.STRIDE];
        int tw2 = lv[o2 + TexelLanes.WIDTH];
        int th2 = lv[o2 + TexelLanes.HEIGHT];
        int wm2 = lv[o2 + TexelLanes.WIDTH_MASK];
        int hm2 = lv[o2 + TexelLanes.HEIGHT_MASK];
        boolean pot = (wm | hm | wm2 | hm2) >= 0;
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
            // The column as a double counter, not (double) x: see PerPixelNearest.
            double xd = spanStart;
            for (int x = spanStart; x < spanEnd; x++, xd++, s0 += ds0, t0 += dt0, s += ds, t += dt, s2 += ds2,
                    t2 += dt2) {
                float qf = (float) (qRow + qDx * xd);
                int i = rowOffset + x;
                if (qf > depth[i]) {
                    depth[i] = qf;
                    long c = pot ? LaneSampler.bilinearPowerOfTwo(lz, off, stride, wm, hm, s >> TO_SAMPLER,
                            t >> TO_SAMPLER)
                            : LaneSampler.bilinear(lz, off, stride, tw, th, s >> TO_SAMPLER, t >> TO_SAMPLER);
                    if (weight != 0) {
                        c = LaneSampler.lerp(c, pot ? LaneSampler.bilinearPowerOfTwo(lz, off2, stride2, wm2, hm2,
                                s2 >> TO_SAMPLER, t2 >> TO_SAMPLER) : LaneSampler.bilinear(lz, off2, stride2, tw2, th2,
                                s2 >> TO_SAMPLER, t2 >> TO_SAMPLER), weight);
                    }
                    color[i] = TexelLanes.argb(c);
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
