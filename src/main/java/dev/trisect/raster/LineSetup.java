package dev.trisect.raster;

/**
 * The setup of a {@link Commands#LINE LINE} command: a segment between two screen points made into
 * what {@link LineRaster} draws, as OpenGL rasterizes aliased lines and as Mesa's llvmpipe sets them up
 * (its {@code lp_setup_line.c}), into a frame's {@link Segments}.
 *
 * <p>Which pixels (OpenGL 1.x specification, section 3.4.1, "Basic Line Segment Rasterization"): a
 * segment is x-major when it spans at least as many columns as rows, else y-major. It lights the
 * pixels whose diamond ({@code |x - xc| + |y - yc| < 1/2} around the pixel centre) it leaves — the
 * diamond-exit rule — so that segments joined end to end light their shared point once and a
 * segment's last pixel is left to the next. Here, as in llvmpipe, the segment becomes a
 * parallelogram: its ends are moved along the segment to the nearest position that lights exactly
 * the pixels the diamond rule gives at each end, and it is widened by {@code width / 2} on both sides
 * along the minor axis (the specification's section 3.4.2 for wide aliased lines: a column of
 * {@code width} pixels per column of an x-major line). The parallelogram's four edges become edge
 * functions in 1/256-pixel fixed point; an edge along a column or a row is folded into the segment's
 * columns or rows, leaving at most two for the row loop. Coordinates are taken in OpenGL's window
 * space (y up, {@code yGl = height - y}) so that every decision at a tie is llvmpipe's; rows are then
 * the frame's (row 0 at the top).
 *
 * <p>Depth: 1/w along the segment's major axis, from its own ends, in doubles (see {@link LineRaster}).
 *
 * <p>Not thread-safe: it holds the corners being set up.
 */
public final class LineSetup {
    /** Sub-pixel steps per pixel (llvmpipe's FIXED_ONE): positions snap to 1/256 pixel. */
    static final int FIXED_ONE = 256;
    private static final int LSTRIDE = Segments.LSTRIDE;
    private static final int ISTRIDE = Segments.ISTRIDE;
    private static final int DSTRIDE = Segments.DSTRIDE;

    /** The parallelogram's corners being set up, 1/256 pixel, window space. */
    private final long[] cx = new long[4];
    private final long[] cy = new long[4];
    /** The store being written and its frame's size. */
    private long[] planes;
    private int width;
    private int height;

