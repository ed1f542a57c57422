package dev.trisect.raster;

import dev.trisect.tessellate.PieceSink;
import dev.trisect.tessellate.VertexLayout;
import java.util.Arrays;

/**
 * Screen-space triangles ready to fill, in drawing order, as parallel primitive arrays.
 *
 * <p>Per triangle: corners snapped to the {@link FixedPoint} grid (for coverage), the same corners
 * unsnapped in pixels (for attribute planes, so snapping never bends the texture mapping), and per
 * corner {@code 1/w} (view-space units^-1) and the varyings of its {@link VertexLayout} (texel
 * coordinates s, t first; {@link #layout}), and once per triangle the layout's flat values, if it has
 * any (after its corners, {@link #flatOffset()}: a flat-shaded triangle's colour). Plus the input triangle's index
 * (for the UV output), its material (the texture to sample), and whether it must be filled per pixel
 * (a tessellated piece a cap stopped short of its policy, see {@link #perPixel()}). The arrays grow as needed and are
 * reused from frame to frame; {@link #shrinkTo} gives storage back after a spike.
 */
public final class ScreenTriangles {
    /** Ints per triangle in {@link #fixed()}: x0, y0, x1, y1, x2, y2. */
    public static final int FIXED_STRIDE = 6;
    /** Doubles per triangle in {@link #screen()}: x0, y0, x1, y1, x2, y2 in pixels. */
    public static final int SCREEN_STRIDE = 6;
    /** Doubles {@link #edges} writes. */
    public static final int EDGES = 7;
    /**
     * {@link #links()} of an edge on its input triangle's own boundary (every edge of a triangle not
     * split): it may have the same corners as an edge of another triangle, which only comparing
     * positions finds.
     */
    public static final int OUTER = -1;
    /** {@link #links()} of an edge inside its input triangle that no earlier piece shares. */
    public static final int INNER = -2;

    private int count;
    private VertexLayout layout = VertexLayout.TEXTURED;
    /** {@link #cornerStride} of a lit frame's layout: 1/w, s, t, r, g, b. */
    private static final int LIT_CORNER = 6;
    /** Doubles per corner in {@link #attributes}: 1/w and the varyings. */
    private int cornerStride = 1 + VertexLayout.TEXTURED.varyings();
    private int[] fixed = new int[FIXED_STRIDE * 1024];
    private double[] screen = new double[SCREEN_STRIDE * 1024];
    /** Flat values per triangle: the layout's, after its three corners in {@link #attributes}. */
    private int flatStride;
    /** Doubles per triangle in {@link #attributes}: three corners, then the flat values. */
    private int triangleStride = 3 * cornerStride;
    private double[] attributes = new double[triangleStride * 1024];
    private int[] ids = new int[1024];
    private int[] materials = new int[1024];
    private boolean[] perPixel = new boolean[1024];
    private byte[] levels = new byte[1024];
    private int[] links = new int[3 * 1024];

    /** Number of triangles. */
    public int count() {
        return count;
    }

    /** Removes all triangles, keeping the storage. */
    public void clear() {
        count = 0;
    }

    /**
     * Removes all triangles and sets the vertex layout of those that follow ({@link
     * VertexLayout#TEXTURED} until set): which varyings each corner carries.
     */
    public void layout(VertexLayout vertexLayout) {
        count = 0;
        if (vertexLayout != layout) {
            layout = vertexLayout;
            cornerStride = 1 + vertexLayout.varyings();
            flatStride = vertexLayout.flats();
            triangleStride = 3 * cornerStride + flatStride;
            // Storage is kept when it is large enough: a view switching between lit and unlit frames
            // (5 and 2 varyings) does not reallocate it at every switch.
            if (attributes.length < triangleStride * ids.length) {
                attributes = new double[triangleStride * ids.length];
            }
        }
    }

    /** The vertex layout of the triangles' varyings. */
    public VertexLayout layout() {
        return layout;
    }

    /** Doubles per corner in {@link #attributes()}: 1/w, then the layout's varyings. */
    public int cornerStride() {
        return cornerStride;
    }

