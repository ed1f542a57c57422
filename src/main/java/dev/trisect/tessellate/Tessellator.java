package dev.trisect.tessellate;

import dev.trisect.math.Viewport;
import dev.trisect.render.SplitPoint;
import dev.trisect.render.TessellationSettings;
import java.util.Arrays;

/**
 * Splits one triangle, one edge at a time at its {@link SplitPoint}, until every edge passes the split
 * policy, and hands the pieces to a {@link PieceSink} to be filled affinely.
 *
 * <p>Why this leaves no cracks: whether an edge is split depends only on that edge — its two
 * endpoints and its level (how many times it has been halved) — and the cut point is
 * {@code (a * ka + b * kb) / (ka + kb)} with {@code ka} a function of b's depth and {@code kb} the
 * same function of a's, which is the same expression bit for bit when a and b trade places (IEEE
 * addition and multiplication are commutative). Two triangles that share an edge therefore cut it at
 * the same points, bit for bit, and the pieces meet without T-junctions. The
 * depth cap is a cap on edge levels for the same reason. Only the per-triangle piece cap, a guard
 * against enormous or degenerate input, can leave a split undone on one side of an edge; reaching it
 * is counted.
 *
 * <p>A piece that still fails the policy when a cap stops its splitting, or that is a sliver thinner
 * than {@link #SLIVER_PIXELS}, is handed on flagged as a fallback, to be filled per pixel: same
 * corners, same coverage, so no new crack, and no pixel of it is displaced more than the per-pixel
 * path's rounding.
 *
 * <p>Each piece is handed on with its edges' links ({@link PieceSink}): which inner edges it shares
 * with a piece handed on before it, from the splits that made them ({@link PieceEdges}), so that no
 * later stage has to find shared edges by their positions.
 *
 * <p>The corners and cut points live in a {@link SplitVertices} pool, which also measures edges and
 * pieces for the policy. The recursion runs on an explicit stack in primitive arrays, so no input can overflow the Java
 * stack, and nothing is allocated per triangle once the scratch arrays have grown to their working
 * size. One instance per thread.
 */
public final class Tessellator {
    /**
     * Ints per stacked piece: three vertex offsets, the levels of edges v0-v1, v1-v2, v2-v0, those
     * edges' numbers in {@link #edges}, and where its reference goes in the split tree (the slot of its
     * parent's {@link SplitTree#kids()}, or -1 for the root).
     */
    private static final int PIECE = 10;

    /** The current input triangle's corners and cut points. */
    private final SplitVertices vertices = new SplitVertices();
    private int[] stack = new int[PIECE * 64];
    /** The split tree of the last triangle split. */
    private final SplitTree tree = new SplitTree();
    /** The edges of the current input triangle's pieces, for the links handed on with each piece. */
    private final PieceEdges edges = new PieceEdges();
    /** The links handed on with a piece (scratch). */
    private final int[] links = new int[3];
    /** Whether pieces are handed on with their links (else every link is {@link PieceSink#OUTER}). */
    private boolean linking = true;

    private TessellationSettings settings = TessellationSettings.defaults();
    /** The frame's shared piece budget, or null for none. */
    private PieceBudget budget;
    private boolean errorPolicy;
    private double threshold;

    private long splits;
    private long pieces;
    private long culledOffScreen;
    private int deepestLevel;
    private int capsReached;
    private long fallbackPieces;

    /** Sets the frame's viewport and split settings for the triangles that follow. */
    public void configure(Viewport viewport, TessellationSettings settings) {
        vertices.configure(viewport, settings.splitPoint());
        this.settings = settings;
        this.errorPolicy = settings.policy().measuresError();
        double px = settings.policy().threshold(settings);
        // The edge policy compares squared lengths, sparing a square root per edge.
        this.threshold = errorPolicy ? px : px * px;
    }

    /** Sets the layout of the vertices that follow ({@link VertexLayout#TEXTURED} until set). */
    public void layout(VertexLayout vertexLayout) {
        vertices.layout(vertexLayout);
    }

    /**
     * Sets the frame-wide piece budget the split triangles that follow draw on, shared with the
     * other threads' tessellators; null for none. When it is exceeded, {@link #process} returns
     * without finishing (or starting) its triangle: the frame must be redone with a lower depth cap.
     */
    public void budget(PieceBudget frameBudget) {
        this.budget = frameBudget;
    }