    /**
     * Sets up a segment between two points in screen space (pixels, y down, pixel centres at .5),
     * each with its 1/w, as the next segment of {@code into} (in the frame {@link Segments#begin} gave).
     *
     * @param into      the store: the segment is its {@link Segments#count()} before the call
     * @param x1        one end, pixels from the left
     * @param y1        one end, pixels from the top
     * @param q1        1/w at that end
     * @param x2        the other end
     * @param y2        the other end
     * @param q2        1/w there
     * @param lineWidth width in whole pixels, at least 1
     * @param rgb       colour, 0xRRGGBB
     * @return whether the segment may light a pixel of the frame (false for a zero-length segment, as
     *         OpenGL draws none); only then is it stored
     */
    public boolean add(Segments into, double x1, double y1, double q1, double x2, double y2, double q2, int lineWidth, int rgb) {
        width = into.width();
        height = into.height();
        // OpenGL's window space, in floats as the rasterizer receives it.
        float ax = (float) x1;
        float ay = (float) (height - y1);
        float bx = (float) x2;
        float by = (float) (height - y2);
        float dx = ax - bx;
        float dy = ay - by;
        if (dx == 0 && dy == 0) {
            return false;
        }
        float adx = ax - (float) Math.floor(ax) - 0.5f;
        float ady = ay - (float) Math.floor(ay) - 0.5f;
        float bdx = bx - (float) Math.floor(bx) - 0.5f;
        float bdy = by - (float) Math.floor(by) - 0.5f;
        int half = Math.max(1, lineWidth) * FIXED_ONE / 2;
        boolean xMajor = Math.abs(dx) >= Math.abs(dy);
        // Offsets moving each end along the segment so the parallelogram's end edge lights the pixels
        // the diamond-exit rule gives at that end.
        float aox = 0;
        float aoy = 0;
        float box = 0;
        float boy = 0;
        if (xMajor) {
            float slope = dy / dx;
            if (bdy == -0.5f && dy < 0) {
                bdy = 0.5f;
            }
            boolean drawStart = startExits(adx, ady, dx, dy, frac(ay) + adx * slope);
            boolean drawEnd = endExits(bdx, bdy, dx, dy, frac(by) + bdx * slope, false);
            // The end edge at a vertex lights that vertex's column when its centre lies on the edge's
            // inner side; move the edge half a pixel past the centre where the rule says otherwise.
            if (dx < 0) {
                if ((adx <= 0) != drawStart) {
                    aox = -adx - 0.5f;
                    aoy = aox * slope;
                }
                if ((bdx > 0) != drawEnd) {
                    box = -bdx - 0.5f;
                    boy = box * slope;
                }
            } else {
                if ((adx > 0) != drawStart) {
                    aox = -adx + 0.5f;
                    aoy = aox * slope;
                }
                if ((bdx <= 0) != drawEnd) {
                    box = -bdx + 0.5f;
                    boy = box * slope;
                }
            }
        } else {
            float slope = dx / dy;
            if (bdx == -0.5f && dx < 0) {
                bdx = 0.5f;
            }
            // The same tests with the axes' roles exchanged.
            boolean drawStart = startExits(-ady, -adx, -dy, -dx, frac(ax) + ady * slope);
            boolean drawEnd = endExits(-bdy, -bdx, -dy, -dx, frac(bx) + bdy * slope, true);
            if (dy > 0) {
                if ((ady > 0) != drawStart) {
                    aoy = -ady + 0.5f;
                    aox = aoy * slope;
                }
                if ((bdy <= 0) != drawEnd) {
                    boy = -bdy + 0.5f;
                    box = boy * slope;
                }
            } else {
                if ((ady <= 0) != drawStart) {
                    aoy = -ady - 0.5f;
                    aox = aoy * slope;
                }
                if ((bdy > 0) != drawEnd) {
                    boy = -bdy - 0.5f;
                    box = boy * slope;
                }
            }
        }
        // Ends snapped to 1/256 pixel, with the sample points at whole coordinates (centres - 1/2).
        long sax = snap(ax + aox - 0.5f);
        long say = snap(ay + aoy - 0.5f);
        long sbx = snap(bx + box - 0.5f);
        long sby = snap(by + boy - 0.5f);
        // Corners in an order that makes the inside positive (see plane()): the rightmost end first
        // for an x-major segment, the lowest (in window y) first for a y-major one.
        boolean aFirst = xMajor ? dx >= 0 : dy <= 0;
        long px = aFirst ? sax : sbx;
        long py = aFirst ? say : sby;
        long qx = aFirst ? sbx : sax;
        long qy = aFirst ? sby : say;
        if (xMajor) {
            cx[0] = px; cy[0] = py - half;
            cx[1] = qx; cy[1] = qy - half;
            cx[2] = qx; cy[2] = qy + half;
            cx[3] = px; cy[3] = py + half;
        } else {
            cx[0] = px - half; cy[0] = py;
            cx[1] = qx - half; cy[1] = qy;
            cx[2] = qx + half; cy[2] = qy;
            cx[3] = px + half; cy[3] = py;
        }
        long minX = Math.min(Math.min(cx[0], cx[1]), Math.min(cx[2], cx[3]));
        long maxX = Math.max(Math.max(cx[0], cx[1]), Math.max(cx[2], cx[3]));
        long minY = Math.min(Math.min(cy[0], cy[1]), Math.min(cy[2], cy[3]));
        long maxY = Math.max(Math.max(cy[0], cy[1]), Math.max(cy[2], cy[3]));
        int col0 = (int) Math.max(0, Math.floorDiv(minX, FIXED_ONE));
        int col1 = (int) Math.min(width - 1L, Math.floorDiv(maxX, FIXED_ONE) + 1);
        // Window rows glY in [minY, maxY] / 256 are frame rows height - 1 - glY.
        int row0 = (int) Math.max(0, height - 1 - (Math.floorDiv(maxY, FIXED_ONE) + 1));
        int row1 = (int) Math.min(height - 1L, height - 1 - Math.floorDiv(minY, FIXED_ONE));
        if (col0 > col1 || row0 > row1) {
            return false;
        }
        int count = into.next();
        planes = into.planes;
        int l = LSTRIDE * count;
        // Window rows py hold the sample gy = 256 py; frame row = height - 1 - py.
        long pyLo = height - 1 - row1;
        long pyHi = height - 1 - row0;
        long colLo = col0;
        long colHi = col1;
        int varying = 0;
        for (int e = 0; e < 4; e++) {
            plane(cx[e], cy[e], cx[(e + 1) & 3], cy[(e + 1) & 3], l + 3 * varying);
            long c = planes[l + 3 * varying];
            long a = planes[l + 3 * varying + 1] * FIXED_ONE;
            long b = planes[l + 3 * varying + 2] * FIXED_ONE;
            // Inside: c - a * col + b * py >= 1. An edge along a column or a row bounds the columns or
            // the rows of every pixel alike: folded in here, leaving the (at most two) slanted edges.
            if (b == 0) {
                if (a > 0) {
                    colHi = Math.min(colHi, Math.floorDiv(c - 1, a));
                } else if (a < 0) {
                    colLo = Math.max(colLo, -Math.floorDiv(1 - c, a));
                } else if (c < 1) {
                    return false;
                }
            } else if (a == 0) {
                if (b > 0) {
                    pyLo = Math.max(pyLo, -Math.floorDiv(c - 1, b));
                } else {
                    pyHi = Math.min(pyHi, Math.floorDiv(c - 1, -b));
                }
            } else {
                varying++;
            }
        }
        if (colLo > colHi || pyLo > pyHi) {
            return false;
        }
        int[] ints = into.ints;
        int i = ISTRIDE * count;
        row0 = (int) (height - 1 - pyHi);
        row1 = (int) (height - 1 - pyLo);
        col0 = (int) colLo;
        col1 = (int) colHi;
        ints[i] = col0;
        ints[i + 1] = col1;
        ints[i + 2] = row0;
        ints[i + 3] = row1;
        ints[i + 4] = rgb | 0xFF000000;
        ints[i + 5] = (xMajor ? 1 : 0) | varying << 1;
        // 1/w along the major axis, from the segment's own ends (not the moved ones), in window space.
        // In doubles: the frame's triangles' 1/w planes are, and a line on a face must meet the face's
        // depth there to the last bits (its 1/w is the face's at every point of it).
        double[] depth = into.depth;
        int d = DSTRIDE * count;
        if (xMajor) {
            depth[d] = x1;
            depth[d + 2] = (q1 - q2) / (x1 - x2);
        } else {
            depth[d] = height - y1;
            depth[d + 2] = (q1 - q2) / (y2 - y1);
        }
        depth[d + 1] = q1;
        into.commit();
        return true;
    }

