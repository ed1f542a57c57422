package dev.trisect.raster;

import dev.trisect.render.BorderStyle;
import java.util.Arrays;

/**
 * The border overlay's work for one list of screen triangles, prepared once per frame rather than
 * once per band: each outlined triangle's depth plane, colour and opacity, and the edges to walk as
 * segments of the line rasterizer's {@link Segments#CROSSING CROSSING} rule ({@link #segments()}),
 * each set up once by {@link LineCrossing} (its canonical ends, slope and pixel range) and binned into
 * the bands of rows its pixels can fall on ({@link #bins()}). {@link LineRaster#band} draws a band of
 * them, each pixel decided by the {@link BorderOverlay}'s write. They are a list of one kind, so they
 * are binned as they are without a command word each: the overlay's memory traffic stays that of its
 * edges.
 *
 * <p>An edge shared by two outlined triangles of the list (the same snapped corners, as the inner
 * edges of a tessellated triangle's pieces are) is walked once, in the later triangle's turn; at each
 * of its pixels the earlier triangle's outline is applied first, then the later one's, each with its
 * own depth test, colour and opacity. That is what drawing the edge twice did, except where a third
 * outline, between the two in drawing order, lights the same pixel in another colour or opacity.
 *
 * <p>Not thread-safe: prepared by one thread, then read by any number.
 */
public final class OutlinePlan {
    /** The earlier sharer of an edge no earlier triangle shares. */
    static final int ALONE = -1;
    /** Per-corner-edge mark of an edge a later triangle shares and walks. */
    private static final int WALKED_LATER = -2;
    /** A hash slot holding no edge. */
    private static final int EMPTY = -1;
    /** A hash slot whose edge has found its partner: probing passes over it. */
    private static final int MATCHED = -2;
    /** Storage for more than this many triangles may shrink when it is far larger than needed. */
    private static final int TRIM_FLOOR = 16384;

    /** Doubles per triangle in {@link #looks}. */
    static final int LOOK = 6;
    /**
     * Per triangle, {@link #LOOK} doubles: its 1/w plane over pixel centres (base, dx, dy, as {@link
     * Plane}), the least and greatest 1/w its outline's depth test may take, and its outline's
     * opacity (0..1). One record, so that drawing an edge reads one cache line for its triangle.
     *
     * <p>The range: a piece filled per pixel by the fallback is mostly a sliver, whose plane is steep
     * or ill-conditioned: evaluated half a pixel off it, it can put the outline in front of a nearer
     * surface. Its depth is then held to the range of its corners' 1/w, which every point of it lies
     * within (1/w is affine on screen). Other triangles are not held (infinite range): their plane is
     * their surface's, bit for bit.
     */
    double[] looks = new double[0];
    /** Per triangle: outline colour, opaque ARGB, or 0 for a triangle not outlined. */
    int[] colours = new int[0];
    /** Per triangle corner edge (edge e from corner e to corner e + 1): the earlier sharer, ALONE or WALKED_LATER. */
    private int[] partner = new int[0];

    /** The edges to walk, in drawing order: {@link Segments#CROSSING CROSSING} segments. */
    private final Segments edges = new Segments(Segments.CROSSING);
    /** The edges of each band, in drawing order. */
    private final BandBins bins = new BandBins();
    private int[] table = new int[0];
    /** Slots of {@link #table} in use this frame: a power of two. */
    private int slots;
    private final Plane depth = new Plane();
    /** {@link ScreenTriangles#edges} of the triangle being set up. */
    private final double[] corner = new double[ScreenTriangles.EDGES];

    /**
     * Prepares the outlines of the triangles of {@code triangles} that the fill draws (those with an
     * area covering a pixel centre on a row of the frame; only fallback pieces when the style says so)
     * in {@code style}, binned into bands of {@code bandRows} rows of a frame {@code height} pixels high.
     *
     * @param maxLevel the depth cap, drawn red when colouring by depth
     * @param maxError the Max error threshold in pixels, drawn yellow when colouring by bound
     */
    public void prepare(ScreenTriangles triangles, BorderStyle style, int maxLevel, double maxError, int height,
                        int bandRows) {
        int n = triangles.count();
        ensureTriangles(n);
        setUp(triangles, style, maxLevel, maxError, n, height);
        ensureTable(outerEdges(triangles.links(), n));
        matchEdges(triangles.fixed(), triangles.links(), n);
        edges(triangles.fixed(), n, height, bandRows);
        bins.build(edges.count(), BandBins.bandCount(height, bandRows));
    }

    /** The outlines' edges: {@link Segments#CROSSING CROSSING} segments, in drawing order. */
    public Segments segments() {
        return edges;
    }

    /** The edges of each band of rows, in drawing order: indices into {@link #segments()}. */
    public BandBins bins() {
        return bins;
    }