    /**
     * Whether the pieces that follow are handed on with the links of their inner edges (the default),
     * or with every link {@link PieceSink#OUTER}, which spares the bookkeeping when nothing reads them.
     * The pieces are the same either way.
     */
    public void links(boolean on) {
        this.linking = on;
    }

    /** Clears the counters. */
    public void resetStatistics() {
        splits = 0;
        pieces = 0;
        culledOffScreen = 0;
        deepestLevel = 0;
        capsReached = 0;
        fallbackPieces = 0;
    }

    /** Splits made since the last reset. */
    public long splits() {
        return splits;
    }

    /** Pieces emitted since the last reset. */
    public long pieces() {
        return pieces;
    }

    /** Pieces dropped since the last reset for lying wholly outside the viewport. */
    public long culledOffScreen() {
        return culledOffScreen;
    }

    /** The highest edge level among emitted pieces since the last reset: the deepest split. */
    public int deepestLevel() {
        return deepestLevel;
    }

    /**
     * Pieces emitted since the last reset flagged to be filled per pixel: a cap stopped them while
     * they still failed the policy, or they are slivers (see {@link #SLIVER_PIXELS}).
     */
    public long fallbackPieces() {
        return fallbackPieces;
    }

    /** Input triangles since the last reset whose splitting a cap stopped short. */
    public int capsReached() {
        return capsReached;
    }

    /**
     * The vertices of the last triangle processed, in the {@link #layout} set ({@link
     * VertexLayout#projectedStride()} doubles each): its three corners, screen positions included, at
     * offsets 0, {@code projectedStride} and {@code 2 * projectedStride}. Scratch: read it before the
     * next {@link #process}.
     */
    public double[] vertices() {
        return vertices.array();
    }

    /** The split tree of the last triangle processed (see {@link SplitTree}); scratch, like {@link #vertices()}. */
    public SplitTree splitTree() {
        return tree;
    }