    /**
     * Whether the segment leaves the diamond of the pixel holding its start, for an x-major segment
     * (a y-major one passes its coordinates with the axes exchanged and negated). {@code fx}, {@code fy}
     * are the start's offsets from that pixel's centre, {@code dx}, {@code dy} start minus end, and
     * {@code cross} where the segment crosses the pixel's side (in the pixel, 0 to 1) when the other
     * tests leave it open.
     */
    private static boolean startExits(float fx, float fy, float dx, float dy, float cross) {
        if (Math.abs(fx) + Math.abs(fy) < 0.5f) {
            return true;
        }
        if ((fx >= 0) == (-dx >= 0)) {
            return false;
        }
        if ((-fy >= 0) != (dy >= 0)) {
            return true;
        }
        return cross < 1 && cross > 0;
    }

    /** As {@link #startExits}, for the end: whether the segment leaves the diamond of its last pixel. */
    private static boolean endExits(float fx, float fy, float dx, float dy, float cross, boolean closedAtZero) {
        if (Math.abs(fx) + Math.abs(fy) < 0.5f) {
            return false;
        }
        if ((fx >= 0) != (-dx >= 0)) {
            return false;
        }
        if ((-fy >= 0) == (dy >= 0)) {
            return true;
        }
        return cross < 1 && (closedAtZero ? cross >= 0 : cross > 0);
    }

    private static float frac(float f) {
        return f - (float) Math.floor(f);
    }

    /** llvmpipe's {@code subpixel_snap}: round half away from zero to 1/256 pixel. */
    private static long snap(float v) {
        float s = v * FIXED_ONE;
        return (long) (s >= 0 ? s + 0.5f : s - 0.5f);
    }

    /**
     * The edge from (x0, y0) to (x1, y1) as an edge function {@code c + dcdy * Y - dcdx * X}, positive
     * inside, with the fill rule's ties folded into c: a centre exactly on a left edge, or on a
     * horizontal edge the shape lies above (in window space), is inside.
     */
    private void plane(long x0, long y0, long x1, long y1, int at) {
        long dcdx = y0 - y1;
        long dcdy = x0 - x1;
        long c = dcdx * x0 - dcdy * y0;
        if (dcdx < 0 || (dcdx == 0 && dcdy > 0)) {
            c++;
        }
        planes[at] = c;
        planes[at + 1] = dcdx;
        planes[at + 2] = dcdy;
    }
}
