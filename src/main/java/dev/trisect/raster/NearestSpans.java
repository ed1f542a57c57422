package dev.trisect.raster;

import dev.trisect.render.Framebuffer;
import dev.trisect.texture.Texture;

/**
 * The pixel loops of nearest sampling over a set-up triangle's spans ({@link TriangleSetup},
 * {@link SpanSolver}): one loop per path, so each inner loop is monomorphic. Both apply the depth
 * test (a fragment passes when its {@code 1/w} as a float is larger than the stored one), write
 * colour, depth and, when the frame records it, the UV output; the bilinear and trilinear loops in
 * {@link FilteredSpans} do exactly the same but for the colour.
 *
 * <p>Textures repeat: a power-of-two side wraps with a mask (exact for negative values in two's
 * complement), any other with {@link Math#floorMod}; texel row 0 is the image's bottom row.
 */
final class NearestSpans {
    /** 2^32: texel coordinates in 32.32 fixed point. */
    private static final double FIXED_SCALE = 4294967296.0;

    private NearestSpans() {
    }

    /**
     * Texel coordinates in doubles from the planes at every pixel: the perspective path (every pixel
     * divides by {@code 1/w}), or an affine triangle whose coordinates are too large for fixed point.
     *
     * @param perspective divide by the interpolated 1/w (the planes hold s/w and t/w)
     * @return pixels written
     */
    static long perPixel(TriangleSetup setup, int[] spans, Framebuffer frame, Texture texture, int uvId,
                         boolean perspective) {
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
        int[] texels = texture.argb();
        int tw = texture.width();
        int th = texture.height();
        boolean pot = (tw & (tw - 1)) == 0 && (th & (th - 1)) == 0;
        int wMask = tw - 1;
        int hMask = th - 1;
        int topRow = th - 1;
        long written = 0;
        int[] sp = spans;
        for (int y = setup.rowStart, j = 0; y < setup.rowEnd; y++, j += 2) {
            int spanStart = sp[j];
            int spanEnd = sp[j + 1];
            if (spanStart >= spanEnd) {
                continue;
            }
            double qRow = qBase + qDy * y;
            double sRow = sBase + sDy * y;
            double tRow = tBase + tDy * y;
            int rowOffset = y * width;
            // Every value comes from the plane at this pixel, not by accumulation along the row, so
            // no rounding error builds up across a wide triangle. The column is counted as a double too
            // (exact): C2 compiles (double) x to cvtsi2sd, which merges into its register's old value;
            // where that value waits on the previous pixel's division, every pixel waits for the one
            // before, about 40 cycles a pixel instead of 14 (docs/performance.md, "The false dependency").
            double xd = spanStart;
            for (int x = spanStart; x < spanEnd; x++, xd++) {
                double q = qRow + qDx * xd;
                float qf = (float) q;
                int i = rowOffset + x;
                if (qf > depth[i]) {
                    depth[i] = qf;
                    double r = perspective ? 1.0 / q : 1.0;
                    double s = (sRow + sDx * xd) * r;
                    double t = (tRow + tDx * xd) * r;
                    int si = (int) Math.floor(s);
                    int ti = (int) Math.floor(t);
                    int column = pot ? si & wMask : Math.floorMod(si, tw);
                    int rowFromBottom = pot ? ti & hMask : Math.floorMod(ti, th);
                    color[i] = texels[(topRow - rowFromBottom) * tw + column] | 0xFF000000;
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
     * The affine fill in fixed point: texel coordinates stepped in 32.32 fixed point, per pixel an
     * integer add, a shift and a mask instead of two multiply-adds, two floors and two conversions.
     * Each row's values are anchored at the triangle's own first column and reach the span by an exact
     * integer multiply, so a pixel's value depends on the triangle, the row and the column only —
     * never on the rectangle being filled — and stepping error stays below 2^-32 texel per pixel of the
     * row. Needs {@link TriangleSetup#fixedPointSafe} (|s|, |t| &lt; 2^30 over the triangle).
     *
     * @return pixels written
     */
    static long affineFixed(TriangleSetup setup, int[] spans, Framebuffer frame, Texture texture, int uvId) {
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
        int[] texels = texture.argb();
        int tw = texture.width();
        int th = texture.height();
        boolean pot = (tw & (tw - 1)) == 0 && (th & (th - 1)) == 0;
        int wMask = tw - 1;
        int hMask = th - 1;
        int topRow = th - 1;
        long ds = (long) Math.floor(sDx * FIXED_SCALE);
        long dt = (long) Math.floor(tDx * FIXED_SCALE);
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
            long s = (long) Math.floor((sBase + sDy * y + sDx * firstColumn) * FIXED_SCALE) + ds * skip;
            long t = (long) Math.floor((tBase + tDy * y + tDx * firstColumn) * FIXED_SCALE) + dt * skip;
            int rowOffset = y * width;
            // The column as a double counter, not (double) x: see perPixel.
            double xd = spanStart;
            for (int x = spanStart; x < spanEnd; x++, xd++, s += ds, t += dt) {
                float qf = (float) (qRow + qDx * xd);
                int i = rowOffset + x;
                if (qf > depth[i]) {
                    depth[i] = qf;
                    // An arithmetic shift floors, negative coordinates included.
                    int si = (int) (s >> 32);
                    int ti = (int) (t >> 32);
                    int column = pot ? si & wMask : Math.floorMod(si, tw);
                    int rowFromBottom = pot ? ti & hMask : Math.floorMod(ti, th);
                    color[i] = texels[(topRow - rowFromBottom) * tw + column] | 0xFF000000;
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
}
