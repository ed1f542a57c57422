package dev.trisect.raster;

import dev.trisect.render.Framebuffer;
import dev.trisect.texture.Texture;

/**
 * The one-pass nearest fill of a tessellated triangle: each row of the triangle's pieces
 * ({@link PieceRows}) is filled by one pixel loop across all the pieces it crosses, which switches
 * to the next piece's affine texel plane where the row crosses into it — a countdown to the next
 * piece boundary, as Quake's span loop counts down to its next knot ({@code d_scan.c}). A fallback
 * piece (per pixel, perspective-correct) or one with coordinates too large for fixed point is filled
 * at its turn along the row by its own per-pixel loop ({@link NearestSpans#perPixelRow}).
 *
 * <p>Every value is the piece-by-piece fill's: depth from the piece's 1/w plane at the pixel, texel
 * coordinates in 32.32 fixed point anchored at the piece's own first column on the row and stepped
 * by its own step ({@link NearestSpans#affineFixed}), so the output is that fill's, bit for bit.
 * Why one loop: a row of a piece is ~8 pixels, and each entry into a counted loop pays C2's pre-,
 * main and post-loop; one loop per row of the triangle pays it once (docs/performance.md).
 */
final class OnePassSpans {
    /** 2^32: texel coordinates in 32.32 fixed point. */
    static final double FIXED_SCALE = 4294967296.0;

    private OnePassSpans() {
    }

    /**
     * Fills every row of {@code rows} (built) with nearest sampling of {@code texture}.
     *
     * @return pixels written
     */
    static long nearest(PieceRows rows, Framebuffer frame, Texture texture, int uvId) {
        long written = 0;
        int[] first = rows.rowFirst;
        for (int r = 0; r < rows.rows; r++) {
            int from = first[r];
            int to = first[r + 1];
            if (from == to) {
                continue;
            }
            int y = rows.rowBase + r;
            written += rows.overlap[r]
                    ? nearestInOrder(rows, y, from, to, frame, texture, uvId)
                    : nearestRow(rows, y, from, to, frame, texture, uvId);
        }
        return written;
    }

    /** Row y's segments [from, to), sorted and disjoint, in one loop. */
    private static long nearestRow(PieceRows rows, int y, int from, int to, Framebuffer frame, Texture texture,
                                   int uvId) {
        int[] segStart = rows.segStart;
        int[] segEnd = rows.segEnd;
        int[] segPiece = rows.segPiece;
        byte[] kind = rows.kind;
        double[] pl = rows.planes;
        long[] steps = rows.steps;
        int[] firstColumn = rows.firstColumn;
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
        int rowOffset = y * width;
        long written = 0;
        int k = from;
        int x = segStart[from];
        int next = x;
        double xd = x;
        double qRow = 0;
        double qDx = 0;
        long s = 0;
        long t = 0;
        long ds = 0;
        long dt = 0;
        for (;; x++, xd++, s += ds, t += dt) {
            while (x == next) {
                // The row crosses into the next piece: its planes, its anchor, its steps.
                if (k == to) {
                    return written;
                }
                int p = segPiece[k];
                int start = segStart[k];
                int end = segEnd[k];
                k++;
                if (kind[p] != PieceRows.FIXED) {
                    written += NearestSpans.perPixelRow(rows, p, y, start, end, frame, texture, uvId);
                    x = end;
                    next = end;
                    continue;
                }
                int o = p * PieceRows.PLANE_STRIDE;
                qRow = pl[o] + pl[o + 2] * y;
                qDx = pl[o + 1];
                ds = steps[2 * p];
                dt = steps[2 * p + 1];
                int fc = firstColumn[p];
                long skip = start - fc;
                s = (long) Math.floor((pl[o + 3] + pl[o + 5] * y + pl[o + 4] * fc) * FIXED_SCALE) + ds * skip;
                t = (long) Math.floor((pl[o + 6] + pl[o + 8] * y + pl[o + 7] * fc) * FIXED_SCALE) + dt * skip;
                x = start;
                xd = start;
                next = end;
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

    /**
     * Row y's segments [from, to) where they overlap (a T-junction a piece cap left): each piece's
     * segment on its own, in the pieces' order, as the piece-by-piece fill draws them.
     */
    private static long nearestInOrder(PieceRows rows, int y, int from, int to, Framebuffer frame, Texture texture,
                                       int uvId) {
        long written = 0;
        for (int p = 0; p < rows.count; p++) {
            for (int k = from; k < to; k++) {
                if (rows.segPiece[k] == p) {
                    written += nearestRow(rows, y, k, k + 1, frame, texture, uvId);
                }
            }
        }
        return written;
    }
}