    private void setUp(ScreenTriangles triangles, BorderStyle style, int maxLevel, double maxError, int n,
                       int height) {
        double[] sc = triangles.screen();
        double[] at = triangles.attributes();
        boolean[] perPixel = triangles.perPixel();
        for (int tri = 0; tri < n; tri++) {
            colours[tri] = 0;
            // The frame's rows whose centres it can cover.
            int firstRow = Math.max(0, triangles.firstRow(tri));
            int endRow = Math.min(height, triangles.endRow(tri));
            if (firstRow >= endRow || style.onlyFallback() && !perPixel[tri]) {
                continue;
            }
            if (!depthPlane(triangles, tri, corner, depth)) {
                continue;
            }
            int a = tri * triangles.attributeStride();
            int cs = triangles.cornerStride();
            int l = LOOK * tri;
            looks[l] = depth.base;
            looks[l + 1] = depth.dx;
            looks[l + 2] = depth.dy;
            boolean held = perPixel[tri];
            looks[l + 3] = held ? Math.min(at[a], Math.min(at[a + cs], at[a + 2 * cs])) : Double.NEGATIVE_INFINITY;
            looks[l + 4] = held ? Math.max(at[a], Math.max(at[a + cs], at[a + 2 * cs])) : Double.POSITIVE_INFINITY;
            // A fallback piece is never faded: its magenta outline is what the legend counts, and it must show.
            looks[l + 5] = style.fade() && !held ? BorderOverlay.fadeAlpha(Math.abs(corner[6]) / 2,
                    perimeter(sc, tri * ScreenTriangles.SCREEN_STRIDE)) : 1;
            colours[tri] = style.colouring() == BorderStyle.Colouring.YELLOW ? OverlayColours.of(triangles, tri)
                    : OverlayColours.of(triangles, tri, style.colouring(), maxLevel, maxError);
        }
    }

    private static double perimeter(double[] sc, int s) {
        return Math.hypot(sc[s + 2] - sc[s], sc[s + 3] - sc[s + 1]) + Math.hypot(sc[s + 4] - sc[s + 2],
                sc[s + 5] - sc[s + 3]) + Math.hypot(sc[s] - sc[s + 4], sc[s + 1] - sc[s + 5]);
    }

    /**
     * Pairs up the edges of outlined triangles that have the same two snapped corners: inside an
     * input triangle as its {@link ScreenTriangles#links() links} say, and on the input triangles'
     * boundaries by comparing corners (through a hash of the edges), since the tessellator sees one
     * input triangle at a time.
     */
    private void matchEdges(int[] f, int[] links, int n) {
        int mask = slots - 1;
        Arrays.fill(table, 0, slots, EMPTY);
        for (int tri = 0; tri < n; tri++) {
            int o = tri * ScreenTriangles.FIXED_STRIDE;
            for (int e = 0; e < 3; e++) {
                int edge = 3 * tri + e;
                partner[edge] = ALONE;
                if (colours[tri] == 0) {
                    continue;
                }
                int link = links[edge];
                if (link != ScreenTriangles.OUTER) {
                    if (link >= 0 && colours[link / 3] != 0) {
                        partner[edge] = link / 3;
                        partner[link] = WALKED_LATER;
                    }
                    continue;
                }
                int a = o + 2 * e;
                int b = o + next(e);
                int ax = f[a];
                int ay = f[a + 1];
                int bx = f[b];
                int by = f[b + 1];
                // Symmetric in the two ends: the sharer walks the edge the other way round.
                int slot = hash(ax + bx, ay + by) & mask;
                while (true) {
                    int held = table[slot];
                    if (held == EMPTY) {
                        table[slot] = edge;
                        break;
                    }
                    if (held >= 0 && sameEdge(f, held, ax, ay, bx, by)) {
                        partner[edge] = held / 3;
                        partner[held] = WALKED_LATER;
                        table[slot] = MATCHED;
                        break;
                    }
                    slot = (slot + 1) & mask;
                }
            }
        }
    }

    /** Offset in a triangle's corners of edge e's second end: corner e + 1, wrapping. */
    private static int next(int e) {
        return e == 2 ? 0 : 2 * e + 2;
    }

    /** Hash of an edge by the sum of its ends (twice its midpoint), the same from either end. */
    private static int hash(int sumX, int sumY) {
        int h = sumX * 0x9E3779B1 ^ sumY * 0x85EBCA6B;
        return h ^ (h >>> 15) ^ (h >>> 23);
    }

    private static boolean sameEdge(int[] f, int edge, int ax, int ay, int bx, int by) {
        int tri = edge / 3;
        int e = edge - 3 * tri;
        int o = tri * ScreenTriangles.FIXED_STRIDE;
        int a = o + 2 * e;
        int b = o + next(e);
        return f[a] == ax && f[a + 1] == ay && f[b] == bx && f[b + 1] == by
                || f[a] == bx && f[a + 1] == by && f[b] == ax && f[b + 1] == ay;
    }

