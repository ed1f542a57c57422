package dev.trisect.raster;

import dev.trisect.render.Framebuffer;
import dev.trisect.texture.Texture;

/**
 * The nearest pixel loop of the span path over a triangle set up for perspective ({@link TriangleSetup}
 * with the planes of 1/w, s/w and t/w) and its spans ({@link SpanSolver}): knots placed along each row
 * by {@link KnotSpacing}, the texel coordinates exact at every knot (divided exactly as the per-pixel
 * loop divides, {@link NearestSpans#perPixel}) and stepped affinely in 32.32 fixed point between them.
 * One loop per row: the pixel at the next knot reloads its exact coordinates and sets up the step to
 * the knot after it, as Quake's span subdivision does every 16 pixels, here at the spacing that keeps
 * the exact displacement within the maximum error. Depth (the 1/w plane at every pixel), the depth
 * test, colour rule and UV output are those of the per-pixel loop.
 *
 * <p>The knots of a row run from its first covered column within the frame to its last, so they depend
 * on the triangle, the row and the frame's width only: a rectangle narrower than the frame (a tile)
 * walks the knots before it without drawing and starts mid-segment, with the values the whole row
 * would have there.
 */
final class KnotSpans {
    /** 2^32: texel coordinates in 32.32 fixed point. */
    static final double FIXED_SCALE = 4294967296.0;

    private KnotSpans() {
    }

    /**
     * The nearest span loop. Needs {@link TriangleSetup#fixedPointSafe}.
     *
     * @param setup    set up for perspective over columns [0, frame width)
     * @param maxError the largest displacement allowed between knots, pixels, &gt; 0
     * @param x0       first column to draw
     * @param x1       one past the last column to draw
     * @return pixels written
     */
    static long nearest(TriangleSetup setup, int[] spans, Framebuffer frame, Texture texture, int uvId,
                        double maxError, int x0, int x1) {
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
            long sb = (long) Math.floor((sRow + sDx * a) * rb * FIXED_SCALE);
            long tb = (long) Math.floor((tRow + tDx * a) * rb * FIXED_SCALE);
            long s = 0;
            long t = 0;
            long ds = 0;
            long dt = 0;
            int rowOffset = y * width;
            // The column as a double counter, not (double) x: see NearestSpans.perPixel.
            double xd = from;
            for (int x = from; x < to; x++, xd++, s += ds, t += dt) {
                if (x == b) {
                    // Knot a's exact coordinates, then the step to the next knot (a is x itself, except
                    // at a tile's first pixel inside a segment).
                    s = sb;
                    t = tb;
                    if (a < last) {
                        b = KnotSpacing.next(a, qb, qRow, qDx, scale, offset, unbounded, last);
                        qb = qRow + qDx * b;
                        rb = 1.0 / qb;
                        sb = (long) Math.floor((sRow + sDx * b) * rb * FIXED_SCALE);
                        tb = (long) Math.floor((tRow + tDx * b) * rb * FIXED_SCALE);
                        int length = b - a;
                        ds = KnotSpacing.step(s, sb, length);
                        dt = KnotSpacing.step(t, tb, length);
                        s += ds * (x - a);
                        t += dt * (x - a);
                        a = b;
                    }
                }
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