    /**
     * Processes one triangle.
     *
     * @param input  input vertices, {@link VertexLayout#clipStride()} doubles each in the {@link #layout} set
     *               (clip x, y, z, w with w &gt; 0, texel s, t, further varyings)
     * @param i0     offset of the first corner in {@code input}
     * @param i1     offset of the second corner
     * @param i2     offset of the third corner
     * @param split  false to emit the triangle whole (the perspective and affine paths)
     * @param sink   receives the pieces
     */
    public void process(double[] input, int i0, int i1, int i2, boolean split, PieceSink sink) {
        SplitVertices pool = vertices;
        pool.clear();
        tree.clear();
        int a = pool.load(input, i0);
        int b = pool.load(input, i1);
        int c = pool.load(input, i2);
        int[] link = links;
        link[0] = PieceSink.OUTER;
        link[1] = PieceSink.OUTER;
        link[2] = PieceSink.OUTER;
        if (!split) {
            pieces++;
            tree.leaf(-1);
            sink.piece(pool.array(), a, b, c, 0, false, link);
            return;
        }
        long allowance = Long.MAX_VALUE;
        if (budget != null) {
            if (budget.exceeded()) {
                return;
            }
            allowance = budget.allowance();
        }
        PieceEdges pe = edges;
        pe.clear();
        boolean tracking = linking;
        int outer = PieceEdges.OUTER;
        int top = push(0, a, b, c, 0, 0, 0, outer, outer, outer, -1);
        int handedOn = 0;
        int maxSplits = settings.maxPieces() - 1;
        int maxLevel = settings.maxDepth();
        int splitsHere = 0;
        boolean capped = false;
        while (top > 0) {
            int[] st = stack;
            int p = (--top) * PIECE;
            int v0 = st[p];
            int v1 = st[p + 1];
            int v2 = st[p + 2];
            int l0 = st[p + 3];
            int l1 = st[p + 4];
            int l2 = st[p + 5];
            int e0 = st[p + 6];
            int e1 = st[p + 7];
            int e2 = st[p + 8];
            int slot = st[p + 9];
            if (pool.offScreen(v0, v1, v2)) {
                // Nothing of it can be seen, so it is neither split nor filled. Its edges lie off
                // screen too, so a neighbour that does split a shared edge cannot open a visible crack.
                culledOffScreen++;
                tree.refer(slot, SplitTree.NO_PIECE);
                continue;
            }
            boolean error = errorPolicy;
            double m0 = pool.measure(v0, v1, error);
            double m1 = pool.measure(v1, v2, error);
            double m2 = pool.measure(v2, v0, error);
            // Pick the failing edge with the largest measure among those still allowed to split.
            int edge = -1;
            double worst = threshold;
            boolean atCap = false;
            if (m0 > worst) {
                if (l0 < maxLevel) {
                    edge = 0;
                    worst = m0;
                } else {
                    atCap = true;
                }
            }
            if (m1 > threshold) {
                if (l1 < maxLevel) {
                    if (m1 > worst) {
                        edge = 1;
                        worst = m1;
                    }
                } else {
                    atCap = true;
                }
            }
            if (m2 > threshold) {
                if (l2 < maxLevel) {
                    if (m2 > worst) {
                        edge = 2;
                    }
                } else {
                    atCap = true;
                }
            }
            if (edge >= 0 && splitsHere >= maxSplits) {
                atCap = true;
                edge = -1;
            }
            if (edge < 0) {
                pieces++;
                int level = Math.max(l0, Math.max(l1, l2));
                if (level > deepestLevel) {
                    deepestLevel = level;
                }
                // Here every edge passes or a cap forbids splitting it: a failing edge means a cap
                // stopped this piece short, and the per-pixel filler takes it.
                if (atCap) {
                    capped = true;
                }
                boolean perPixel = atCap || pool.thin(v0, v1, v2);
                if (perPixel) {
                    fallbackPieces++;
                }
                if (tracking) {
                    link[0] = pe.link(e0, handedOn, 0);
                    link[1] = pe.link(e1, handedOn, 1);
                    link[2] = pe.link(e2, handedOn, 2);
                    handedOn++;
                }
                tree.leaf(slot);
                sink.piece(pool.array(), v0, v1, v2, level, perPixel, link);
                continue;
            }
            if (splitsHere + 2L > allowance) {
                // This triangle alone would take the frame past its budget.
                budget.exceed();
                return;
            }
            splitsHere++;
            splits++;
            // Rotate so that the split edge runs p -> q with r opposite, keeping the winding.
            int vp = v0, vq = v1, vr = v2, lpq = l0, lqr = l1, lrp = l2, epq = e0, eqr = e1, erp = e2;
            if (edge == 1) {
                vp = v1; vq = v2; vr = v0; lpq = l1; lqr = l2; lrp = l0; epq = e1; eqr = e2; erp = e0;
            } else if (edge == 2) {
                vp = v2; vq = v0; vr = v1; lpq = l2; lqr = l0; lrp = l1; epq = e2; eqr = e0; erp = e1;
            }
            // The piece on the edge's other side may have cut it already: the same point (the cut is
            // symmetric in p and q bit for bit), so take that vertex and its halves.
            int m;
            int halfP = PieceEdges.OUTER;
            int halfQ = PieceEdges.OUTER;
            if (epq == PieceEdges.OUTER) {
                // On the input triangle's boundary, or links are off: nothing to take or record.
                m = pool.cut(vp, vq);
            } else {
                m = pe.cut(epq);
                if (m < 0) {
                    m = pool.cut(vp, vq);
                    pe.split(epq, m);
                }
                halfP = pe.halfAt(epq, vp);
                halfQ = pe.halfAt(epq, vq);
            }
            int inner = tracking ? pe.add(m) : PieceEdges.OUTER;
            int half = lpq + 1;
            int screenX = pool.screenX();
            int pSlot = tree.split(pool.array(), slot, m + screenX, vr + screenX, vp + screenX);
            // The new inner edge m-r also gets level lpq + 1: every split then lowers the sum of
            // 2^(maxLevel - level) over a piece's edges, so splitting ends even without the piece cap.
            top = push(top, m, vq, vr, half, lqr, half, halfQ, eqr, inner, pSlot ^ 1);
            top = push(top, vp, m, vr, half, half, lrp, halfP, inner, erp, pSlot);
        }
        tree.complete(true);
        if (capped) {
            capsReached++;
        }
        if (budget != null) {
            budget.charge(splitsHere + 1L);
        }
    }

    private int push(int top, int v0, int v1, int v2, int l0, int l1, int l2, int e0, int e1, int e2, int slot) {
        int p = top * PIECE;
        if (p + PIECE > stack.length) {
            stack = Arrays.copyOf(stack, stack.length * 2);
        }
        int[] st = stack;
        st[p] = v0;
        st[p + 1] = v1;
        st[p + 2] = v2;
        st[p + 3] = l0;
        st[p + 4] = l1;
        st[p + 5] = l2;
        st[p + 6] = e0;
        st[p + 7] = e1;
        st[p + 8] = e2;
        st[p + 9] = slot;
        return top + 1;
    }
}
