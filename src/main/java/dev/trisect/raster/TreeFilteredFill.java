package dev.trisect.raster;

import dev.trisect.render.Framebuffer;
import dev.trisect.texture.MipChain;
import dev.trisect.texture.TextureFilter;
import dev.trisect.texture.internal.LaneSampler;
import dev.trisect.texture.internal.Lod;
import dev.trisect.texture.internal.Sampler;
import dev.trisect.texture.internal.TexelLanes;

/**
 * The tessellated path's bilinear and trilinear fill, one pass per input triangle: each row of the
 * input triangle is cut into its pieces' segments by {@link TreeFill#descend}, and each run of affine
 * pieces along the row is filled by one loop that loads the next piece's planes and levels where the
 * row crosses into it. Each segment is filled as a row of its piece, so that its pixels take exactly
 * the colour and texel coordinates the piece-by-piece fill ({@link FilteredSpans}) gave them: an affine piece's row anchored in 32.32
 * fixed point at the piece's own first column, trilinear with the piece's one level of detail, set
 * up once per piece in the geometry pass ({@link SplitTrees#selections()}). Depth is the input
 * triangle's, as in the per-pixel path. Per-pixel fallback pieces and pieces too large for fixed
 * point are filled by {@link FilteredSpans#fill} as a triangle of one row ({@link TreeFill#oneRow}).
 *
 * <p>One per thread, beside the thread's {@link TreeFill}, whose scratch it uses.
 */
final class TreeFilteredFill {
    /** 2^32: texel coordinates in 32.32 fixed point. */
    private static final double FIXED_SCALE = 4294967296.0;
    /** Right shift from 32.32 fixed point to the sampler's 8 fraction bits. */
    private static final int TO_SAMPLER = 32 - Sampler.FRACTION_BITS;

