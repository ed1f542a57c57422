package dev.trisect.raster;

/**
 * The {@link Segments#CROSSING CROSSING} rule of {@link Commands#LINE LINE} commands, the border
 * overlay's: its setup ({@link #add}), its row loop ({@link #band}) and the same rule for one pixel
 * ({@link #lights}).
 *
 * <p>Which pixels: a mostly horizontal edge (at least as many columns as rows) lights, in every column
 * whose centre lies within the edge's extent, the pixel holding the point where the edge crosses that
 * centre's vertical, {@code floor(ya + (c + 0.5 - xa) * dy/dx)}; a mostly vertical one likewise per
 * row. The pixel is a function of the edge and that column alone, and an edge is walked from its
 * canonical end (the smaller x, then y), so a shared edge drawn from either triangle and in any band
 * lights the same pixels. Unlike OpenGL's diamond exit ({@link Segments#DIAMOND}) both ends' pixels are
 * lit, which closes an outline's corners.
 *
 * <p>What a pixel gets is the {@link BorderOverlay}'s write: its depth test against the outlined
 * triangles' own depth planes, colour and opacity, per edge the one or two triangles that share it.
 *
 * <p>{@link #band} may run on many threads at once over distinct rows.
 */
public final class LineCrossing {
    /**
     * Ints per segment: the triangle whose turn it is, the earlier triangle sharing the edge (or
     * {@link OutlinePlan#ALONE}); the first and last column (mostly horizontal) or row (mostly
     * vertical) it lights; the first and last row (mostly horizontal) or column (mostly vertical) its
     * pixels can fall on, unclipped, so that an edge within the band and the frame is walked without
     * per-pixel tests; 1 when it is mostly horizontal (walked by column), else 0; and a pad to 32
     * bytes. One record, so that a band's walk reads one cache line per edge for them.
     */
    static final int ISTRIDE = 8;
    /**
     * Doubles per segment, pixels: the canonical end's x and y, the slope (dy/dx for a mostly
     * horizontal edge, dx/dy for a mostly vertical one), and its reciprocal, with which a band finds
     * the columns of an edge that crosses it without dividing.
     */
    static final int DSTRIDE = 4;

    private LineCrossing() {
    }

    /**
     * Sets up the edge between two corners in {@link FixedPoint} sub-pixel units, screen space, as
     * segment {@code s} of {@code into} (which has room for it: {@link Segments#reserve}), walked in
     * triangle {@code owner}'s turn with triangle {@code earlier} (or {@link OutlinePlan#ALONE})
     * sharing it, in a frame {@code height} rows high. The caller counts the segments it stored
     * ({@link Segments#count(int)}): per edge, this writes the record and nothing else.
     *
     * @return -1 when the edge lights no pixel of the frame's rows (then nothing is stored), else the
     *         first and last frame row it can light, {@code first << 32 | last}
     */
    static long add(Segments into, int s, int ax, int ay, int bx, int by, int owner, int earlier, int height) {
        // Canonical direction: from the smaller (x, y) end, so both sharers would light the same pixels.
        if (ax > bx || ax == bx && ay > by) {
            int t = ax;
            ax = bx;
            bx = t;
            t = ay;
            ay = by;
            by = t;
        }
        // In sub-pixel units, exactly: a pixel centre's column c lies within [xa, xb] when
        // ceil(xa - 0.5) <= c <= floor(xb - 0.5), that is (ax + HALF - 1) >> BITS <= c <= (bx - HALF) >> BITS.
        int dx = bx - ax;
        int dy = by - ay;
        boolean byColumn = Math.abs(dx) >= Math.abs(dy);
        int first;
        int firstRow;
        int lastRow;
        int last;
        int crossFirst;
        int crossLast;
        double slope;
        double inverse = 0;
        if (byColumn) {
            if (dx == 0) {
                return -1;
            }
            // The quotient of the two differences in pixels: both are exact, and scaling both by 2^-BITS keeps it.
            slope = dy / (double) dx;
            // Only to find the columns that may fall in a band, with a column of margin: no pixel
            // depends on its rounding.
            inverse = dy == 0 ? 0 : dx / (double) dy;
            first = (ax + FixedPoint.HALF - 1) >> FixedPoint.BITS;
            last = (bx - FixedPoint.HALF) >> FixedPoint.BITS;
            crossFirst = cellBelow(Math.min(ay, by));
            crossLast = Math.max(ay, by) >> FixedPoint.BITS;
            firstRow = crossFirst;
            lastRow = crossLast;
        } else {
            slope = dx / (double) dy;
            first = (Math.min(ay, by) + FixedPoint.HALF - 1) >> FixedPoint.BITS;
            last = (Math.max(ay, by) - FixedPoint.HALF) >> FixedPoint.BITS;
            crossFirst = cellBelow(ax);
            crossLast = bx >> FixedPoint.BITS;
            firstRow = first;
            lastRow = last;
        }
        firstRow = Math.max(0, firstRow);
        lastRow = Math.min(height - 1, lastRow);
        if (first > last || firstRow > lastRow) {
            return -1;
        }
        store(into, s, owner, earlier, first, last, crossFirst, crossLast, byColumn, ax, ay, slope, inverse);
        return (long) firstRow << 32 | lastRow;
    }

