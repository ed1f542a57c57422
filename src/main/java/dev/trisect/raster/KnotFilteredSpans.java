package dev.trisect.raster;

import dev.trisect.render.Framebuffer;
import dev.trisect.texture.internal.LaneSampler;
import dev.trisect.texture.internal.Lod;
import dev.trisect.texture.MipChain;
import dev.trisect.texture.internal.Sampler;
import dev.trisect.texture.internal.TexelLanes;

/**
 * The bilinear and trilinear pixel loop of the span path: the knots, the exact coordinates at them and
 * the 32.32 fixed-point steps between them of {@link KnotNearest}, sampled as {@link FilteredSpans}
 * samples ({@link LaneSampler}, the packed blend with 8-bit weights).
 *
 * <p>Trilinear takes one level of detail per segment: at each knot, OpenGL's lambda from the exact
 * derivatives of the perspective map there ({@link Lod#rhoSquared} along x and along y, each
 * {@link Lod#fixedOfSquared}, the larger), and for the segment between two knots the mean of theirs
 * (floored to 1/256), selected by {@link Lod#select(int, int)}. The two levels' descriptors are
 * reloaded only when the segment's level changes.
 *
 * <p>On a {@link MipChain#powerOfTwo} chain the bilinear position of level d is the 32.32 coordinate
 * shifted right by {@code 24 + k} ({@code k = log2} of level 0's side over level d's) less half a
 * texel: {@code floor(256 s 2^-k) - 128}, exactly as the per-pixel loop has it, since
 * {@code floor(floor(x) / 2^m) = floor(x / 2^m)}. Other chains take the coordinate as a double and
 * {@link Sampler#position} per level, as the per-pixel loop does for them.
 */
final class KnotFilteredSpans {
    private static final double FIXED_SCALE = KnotNearest.FIXED_SCALE;
    /** From 32.32 to the sampler's 24.8. */
    private static final int TO_SAMPLER = 32 - Sampler.FRACTION_BITS;

    private KnotFilteredSpans() {
    }

