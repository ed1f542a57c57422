package dev.trisect.raster;

import dev.trisect.tessellate.SplitTree;
import dev.trisect.tessellate.VertexLayout;
import dev.trisect.texture.internal.Lod;
import java.util.Arrays;

/**
 * The tessellated path's input triangles with the split trees that say which of their pieces each
 * pixel lies in, for {@link TreeFill}: one pass per input triangle, coverage from the input triangle
 * itself, each row cut into its pieces' segments by descending the tree.
 *
 * <p>Per input triangle that was split (in the order added; a {@link Commands#TREE} command refers to
 * it by that index): the triangle as the tessellator received it, in {@link #inputs()} (snapped
 * corners for coverage, {@code 1/w} for depth, texel coordinates for the per-pixel fallback), and the
 * root of its tree. An input triangle that was not split is its one piece, a {@link Commands#TRIANGLE}
 * command, and has nothing here. A node is one split: a line in screen pixels ({@link #lines()}: along the
 * row of pixel centres of pixel row y it lies at x = {@code k y + m + 0.5}, so that its first column
 * at or right of the line is {@code ceil(k y + m)}) and its two children ({@link #kids()}: left,
 * the side of smaller x, then right), each a node ({@code >= 0}), a piece ({@code -1 - p}, p the
 * piece's index in the chunk's pieces) or {@link #NO_PIECE} (dropped off screen).
 *
 * <p>Per piece, set up in bulk when its input triangle is added (the geometry pass, not the fill): the affine
 * planes of its varyings over pixel centres ({@link #planes()}: s base, dx, dy, then t, then any
 * further varying of the {@link VertexLayout}: each is affine per piece), fitted exactly as
 * {@link TriangleSetup} fits a piece's, their steps per column in 32.32 fixed point and the piece's
 * first column where its rows are anchored ({@link #fixedSteps()}, {@link #firstColumns()}), how it is
 * filled ({@link #kinds()}) and, for trilinear filtering, its one level of detail ({@link #selections()}).
 *
 * <p>Storage grows as needed and is kept from frame to frame; {@link #clear} empties it.
 */
public final class SplitTrees {
    /** The reference of a piece dropped for lying off screen (no pixel centre of the frame lies in it). */
    public static final int NO_PIECE = SplitTree.NO_PIECE;
    /** Doubles per node in {@link #lines()}: k, m (see the class comment). */
    public static final int LINE = 2;
    /** Doubles per varying in {@link #planes()}: base, dx, dy. */
    public static final int PLANE = 3;
    /** Longs per piece in {@link #fixedSteps()}: the steps of s and of t per column, 32.32 fixed point. */
    public static final int FIXED_STEP = 2;
    /** {@link #kinds()}: affine, stepped in 32.32 fixed point. */
    public static final byte AFFINE = 0;
    /** {@link #kinds()}: affine, texel coordinates too large for fixed point, in doubles per pixel. */
    public static final byte AFFINE_WIDE = 1;
    /** {@link #kinds()}: the per-pixel fallback (a cap stopped it, or a sliver): perspective-correct. */
    public static final byte PER_PIXEL = 2;

    /** 2^32: texel coordinates in 32.32 fixed point. */
    private static final double FIXED_SCALE = 4294967296.0;

    private final ScreenTriangles inputs = new ScreenTriangles();
    private int[] roots = new int[1024];
    private int[] nodeCounts = new int[1024];
    private int nodes;
    private int[] kids = new int[2 * 4096];
    private double[] lines = new double[LINE * 4096];
    private int[] rows = new int[2 * 4096];
    private int[] rowKids = new int[2 * 4096];
    private int pieces;
    /** Doubles per piece in {@link #planes}: a {@link #PLANE} per varying. */
    private int planeStride = PLANE * VertexLayout.TEXTURED.varyings();
    private double[] planes = new double[planeStride * 4096];
    private long[] fixedSteps = new long[FIXED_STEP * 4096];
    private int[] firstColumns = new int[4096];
    private byte[] kinds = new byte[4096];
    private int[] selections = new int[4096];
    /** Scratch for fitting a piece's planes exactly as the piece-by-piece fill fits them. */
    private final TriangleSetup scratch = new TriangleSetup();