    /**
     * Writes the segment {@link #add} set up into {@code into}. Apart from {@code add}, so that
     * {@code add} stays small enough for the compiler to inline into the overlay's per-edge loop.
     */
    private static void store(Segments into, int s, int owner, int earlier, int first, int last, int crossFirst,
                              int crossLast, boolean byColumn, int ax, int ay, double slope, double inverse) {
        int[] ints = into.ints;
        int w = ISTRIDE * s;
        ints[w] = owner;
        ints[w + 1] = earlier;
        ints[w + 2] = first;
        ints[w + 3] = last;
        ints[w + 4] = crossFirst;
        ints[w + 5] = crossLast;
        ints[w + 6] = byColumn ? 1 : 0;
        double[] lines = into.depth;
        int k = DSTRIDE * s;
        lines[k] = ax / (double) FixedPoint.ONE;
        lines[k + 1] = ay / (double) FixedPoint.ONE;
        lines[k + 2] = slope;
        lines[k + 3] = inverse;
    }

    /**
     * The lowest pixel row (or column) a line pixel can fall on for an edge whose lower end lies at
     * {@code low} sub-pixel units: that end's, or the one before when the end lies on a pixel
     * boundary, where rounding of the line's height can reach just below it.
     */
    private static int cellBelow(int low) {
        // floor(low / ONE), less one when low is a multiple of ONE.
        return (low - 1) >> FixedPoint.BITS;
    }

    /**
     * Whether the edge between two corners in {@link FixedPoint} units (either order) lights pixel
     * (x, y) by this rule: what {@link #add} and {@link #band} give, for one pixel.
     */
    static boolean lights(int ax, int ay, int bx, int by, int x, int y) {
        if (ax > bx || ax == bx && ay > by) {
            return lights(bx, by, ax, ay, x, y);
        }
        int dx = bx - ax;
        int dy = by - ay;
        double xa = ax / (double) FixedPoint.ONE;
        double ya = ay / (double) FixedPoint.ONE;
        if (Math.abs(dx) >= Math.abs(dy)) {
            return dx != 0 && x >= (ax + FixedPoint.HALF - 1) >> FixedPoint.BITS
                    && x <= (bx - FixedPoint.HALF) >> FixedPoint.BITS
                    && Math.floor(ya + (x + 0.5 - xa) * (dy / (double) dx)) == y;
        }
        return y >= (Math.min(ay, by) + FixedPoint.HALF - 1) >> FixedPoint.BITS
                && y <= (Math.max(ay, by) - FixedPoint.HALF) >> FixedPoint.BITS
                && Math.floor(xa + (y + 0.5 - ya) * (dx / (double) dy)) == x;
    }

    /**
     * Draws band {@code band}'s segments of {@code segments} (a CROSSING store binned by {@code bins})
     * into frame rows {@code [y0, y1)} and columns {@code [0, width)} through {@code write}: the loop of
     * {@link LineRaster#band} for this rule, one segment after another in one loop.
     *
     * @return pixels drawn
     */
    static long band(Segments segments, BandBins bins, int band, BorderOverlay write, int width, int y0, int y1) {
        int[] walks = segments.ints;
        double[] lines = segments.depth;
        OutlinePlan plan = segments.plan;
        int[] items = bins.items();
        long painted = 0;
        for (int k = bins.start(band), end = bins.start(band + 1); k < end; k++) {
            painted += edge(walks, lines, plan, items[k], write, width, y0, y1);
        }
        return painted;
    }