    /**
     * Lists the edges to walk in drawing order as line segments, each set up by the line
     * rasterizer's {@link LineCrossing crossing rule} with the rows its pixels can fall on.
     */
    private void edges(int[] f, int n, int height, int bandRows) {
        // Room for every edge, so that each is written in place (LineCrossing.add).
        ensureEdges(3 * n);
        bins.prepare(3 * n);
        int count = 0;
        // The crossing rule clips to the frame's columns when drawn (LineCrossing.band): no width here.
        edges.begin(0, height);
        edges.plan = this;
        for (int tri = 0; tri < n; tri++) {
            if (colours[tri] == 0) {
                continue;
            }
            int o = tri * ScreenTriangles.FIXED_STRIDE;
            for (int e = 0; e < 3; e++) {
                int earlier = partner[3 * tri + e];
                if (earlier == WALKED_LATER) {
                    continue;
                }
                int a = o + 2 * e;
                int b = o + next(e);
                long rows = LineCrossing.add(edges, count, f[a], f[a + 1], f[b], f[b + 1], tri, earlier, height);
                if (rows >= 0) {
                    bins.rows(count, (int) (rows >>> 32), (int) rows, bandRows);
                    count++;
                }
            }
        }
        edges.count(count);
    }

    /** The number of edges to walk (for tests). */
    int edgeCount() {
        return edges.count();
    }

    /** Edge {@code k}'s walker: the triangle whose turn it is (for tests). */
    int owner(int k) {
        return edges.ints[LineCrossing.ISTRIDE * k];
    }

    /** The earlier triangle sharing edge {@code k}, or {@link #ALONE} (for tests). */
    int earlier(int k) {
        return edges.ints[LineCrossing.ISTRIDE * k + 1];
    }

    /** Edge {@code k}'s line, i = 0, 1, 2: its canonical end's x and y, and its slope (for tests). */
    double line(int k, int i) {
        return edges.depth[LineCrossing.DSTRIDE * k + i];
    }

    /** Triangle {@code tri}'s outline opacity, 0..1. */
    double alpha(int tri) {
        return looks[LOOK * tri + 5];
    }

    /** Makes room for {@code n} triangles; gives storage back when it has become far larger than needed. */
    private void ensureTriangles(int n) {
        int capacity = colours.length;
        if (capacity < n || capacity > TRIM_FLOOR && capacity > 4 * n) {
            int size = capacity < n ? Math.max(n, 2 * capacity) : 2 * n;
            looks = new double[LOOK * size];
            colours = new int[size];
            partner = new int[3 * size];
        }
    }

    /** The edges of outlined triangles among the first {@code n} that lie on their input triangle's boundary. */
    private int outerEdges(int[] links, int n) {
        int outer = 0;
        for (int tri = 0; tri < n; tri++) {
            if (colours[tri] != 0) {
                int l = 3 * tri;
                outer += (links[l] == ScreenTriangles.OUTER ? 1 : 0) + (links[l + 1] == ScreenTriangles.OUTER ? 1 : 0)
                        + (links[l + 2] == ScreenTriangles.OUTER ? 1 : 0);
            }
        }
        return outer;
    }

    /** Makes the hash table room for {@code edges} edges; gives storage back when it has become far larger than needed. */
    private void ensureTable(int edges) {
        // Open addressing at a load of at most 1/2.
        slots = Integer.highestOneBit(Math.max(16, 2 * edges - 1)) << 1;
        if (table.length < slots || table.length > 8 * slots && table.length > 4 * TRIM_FLOOR) {
            table = new int[slots];
        }
    }

    private void ensureEdges(int n) {
        int capacity = edges.capacity();
        if (capacity < n) {
            edges.reserve(Math.max(n, 2 * capacity));
        } else if (capacity > 3 * TRIM_FLOOR && capacity > 4 * n) {
            edges.shrink(2 * n);
            bins.shrink(2 * n, 8 * n);
        }
    }

    /**
     * Fits {@code into} to screen triangle {@code tri}'s 1/w over pixel centres, from its corners' 1/w:
     * the plane its outline is depth-tested by ({@link #looks}); {@code edges} is scratch of
     * {@link ScreenTriangles#EDGES} doubles.
     *
     * @return false when the triangle has no area (it is not outlined)
     */
    static boolean depthPlane(ScreenTriangles triangles, int tri, double[] edges, Plane into) {
        if (!ScreenTriangles.edges(triangles.screen(), tri * ScreenTriangles.SCREEN_STRIDE, edges)) {
            return false;
        }
        double[] at = triangles.attributes();
        int a = tri * triangles.attributeStride();
        int cs = triangles.cornerStride();
        into.fit(edges[0], edges[1], edges[2], edges[3], edges[4], edges[5], 1 / edges[6], at[a], at[a + cs],
                at[a + 2 * cs]);
        return true;
    }
}