    /** Removes every input triangle, keeping the storage. */
    public void clear() {
        inputs.clear();
        nodes = 0;
        pieces = 0;
    }

    /**
     * Removes every input triangle and sets the vertex layout of the input triangles and pieces that follow
     * ({@link VertexLayout#TEXTURED} until set).
     */
    public void layout(VertexLayout layout) {
        clear();
        inputs.layout(layout);
        int stride = PLANE * layout.varyings();
        if (stride != planeStride) {
            planeStride = stride;
            // Kept when large enough, as ScreenTriangles keeps its attributes.
            if (planes.length < stride * kinds.length) {
                planes = new double[stride * kinds.length];
            }
        }
    }

    /** Doubles per piece in {@link #planes()}: {@link #PLANE} per varying of the layout. */
    public int planeStride() {
        return planeStride;
    }

    /** Number of input triangles added (each split), in the order they were added. */
    public int count() {
        return inputs.count();
    }

    /** The input triangles that were split, with their ids and materials. */
    public ScreenTriangles inputs() {
        return inputs;
    }

    /** The root of each input triangle's tree (a reference, see the class comment). */
    public int[] roots() {
        return roots;
    }

    /** The nodes' children, two per node: left, right. */
    public int[] kids() {
        return kids;
    }

    /**
     * Per node, two rows: rows above the first lie wholly in the child {@link #rowKids()} names first,
     * rows from the second on wholly in the one it names second; only the rows between (those its line
     * meets, or nearly: see {@link SplitTree#rows()}) evaluate the line.
     */
    public int[] rows() {
        return rows;
    }

    /** Per node, the child of the rows above its line's rows, then the child of the rows below. */
    public int[] rowKids() {
        return rowKids;
    }

    /** The nodes' lines, {@link #LINE} doubles per node, screen pixels. */
    public double[] lines() {
        return lines;
    }

    /**
     * Per piece of the chunk, {@link #planeStride()} doubles: the planes over pixel centres of its
     * varyings, {@link #PLANE} doubles each (base, dx, dy), s first, then t, then the others.
     */
    public double[] planes() {
        return planes;
    }

    /**
     * Per piece, {@link #FIXED_STEP} longs: the steps per column of s and of t in 32.32 fixed point,
     * {@code floor(dx * 2^32)}, as {@link FixedLoops} steps a piece.
     */
    public long[] fixedSteps() {
        return fixedSteps;
    }

    /**
     * Per piece: its own first column (from its snapped corners), where each of its rows is anchored in
     * fixed point as {@link FixedLoops} anchors it, so that a pixel's texel coordinates
     * are those the piece-by-piece fill gave it: they depend on the piece and the pixel alone.
     */
    public int[] firstColumns() {
        return firstColumns;
    }

    /**
     * Per piece: its one level of detail for trilinear filtering ({@link Lod#select} form), from its
     * planes' constant derivatives as the trilinear loops take it, or 0 when its input triangle was added
     * without a mip chain's last level.
     */
    public int[] selections() {
        return selections;
    }

    /** Per piece: {@link #AFFINE}, {@link #AFFINE_WIDE} or {@link #PER_PIXEL}. */
    public byte[] kinds() {
        return kinds;
    }

    /** The number of nodes of the tree of input triangle {@code i}, an index into {@link #inputs()}. */
    public int nodeCount(int i) {
        return nodeCounts[i];
    }