    /**
     * Draws segment {@code s}, whose store holds {@code walks} and {@code lines} for {@code plan}'s
     * outlines, into frame rows {@code [y0, y1)} and columns {@code [0, width)} through {@code write}.
     *
     * @return pixels drawn (each once, whether one or both triangles sharing the edge drew it)
     */
    private static int edge(int[] walks, double[] lines, OutlinePlan plan, int s, BorderOverlay write, int width,
                            int y0, int y1) {
        int w = ISTRIDE * s;
        write.edge(plan, walks[w], walks[w + 1]);
        int first = walks[w + 2];
        int last = walks[w + 3];
        int crossFirst = walks[w + 4];
        int crossLast = walks[w + 5];
        int k = DSTRIDE * s;
        double xa = lines[k];
        double ya = lines[k + 1];
        double slope = lines[k + 2];
        if (walks[w + 6] != 0) {
            return crossFirst >= y0 && crossLast < y1 && first >= 0 && last < width
                    ? byColumnInside(write, xa, ya, slope, first, last)
                    : byColumn(write, xa, ya, slope, lines[k + 3], first, last, width, y0, y1);
        }
        int from = Math.max(y0, first);
        int to = Math.min(y1 - 1, last);
        return crossFirst >= 0 && crossLast < width ? byRowInside(write, xa, ya, slope, from, to)
                : byRow(write, xa, ya, slope, from, to, width);
    }

    /**
     * Walks a mostly horizontal edge: in column c, the pixel on row floor(ya + (c + 0.5 - xa) * slope).
     * Only the columns whose rows can fall within [y0, y1) are visited, solved with the slope's
     * {@code inverse} and a column of margin; the exact test decides.
     */
    private static int byColumn(BorderOverlay write, double xa, double ya, double slope, double inverse, int first,
                                int last, int width, int y0, int y1) {
        double from = first;
        double to = last;
        if (slope != 0) {
            double c0 = xa - 0.5 + (y0 - ya) * inverse;
            double c1 = xa - 0.5 + (y1 - ya) * inverse;
            from = Math.max(from, Math.floor(Math.min(c0, c1)) - 1);
            to = Math.min(to, Math.ceil(Math.max(c0, c1)) + 1);
        }
        int c = (int) Math.max(from, 0);
        int end = (int) Math.min(to, width - 1);
        int painted = 0;
        for (; c <= end; c++) {
            double r = ya + (c + 0.5 - xa) * slope;
            // r >= y0 >= 0, so the cast floors.
            if (r >= y0 && r < y1) {
                painted += write.plot(c, (int) r);
            }
        }
        return painted;
    }

    /** {@link #byColumn} for an edge whose pixels all lie within the band and the frame. */
    private static int byColumnInside(BorderOverlay write, double xa, double ya, double slope, int first, int last) {
        if (write.simple) {
            return simple(write, xa, ya, slope, first, last, 1);
        }
        int painted = 0;
        for (int c = first; c <= last; c++) {
            // At least the edge's first row, >= 0, so the cast floors.
            painted += write.plot(c, (int) (ya + (c + 0.5 - xa) * slope));
        }
        return painted;
    }

    /** {@link #byRow} for an edge whose pixels all lie within the frame's columns. */
    private static int byRowInside(BorderOverlay write, double xa, double ya, double slope, int first, int last) {
        if (write.simple) {
            return simple(write, ya, xa, slope, first, last, 0);
        }
        int painted = 0;
        for (int r = first; r <= last; r++) {
            painted += write.plot((int) (xa + (r + 0.5 - ya) * slope), r);
        }
        return painted;
    }

    /** Walks a mostly vertical edge over rows first..last: in row r, the pixel in column floor(xa + (r + 0.5 - ya) * slope). */
    private static int byRow(BorderOverlay write, double xa, double ya, double slope, int first, int last, int width) {
        int painted = 0;
        for (int r = first; r <= last; r++) {
            double c = xa + (r + 0.5 - ya) * slope;
            // c >= 0, so the cast floors.
            if (c >= 0 && c < width) {
                painted += write.plot((int) c, r);
            }
        }
        return painted;
    }

    /**
     * {@link #byColumnInside} ({@code alongX} 1) or {@link #byRowInside} ({@code alongX} 0) of a
     * {@link BorderOverlay#simple simple} edge: step {@code k} = first..last along the edge's major
     * axis, the other coordinate floor(b0 + (k + 0.5 - a0) * slope). Each value is the same double as
     * there: k and k + 0.5 are counted up exactly in doubles, and the 0/1 weights that put k and the
     * other coordinate into x and y are exact, every value being a whole number.
     */
    private static int simple(BorderOverlay write, double a0, double b0, double slope, int first, int last,
                              double alongX) {
        double alongY = 1 - alongX;
        int painted = 0;
        int width = write.width;
        double k = first;
        for (int n = first; n <= last; n++, k++) {
            double b = Math.floor(b0 + (k + 0.5 - a0) * slope);
            double x = k * alongX + b * alongY;
            double y = k * alongY + b * alongX;
            painted += write.plotSimple((int) y * width + (int) x, x, y);
        }
        return painted;
    }
}