    /**
     * The filtered span loop. Needs {@link TriangleSetup#fixedPointSafe}.
     *
     * @param setup     set up for perspective over columns [0, frame width)
     * @param maxError  the largest displacement allowed between knots, pixels, &gt; 0
     * @param trilinear trilinear with a level of detail per segment; else bilinear on level 0
     * @param x0        first column to draw
     * @param x1        one past the last column to draw
     * @return pixels written
     */
    static long fill(TriangleSetup setup, int[] spans, Framebuffer frame, MipChain mips, int uvId, double maxError,
                     boolean trilinear, int x0, int x1) {
        double qBase = setup.qPlane.base;
        double qDx = setup.qPlane.dx;
        double qDy = setup.qPlane.dy;
        double sBase = setup.sPlane.base;
        double sDx = setup.sPlane.dx;
        double sDy = setup.sPlane.dy;
        double tBase = setup.tPlane.base;
        double tDx = setup.tPlane.dx;
        double tDy = setup.tPlane.dy;
        double scale = KnotSpacing.scale(qDx, maxError);
        double offset = KnotSpacing.offset(qDx, maxError);
        double unbounded = KnotSpacing.unbounded(qDx, maxError);
        int maxLevel = mips.maxLevel();
        boolean pot = mips.powerOfTwo();
        TexelLanes lanes = TexelLanes.of(mips);
        long[] lz = lanes.lanes();
        int[] lv = lanes.levels();
        // The levels of the current segment: its selection, and (power-of-two chains) both levels'
        // descriptors, with the shifts from 32.32 level-0 coordinates to each level's 24.8 position.
        int selection = 0;
        int level = -1;
        int weight = 0;
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
            int from = Math.max(spanStart, x0);
            int to = Math.min(spanEnd, x1);
            if (from >= to) {
                continue;
            }
            double qRow = qBase + qDy * y;
            double sRow = sBase + sDy * y;
            double tRow = tBase + tDy * y;
            int last = spanEnd - 1;
            int a = KnotSpacing.knotAtOrBefore(from, spanStart, qRow, qDx, scale, offset, unbounded, last);
            int b = from;
            double qb = qRow + qDx * a;
            double rb = 1.0 / qb;
            double sExact = (sRow + sDx * a) * rb;
            double tExact = (tRow + tDx * a) * rb;
            long sb = (long) Math.floor(sExact * FIXED_SCALE);
            long tb = (long) Math.floor(tExact * FIXED_SCALE);
            int lambdaB = trilinear ? lambdaAt(sExact, tExact, rb, sDx, sDy, tDx, tDy, qDx, qDy, maxLevel) : 0;
            long s = 0;
            long t = 0;
            long ds = 0;
            long dt = 0;
            int rowOffset = y * width;
            // The column as a double counter, not (double) x: see PerPixelNearest.
            double xd = from;
            for (int x = from; x < to; x++, xd++, s += ds, t += dt) {
                if (x == b) {
                    s = sb;
                    t = tb;
                    int lambdaA = lambdaB;
                    if (a < last) {
                        b = KnotSpacing.next(a, qb, qRow, qDx, scale, offset, unbounded, last);
                        qb = qRow + qDx * b;
                        rb = 1.0 / qb;
                        sExact = (sRow + sDx * b) * rb;
                        tExact = (tRow + tDx * b) * rb;
                        sb = (long) Math.floor(sExact * FIXED_SCALE);
                        tb = (long) Math.floor(tExact * FIXED_SCALE);
                        int length = b - a;
                        ds = KnotSpacing.step(s, sb, length);
                        dt = KnotSpacing.step(t, tb, length);
                        s += ds * (x - a);
                        t += dt * (x - a);
                        a = b;
                        if (trilinear) {
                            lambdaB = lambdaAt(sExact, tExact, rb, sDx, sDy, tDx, tDy, qDx, qDy, maxLevel);
                        }
                    }
                    if (trilinear) {
                        selection = lambdaA == Lod.NO_LAMBDA || lambdaB == Lod.NO_LAMBDA ? 0
                                : Lod.select(lambdaA + lambdaB >> 1, maxLevel);
                        weight = Lod.weight(selection);
                    }
                    int d = Lod.level(selection);
                    if (d != level && pot) {
                        level = d;
                        int o = d * TexelLanes.LEVEL_INTS;
                        int o2 = Math.min(d + 1, maxLevel) * TexelLanes.LEVEL_INTS;
                        off1 = lv[o + TexelLanes.OFFSET];
                        stride1 = lv[o + TexelLanes.STRIDE];
                        wm1 = lv[o + TexelLanes.WIDTH_MASK];
                        hm1 = lv[o + TexelLanes.HEIGHT_MASK];
                        ss1 = lv[o + TexelLanes.SHIFT_S] + TO_SAMPLER;
                        ts1 = lv[o + TexelLanes.SHIFT_T] + TO_SAMPLER;
                        off2 = lv[o2 + TexelLanes.OFFSET];
                        stride2 = lv[o2 + TexelLanes.STRIDE];
                        wm2 = lv[o2 + TexelLanes.WIDTH_MASK];
                        hm2 = lv[o2 + TexelLanes.HEIGHT_MASK];
                        ss2 = lv[o2 + TexelLanes.SHIFT_S] + TO_SAMPLER;
                        ts2 = lv[o2 + TexelLanes.SHIFT_T] + TO_SAMPLER;
                    }
                }
                float qf = (float) (qRow + qDx * xd);
                int i = rowOffset + x;
                if (qf > depth[i]) {
                    depth[i] = qf;
                    long l;
                    if (pot) {
                        l = LaneSampler.bilinearPowerOfTwo(lz, off1, stride1, wm1, hm1,
                                (s >> ss1) - Sampler.ONE / 2, (t >> ts1) - Sampler.ONE / 2);
                        if (weight != 0) {
                            l = LaneSampler.lerp(l, LaneSampler.bilinearPowerOfTwo(lz, off2, stride2, wm2, hm2,
                                    (s >> ss2) - Sampler.ONE / 2, (t >> ts2) - Sampler.ONE / 2), weight);
                        }
                    } else {
                        int d = Lod.level(selection);
                        double sd = s / FIXED_SCALE;
                        double td = t / FIXED_SCALE;
                        l = FilteredSpans.sample(lz, lv, mips, d, sd, td);
                        if (weight != 0) {
                            l = LaneSampler.lerp(l, FilteredSpans.sample(lz, lv, mips, d + 1, sd, td), weight);
                        }
                    }
                    color[i] = TexelLanes.argb(l);
                    if (uv != null) {
                        uv[3 * i] = s / FIXED_SCALE;
                        uv[3 * i + 1] = t / FIXED_SCALE;
                        uv[3 * i + 2] = uvId;
                    }
                    written++;
                }
            }
        }
        return written;
    }

    /**
     * OpenGL's lambda at a pixel of a perspective map, in 1/256 level ({@link Lod#fixedOfSquared} of
     * each axis, the larger), or {@link Lod#NO_LAMBDA}.
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
}