    /**
     * Fills group {@code root}'s input triangle, set up as {@code setup} for a perspective fill (its
     * planes hold 1/w, s/w, t/w), with spans {@code spans}; {@code trilinear} false: bilinear on level 0.
     *
     * @param descent the thread's descent scratch
     * @return pixels written
     */
    long fill(TreeFill descent, TriangleSetup setup, int[] spans, SplitTrees trees, int root, int nodes,
              Framebuffer frame, MipChain mips, int uvId, boolean trilinear) {
        int[] st = descent.stackFor(nodes);
        int[] segs = descent.segments();
        double[] planes = trees.planes();
        int ps = trees.planeStride();
        int[] firstColumns = trees.firstColumns();
        long[] steps = trees.fixedSteps();
        int[] selections = trees.selections();
        byte[] kinds = trees.kinds();
        double qBase = setup.qPlane.base;
        double qDx = setup.qPlane.dx;
        double qDy = setup.qPlane.dy;
        int width = frame.width();
        int[] color = frame.colour();
        float[] depth = frame.depth();
        double[] uv = frame.uv();
        TexelLanes lanes = TexelLanes.of(mips);
        long[] lz = lanes.lanes();
        int[] lv = lanes.levels();
        // The levels of the last segment, reloaded only when a segment's levels differ.
        int level = -1;
        int level2 = -1;
        int off = 0, stride = 0, tw = 0, th = 0, wm = 0, hm = 0;
        int off2 = 0, stride2 = 0, tw2 = 0, th2 = 0, wm2 = 0, hm2 = 0;
        boolean pot = false;
        double ks = 0, kt = 0, ks2 = 0, kt2 = 0;
        long half = 1L << 31;
        long written = 0;
        for (int y = setup.rowStart, j = 0; y < setup.rowEnd; y++, j += 2) {
            int rowA = spans[j];
            int rowB = spans[j + 1];
            if (rowA >= rowB) {
                continue;
            }
            int n = TreeFill.descend(root, rowA, rowB, y, trees, st, segs);
            double qRow = qBase + qDy * y;
            int rowOffset = y * width;
            for (int g = 0; g < n; g += 3) {
                int piece = segs[g + 2];
                if (kinds[piece] != SplitTrees.AFFINE) {
                    written += FilteredSpans.fill(descent.oneRow(setup, trees, piece, y, segs[g], segs[g + 1]),
                            descent.segmentSpan, frame, mips, uvId, kinds[piece] == SplitTrees.PER_PIXEL,
                            trilinear ? TextureFilter.TRILINEAR : TextureFilter.BILINEAR);
                    continue;
                }
                // One loop across the run of affine pieces that starts here; where the row crosses into
                // the next piece (first at the run's start), its levels and planes are loaded.
                int runStart = segs[g];
                int runEnd = segs[TreeFill.affineRun(segs, g, n, kinds) - 2];
                int end = runStart;
                g -= 3;
                int weight = 0;
                long ds0 = 0, dt0 = 0, ds = 0, dt = 0, ds2 = 0, dt2 = 0;
                long s0 = 0, t0 = 0, s = 0, t = 0, s2 = 0, t2 = 0;
                // The column as a double counter, not (double) x: see PerPixelNearest.
                double xd = runStart;
                for (int x = runStart; x < runEnd; x++, xd++, s0 += ds0, t0 += dt0, s += ds, t += dt, s2 += ds2,
                        t2 += dt2) {
                    if (x == end) {
                        g += 3;
                        end = segs[g + 1];
                        piece = segs[g + 2];
                        int selection = trilinear ? selections[piece] : 0;
                        int l1 = Lod.level(selection);
                        weight = Lod.weight(selection);
                        int l2 = weight == 0 ? l1 : l1 + 1;
                        if (l1 != level || l2 != level2) {
                            level = l1;
                            level2 = l2;
                            int o1 = level * TexelLanes.LEVEL_INTS;
                            int o2 = level2 * TexelLanes.LEVEL_INTS;
                            off = lv[o1 + TexelLanes.OFFSET];
                            stride = lv[o1 + TexelLanes.STRIDE];
                            tw = lv[o1 + TexelLanes.WIDTH];
                            th = lv[o1 + TexelLanes.HEIGHT];
                            wm = lv[o1 + TexelLanes.WIDTH_MASK];
                            hm = lv[o1 + TexelLanes.HEIGHT_MASK];
                            off2 = lv[o2 + TexelLanes.OFFSET];
                            stride2 = lv[o2 + TexelLanes.STRIDE];
                            tw2 = lv[o2 + TexelLanes.WIDTH];
                            th2 = lv[o2 + TexelLanes.HEIGHT];
                            wm2 = lv[o2 + TexelLanes.WIDTH_MASK];
                            hm2 = lv[o2 + TexelLanes.HEIGHT_MASK];
                            pot = (wm | hm | wm2 | hm2) >= 0;
                            ks = mips.scaleS(level) * FIXED_SCALE;
                            kt = mips.scaleT(level) * FIXED_SCALE;
                            ks2 = mips.scaleS(level2) * FIXED_SCALE;
                            kt2 = mips.scaleT(level2) * FIXED_SCALE;
                        }
                        // As FilteredSpans.levelFixed fills this row of the piece: anchored at its first column.
                        int po = ps * piece;
                        double sDx = planes[po + 1];
                        double tDx = planes[po + 4];
                        int fc = firstColumns[piece];
                        long skip = x - fc;
                        double sAnchor = planes[po] + planes[po + 2] * y + sDx * fc;
                        double tAnchor = planes[po + 3] + planes[po + 5] * y + tDx * fc;
                        ds0 = steps[SplitTrees.FIXED_STEP * piece];
                        dt0 = steps[SplitTrees.FIXED_STEP * piece + 1];
                        ds = (long) Math.floor(sDx * ks);
                        dt = (long) Math.floor(tDx * kt);
                        ds2 = (long) Math.floor(sDx * ks2);
                        dt2 = (long) Math.floor(tDx * kt2);
                        s0 = (long) Math.floor(sAnchor * FIXED_SCALE) + ds0 * skip;
                        t0 = (long) Math.floor(tAnchor * FIXED_SCALE) + dt0 * skip;
                        s = (long) Math.floor(sAnchor * ks) - half + ds * skip;
                        t = (long) Math.floor(tAnchor * kt) - half + dt * skip;
                        s2 = (long) Math.floor(sAnchor * ks2) - half + ds2 * skip;
                        t2 = (long) Math.floor(tAnchor * kt2) - half + dt2 * skip;
                    }
                    float qf = (float) (qRow + qDx * xd);
                    int i = rowOffset + x;
                    if (qf > depth[i]) {
                        depth[i] = qf;
                        long c = pot ? LaneSampler.bilinearPowerOfTwo(lz, off, stride, wm, hm, s >> TO_SAMPLER,
                                t >> TO_SAMPLER)
                                : LaneSampler.bilinear(lz, off, stride, tw, th, s >> TO_SAMPLER, t >> TO_SAMPLER);
                        if (weight != 0) {
                            c = LaneSampler.lerp(c, pot ? LaneSampler.bilinearPowerOfTwo(lz, off2, stride2, wm2, hm2,
                                    s2 >> TO_SAMPLER, t2 >> TO_SAMPLER) : LaneSampler.bilinear(lz, off2, stride2, tw2,
                                    th2, s2 >> TO_SAMPLER, t2 >> TO_SAMPLER), weight);
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
        }
        return written;
    }
}