    /**
     * Doubles per triangle in {@link #attributes()}: three corners of {@link #cornerStride()}, then the
     * layout's flat values ({@link #flatOffset()}).
     */
    public int attributeStride() {
        return triangleStride;
    }

    /**
     * Where a triangle's flat values ({@link VertexLayout#flats()}: a flat-shaded triangle's colour)
     * start among its {@link #attributes()}, after its corners: triangle i's at
     * {@code i * attributeStride() + flatOffset()}. Beside the corners rather than in an array of their
     * own, so that the setup reads them from the cache lines it reads the corners from.
     */
    public int flatOffset() {
        return 3 * cornerStride;
    }

    /** How many triangles fit before the storage must grow. */
    public int capacity() {
        return ids.length;
    }

    /**
     * Reallocates the storage to hold {@code triangles} (at least the current count), giving the rest
     * back to the garbage collector: for after a spike in the number of triangles.
     */
    public void shrinkTo(int triangles) {
        int n = Math.max(Math.max(triangles, count), 1);
        if (n < ids.length) {
            resize(n);
        }
    }

    /** Snapped corners, sub-pixel units. Read-only outside this package. */
    public int[] fixed() {
        return fixed;
    }

    /** Unsnapped corners, pixels. */
    public double[] screen() {
        return screen;
    }

    /**
     * Per corner, {@link #cornerStride()} doubles: 1/w, then the varyings of the {@link #layout()} (s, t
     * first); corner k of triangle i at {@code i * attributeStride() + k * cornerStride()}; then the
     * triangle's flat values, if the layout has any ({@link #flatOffset()}).
     */
    public double[] attributes() {
        return attributes;
    }

    /** Input triangle index of each triangle. */
    public int[] ids() {
        return ids;
    }

    /** Material index of each triangle. */
    public int[] materials() {
        return materials;
    }

    /**
     * Whether each triangle is filled perspective-correct whatever the path: the fallback for pieces
     * that a cap stopped before they met their split policy.
     */
    public boolean[] perPixel() {
        return perPixel;
    }

    /**
     * Split level of each triangle: how many times the most-halved of its edges was halved (0 for a
     * triangle that was not split, and in the paths that do not split), for the overlay's depth colouring.
     */
    public byte[] levels() {
        return levels;
    }

    /**
     * Per triangle edge (edge e of triangle i at {@code 3 * i + e}, from corner e to corner e + 1
     * mod 3): {@code 3 * j + f} when it is edge f of an earlier triangle j, a piece of the same input
     * triangle with the same two corners, as the tessellator made them ({@link PieceSink}); {@link
     * #OUTER} or {@link #INNER} otherwise.
     */
    public int[] links() {
        return links;
    }

    /**
     * The link of an edge of triangle {@code index} (about to be appended) from the link a {@link PieceSink}
     * was handed for it: the earlier piece's edge counted back from
     * this one becomes that piece's edge in these triangles (the pieces of one input triangle are
     * appended one after another).
     */
    public static int link(int pieceLink, int index) {
        if (pieceLink < 0) {
            return pieceLink == PieceSink.OUTER ? OUTER : INNER;
        }
        return 3 * (index - pieceLink / 3) + pieceLink % 3;
    }

    /** Appends an unsplit triangle that follows the frame's path (not a per-pixel fallback); see the full form. */
    public void add(double x0, double y0, double q0, double s0, double t0,
                    double x1, double y1, double q1, double s1, double t1,
                    double x2, double y2, double q2, double s2, double t2,
                    int id, int material) {
        add(x0, y0, q0, s0, t0, x1, y1, q1, s1, t1, x2, y2, q2, s2, t2, id, material, false, 0);
    }

    /** Appends an unsplit triangle (split level 0); see the full form. */
    public void add(double x0, double y0, double q0, double s0, double t0,
                    double x1, double y1, double q1, double s1, double t1,
                    double x2, double y2, double q2, double s2, double t2,
                    int id, int material, boolean fallback) {
        add(x0, y0, q0, s0, t0, x1, y1, q1, s1, t1, x2, y2, q2, s2, t2, id, material, fallback, 0);
    }

