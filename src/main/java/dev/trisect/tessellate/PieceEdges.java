package dev.trisect.tessellate;

import java.util.Arrays;

/**
 * The edges of one input triangle's pieces while a {@link Tessellator} splits it, each segment once:
 * its two end vertices, whether it lies on the input triangle's own boundary, its cut point and two
 * halves once it is split, and the first piece handed on that has it as an edge. That is the
 * topology {@link PieceSink#piece} reports with each piece, known from the splits themselves, not
 * found by comparing positions: a split of a piece's edge creates one inner edge (cut point to the
 * opposite corner), which the two children share; its other two edges pass to the children whole,
 * and the split edge passes on as its two halves.
 *
 * <p>Whether an edge is split depends on the edge alone, so the piece on its other side splits it
 * too, later: it then takes the cut point and halves recorded here (the same vertex, which it would
 * have computed bit for bit alike) instead of cutting again. Each segment thus borders at most one
 * piece on each side, and two pieces share an edge exactly when they hand on the same segment. Where
 * a cap stops one side short of a split the other side made, the halves and the whole are different
 * segments and nothing is shared, as no two of their pieces have the same two corners.
 *
 * <p>Inner edges are numbered from 0 in the order they are made, per input triangle ({@link #clear});
 * an edge on the input triangle's boundary, and each of its halves, is {@link #OUTER}: no other
 * piece of the triangle can share it, and only one piece splits it.
 */
final class PieceEdges {
    /** The number of an edge on the input triangle's own boundary: it has no record, being a piece's on one side only. */
    static final int OUTER = -1;
    /** Ints per edge: end a, cut vertex (or -1), the first of its two halves (from a; the other follows), first link (or -1). */
    private static final int STRIDE = 4;
    private static final int A = 0;
    private static final int CUT = 1;
    private static final int HALF = 2;
    private static final int FIRST = 3;

    private int[] edges = new int[STRIDE * 256];
    private int count;

    /** Forgets every edge, for the next input triangle. */
    void clear() {
        count = 0;
    }

    /**
     * A new inner edge from vertex {@code a} (an offset in the tessellator's vertices) to another.
     *
     * @return its number
     */
    int add(int a) {
        int o = count * STRIDE;
        if (o + STRIDE > edges.length) {
            edges = Arrays.copyOf(edges, edges.length * 2);
        }
        int[] e = edges;
        e[o + A] = a;
        e[o + CUT] = -1;
        e[o + FIRST] = -1;
        return count++;
    }

    /** The vertex edge {@code id} was cut at, or -1 while it is whole. */
    int cut(int id) {
        return edges[id * STRIDE + CUT];
    }

    /** Records that edge {@code id} is cut at vertex {@code m}: its two halves become edges of their own. */
    void split(int id, int m) {
        int o = id * STRIDE;
        int halfA = add(edges[o + A]);
        add(m);
        // add may have grown the array.
        int[] e = edges;
        e[o + CUT] = m;
        e[o + HALF] = halfA;
    }

    /** The half of split edge {@code id} that ends at vertex {@code v}, one of its two ends. */
    int halfAt(int id, int v) {
        int o = id * STRIDE;
        int half = edges[o + HALF];
        return edges[o + A] == v ? half : half + 1;
    }

    /**
     * The link of edge {@code k} (0..2) of the {@code piece}-th piece handed on (counted from 0 for
     * the input triangle), which lies on edge {@code id} (or {@link #OUTER}): see {@link
     * PieceSink#piece}. The first piece to ask about an inner edge gets {@link PieceSink#INNER} and is
     * remembered; the second, on its other side, gets that piece.
     */
    int link(int id, int piece, int k) {
        if (id < 0) {
            return PieceSink.OUTER;
        }
        int o = id * STRIDE + FIRST;
        int[] e = edges;
        int first = e[o];
        if (first < 0) {
            e[o] = 3 * piece + k;
            return PieceSink.INNER;
        }
        return 3 * (piece - first / 3) + first % 3;
    }
}