    /**
     * Adds an input triangle that was split, of the {@link VertexLayout#TEXTURED} layout: the input triangle
     * (screen pixels, {@code 1/w}, texel coordinates per corner); otherwise as the other form.
     *
     * @return the input triangle's index, the reference of its {@link Commands#TREE} command
     */
    public int add(double x0, double y0, double q0, double s0, double t0,
                    double x1, double y1, double q1, double s1, double t1,
                    double x2, double y2, double q2, double s2, double t2, int id, int material,
                    SplitTree tree, ScreenTriangles pieceTriangles, int firstPiece, int maxLevel) {
        inputs.add(x0, y0, q0, s0, t0, x1, y1, q1, s1, t1, x2, y2, q2, s2, t2, id, material);
        return addTree(tree, pieceTriangles, firstPiece, maxLevel);
    }

    /**
     * Adds an input triangle that was split, from its three projected vertices in the
     * layout set ({@link #layout}; at offsets {@code a}, {@code b}, {@code c} of {@code v}, as a
     * {@link dev.trisect.tessellate.Tessellator} holds them), and its split tree as the tessellator
     * recorded it, whose leaf k is piece {@code firstPiece + k} of {@code pieceTriangles} (already
     * appended there, {@code tree.leaves()} of them).
     *
     * @param maxLevel the last level of the material's mip chain when the frame filters trilinearly
     *                 (each piece's level of detail is set up with it), else 0
     * @return the input triangle's index, the reference of its {@link Commands#TREE} command
     */
    public int add(double[] v, int a, int b, int c, int id, int material, SplitTree tree,
                    ScreenTriangles pieceTriangles, int firstPiece, int maxLevel) {
        return add(v, a, b, c, id, material, null, 0, tree, pieceTriangles, firstPiece, maxLevel);
    }

    /**
     * As the other form, with the input triangle's flat values ({@link ScreenTriangles#flatOffset()}) from
     * {@code flat[flatAt..]}, as many as the layout has.
     */
    public int add(double[] v, int a, int b, int c, int id, int material, double[] flat, int flatAt, SplitTree tree,
                   ScreenTriangles pieceTriangles, int firstPiece, int maxLevel) {
        inputs.add(v, a, b, c, id, material, false, 0, ScreenTriangles.OUTER, ScreenTriangles.OUTER,
                ScreenTriangles.OUTER, flat, flatAt);
        return addTree(tree, pieceTriangles, firstPiece, maxLevel);
    }

    /** The tree and pieces of the input triangle just appended to {@link #inputs}; returns its index. */
    private int addTree(SplitTree tree, ScreenTriangles pieceTriangles, int firstPiece, int maxLevel) {
        int root = tree.root();
        int[] treeKids = tree.kids();
        double[] treeLines = tree.lines();
        int[] treeRows = tree.rows();
        int treeNodes = tree.nodes();
        int leaves = tree.leaves();
        int g = inputs.count() - 1;
        if (g == roots.length) {
            roots = Arrays.copyOf(roots, 2 * g);
            nodeCounts = Arrays.copyOf(nodeCounts, 2 * g);
        }
        int base = nodes;
        if (2 * (base + treeNodes) > kids.length) {
            int n = Math.max(2 * (base + treeNodes), 2 * kids.length);
            kids = Arrays.copyOf(kids, n);
            lines = Arrays.copyOf(lines, n / 2 * LINE);
            rows = Arrays.copyOf(rows, n);
            rowKids = Arrays.copyOf(rowKids, n);
        }
        roots[g] = translate(root, base, firstPiece);
        nodeCounts[g] = treeNodes;
        for (int k = 0; k < 2 * treeNodes; k++) {
            kids[2 * base + k] = translate(treeKids[k], base, firstPiece);
        }
        System.arraycopy(treeLines, 0, lines, LINE * base, LINE * treeNodes);
        for (int k = 0; k < treeNodes; k++) {
            int o = 2 * (base + k);
            rows[o] = treeRows[3 * k];
            rows[o + 1] = treeRows[3 * k + 1];
            int upper = treeRows[3 * k + 2];
            rowKids[o] = kids[o + upper];
            rowKids[o + 1] = kids[o + 1 - upper];
        }
        nodes = base + treeNodes;
        fitPieces(pieceTriangles, firstPiece, firstPiece + leaves, maxLevel);
        return g;
    }