    /** Appends a triangle whose edges are all {@link #OUTER}; see the full form. */
    public void add(double x0, double y0, double q0, double s0, double t0,
                    double x1, double y1, double q1, double s1, double t1,
                    double x2, double y2, double q2, double s2, double t2,
                    int id, int material, boolean fallback, int level) {
        add(x0, y0, q0, s0, t0, x1, y1, q1, s1, t1, x2, y2, q2, s2, t2, id, material, fallback, level,
                OUTER, OUTER, OUTER);
    }

    /**
     * Appends a triangle of the {@link VertexLayout#TEXTURED} layout from its values.
     *
     * @param x0 screen x of corner 0, pixels (snapped here)
     * @param q0 1/w of corner 0, w the view depth &gt; 0
     * @param s0 texel s of corner 0
     * @param t0 texel t of corner 0
     * @param fallback fill this triangle per pixel (perspective-correct) whatever the frame's path
     * @param level    its split level (see {@link #levels()}), stored clamped to 0..127
     * @param link0    the link of edge 0 (see {@link #links()}): an earlier triangle's edge, OUTER or INNER
     * @throws IllegalStateException when the triangles' {@link #layout()} has more varyings
     */
    public void add(double x0, double y0, double q0, double s0, double t0,
                    double x1, double y1, double q1, double s1, double t1,
                    double x2, double y2, double q2, double s2, double t2,
                    int id, int material, boolean fallback, int level, int link0, int link1, int link2) {
        if (layout != VertexLayout.TEXTURED) {
            throw new IllegalStateException("these triangles carry " + layout.varyings()
                    + " varyings; add them from vertices");
        }
        int a = append(x0, y0, x1, y1, x2, y2, id, material, fallback, level, link0, link1, link2);
        attributes[a] = q0;
        attributes[a + 1] = s0;
        attributes[a + 2] = t0;
        attributes[a + 3] = q1;
        attributes[a + 4] = s1;
        attributes[a + 5] = t1;
        attributes[a + 6] = q2;
        attributes[a + 7] = s2;
        attributes[a + 8] = t2;
    }

    /**
     * Appends a triangle from three projected vertices in the triangles' {@link #layout()} (as a
     * {@link dev.trisect.tessellate.Tessellator} hands them to a {@link PieceSink}): their screen
     * positions, 1/w and varyings. Other parameters as in the other form.
     *
     * @param v       vertices, {@link VertexLayout#projectedStride()} doubles each
     * @param a       offset of corner 0 in {@code v}; {@code b}, {@code c} of corners 1 and 2
     */
    public void add(double[] v, int a, int b, int c, int id, int material, boolean fallback, int level,
                    int link0, int link1, int link2) {
        add(v, a, b, c, id, material, fallback, level, link0, link1, link2, null, 0);
    }

    /**
     * As the other form, with the triangle's flat values ({@link #flatOffset()}) copied from
     * {@code flat[flatAt..]}: as many as the layout has (none read when it has none; null then allowed).
     */
    public void add(double[] v, int a, int b, int c, int id, int material, boolean fallback, int level,
                    int link0, int link1, int link2, double[] flat, int flatAt) {
        int sx = layout.screenX();
        int o = append(v[a + sx], v[a + sx + 1], v[b + sx], v[b + sx + 1], v[c + sx], v[c + sx + 1], id, material,
                fallback, level, link0, link1, link2);
        int fs = flatStride;
        if (fs == 1) {
            // A flat-lit frame's colour (PixelState.flatColour), once per triangle: one store, not a
            // copy of a length the compiler does not know.
            attributes[o + 3 * cornerStride] = flat[flatAt];
        } else if (fs != 0) {
            System.arraycopy(flat, flatAt, attributes, o + 3 * cornerStride, fs);
        }
        corner(v, a, o);
        corner(v, b, o + cornerStride);
        corner(v, c, o + 2 * cornerStride);
    }

    /** Corner attributes from the vertex at {@code v[from..]}: 1/w, then the varyings. */
    private void corner(double[] v, int from, int to) {
        double[] at = attributes;
        at[to] = 1 / v[from + VertexLayout.W];
        if (cornerStride == 3) {
            // The textured layout, once per corner of every triangle: two stores, not a loop.
            at[to + 1] = v[from + VertexLayout.S];
            at[to + 2] = v[from + VertexLayout.T];
            return;
        }
        if (cornerStride == LIT_CORNER) {
            // A lit frame's layout (s, t, r, g, b): a copy of a constant length, not a loop.
            System.arraycopy(v, from + VertexLayout.FIRST_VARYING, at, to + 1, LIT_CORNER - 1);
            return;
        }
        for (int k = 1, f = from + VertexLayout.FIRST_VARYING; k < cornerStride; k++, f++) {
            at[to + k] = v[f];
        }
    }

    /** Appends everything of a triangle but its attributes; returns where they go in {@link #attributes}. */
    private int append(double x0, double y0, double x1, double y1, double x2, double y2, int id, int material,
                       boolean fallback, int level, int link0, int link1, int link2) {
        if (count == ids.length) {
            grow();
        }
        int f = count * FIXED_STRIDE;
        fixed[f] = FixedPoint.snap(x0);
        fixed[f + 1] = FixedPoint.snap(y0);
        fixed[f + 2] = FixedPoint.snap(x1);
        fixed[f + 3] = FixedPoint.snap(y1);
        fixed[f + 4] = FixedPoint.snap(x2);
        fixed[f + 5] = FixedPoint.snap(y2);
        int s = count * SCREEN_STRIDE;
        screen[s] = x0;
        screen[s + 1] = y0;
        screen[s + 2] = x1;
        screen[s + 3] = y1;
        screen[s + 4] = x2;
        screen[s + 5] = y2;
        ids[count] = id;
        materials[count] = material;
        perPixel[count] = fallback;
        levels[count] = (byte) Math.max(0, Math.min(127, level));
        int l = 3 * count;
        links[l] = link0;
        links[l + 1] = link1;
        links[l + 2] = link2;
        return triangleStride * count++;
    }

    private void grow() {
        resize(ids.length * 2);
    }

    /** Reallocates every array for {@code n} triangles, keeping the first {@code min(n, count)}. */
    private void resize(int n) {
        fixed = Arrays.copyOf(fixed, n * FIXED_STRIDE);
        screen = Arrays.copyOf(screen, n * SCREEN_STRIDE);
        attributes = Arrays.copyOf(attributes, n * triangleStride);
        ids = Arrays.copyOf(ids, n);
        materials = Arrays.copyOf(materials, n);
        perPixel = Arrays.copyOf(perPixel, n);
        levels = Arrays.copyOf(levels, n);
        links = Arrays.copyOf(links, 3 * n);
    }

    /** Smallest pixel row whose centre the triangle can cover (may be below 0). */
    public int firstRow(int triangle) {
        int f = triangle * FIXED_STRIDE;
        int minY = Math.min(fixed[f + 1], Math.min(fixed[f + 3], fixed[f + 5]));
        return FixedPoint.firstCentre(minY);
    }

    /** One past the largest pixel row whose centre the triangle can cover. */
    public int endRow(int triangle) {
        int f = triangle * FIXED_STRIDE;
        int maxY = Math.max(fixed[f + 1], Math.max(fixed[f + 3], fixed[f + 5]));
        return FixedPoint.endCentre(maxY);
    }

    /**
     * The screen triangle at {@code s}, an offset into {@link #screen()}, seen from its corner 0, into
     * {@code into[0..6]}: x0, y0; ex1, ey1 and ex2, ey2, the edges to corners 1 and 2; and their cross
     * product det = ex1 * ey2 - ex2 * ey1 (twice the signed area, in square pixels), the others in pixels. What fitting a plane
     * over the triangle or weighing a point in it starts from.
     *
     * @return false when the triangle has no area (det 0 or not finite); {@code into} is written either way
     */
    public static boolean edges(double[] screen, int s, double[] into) {
        double x0 = screen[s];
        double y0 = screen[s + 1];
        into[0] = x0;
        into[1] = y0;
        for (int k = 2; k < 6; k += 2) {
            into[k] = screen[s + k] - x0;
            into[k + 1] = screen[s + k + 1] - y0;
        }
        double det = into[2] * into[5] - into[4] * into[3];
        into[6] = det;
        return det != 0 && Double.isFinite(det);
    }
}