    private static int translate(int ref, int nodeBase, int firstPiece) {
        if (ref == SplitTree.NO_PIECE) {
            return NO_PIECE;
        }
        return ref >= 0 ? nodeBase + ref : -1 - (firstPiece + (-1 - ref));
    }

    /** Sets up pieces [from, to) of {@code t}: planes, first columns, steps, kinds and levels of detail. */
    private void fitPieces(ScreenTriangles t, int from, int to, int maxLevel) {
        if (to > kinds.length) {
            int n = Math.max(to, 2 * kinds.length);
            planes = Arrays.copyOf(planes, planeStride * n);
            fixedSteps = Arrays.copyOf(fixedSteps, FIXED_STEP * n);
            firstColumns = Arrays.copyOf(firstColumns, n);
            kinds = Arrays.copyOf(kinds, n);
            selections = Arrays.copyOf(selections, n);
        }
        pieces = Math.max(pieces, to);
        int[] f = t.fixed();
        boolean[] perPixel = t.perPixel();
        TriangleSetup setup = scratch;
        for (int p = from; p < to; p++) {
            int o = p * ScreenTriangles.FIXED_STRIDE;
            int minX = Math.min(f[o], Math.min(f[o + 2], f[o + 4]));
            firstColumns[p] = FixedPoint.firstCentre(minX);
            // The piece's affine planes exactly as the piece-by-piece fill set them up; a piece whose
            // snapped corners enclose no area (which that fill gave no pixel) has none: a pixel centre
            // its region holds takes the input triangle's perspective-correct mapping.
            boolean flat = !setup.affinePlanes(t, p);
            int po = planeStride * p;
            for (int k = 0, o2 = po; o2 < po + planeStride; k++, o2 += PLANE) {
                Plane plane = setup.planes[1 + k];
                planes[o2] = plane.base;
                planes[o2 + 1] = plane.dx;
                planes[o2 + 2] = plane.dy;
            }
            fixedSteps[FIXED_STEP * p] = (long) Math.floor(planes[po + 1] * FIXED_SCALE);
            fixedSteps[FIXED_STEP * p + 1] = (long) Math.floor(planes[po + 4] * FIXED_SCALE);
            kinds[p] = perPixel[p] || flat ? PER_PIXEL : setup.fixedPointSafe ? AFFINE : AFFINE_WIDE;
            double sDx = planes[po + 1];
            double sDy = planes[po + 2];
            double tDx = planes[po + 4];
            double tDy = planes[po + 5];
            selections[p] = maxLevel <= 0 ? 0
                    : Lod.selectOfSquared(sDx * sDx + tDx * tDx, sDy * sDy + tDy * tDy, maxLevel);
        }
    }

    /**
     * Gives storage back after a spike, keeping room for {@code n} pieces (and as many nodes and
     * input triangles). Each kind of storage is trimmed on its own: a spike may grow one alone (a frame
     * of off-screen pieces grows only the nodes).
     */
    public void shrinkTo(int n) {
        int keep = Math.max(n, 1);
        inputs.shrinkTo(Math.max(keep, inputs.count()));
        int p = Math.max(keep, pieces);
        if (kinds.length > p) {
            planes = Arrays.copyOf(planes, planeStride * p);
            fixedSteps = Arrays.copyOf(fixedSteps, FIXED_STEP * p);
            firstColumns = Arrays.copyOf(firstColumns, p);
            kinds = Arrays.copyOf(kinds, p);
            selections = Arrays.copyOf(selections, p);
        }
        int d = Math.max(keep, nodes);
        if (kids.length > 2 * d) {
            kids = Arrays.copyOf(kids, 2 * d);
            lines = Arrays.copyOf(lines, LINE * d);
            rows = Arrays.copyOf(rows, 2 * d);
            rowKids = Arrays.copyOf(rowKids, 2 * d);
        }
        int i = Math.max(keep, inputs.count());
        if (roots.length > i) {
            roots = Arrays.copyOf(roots, i);
            nodeCounts = Arrays.copyOf(nodeCounts, i);
        }
    }
}
