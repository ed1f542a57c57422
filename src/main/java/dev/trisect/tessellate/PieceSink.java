package dev.trisect.tessellate;

/**
 * Receives the pieces a {@link Tessellator} produces, in order.
 *
 * <p>Each vertex is {@link VertexLayout#PROJECTED_STRIDE} doubles in {@code vertices} starting at its
 * offset, at the offsets {@link VertexLayout} names: clip-space x, y, z, w; texel coordinates
 * s = u * width and t = v * height; screen-space x and y in pixels (see {@link dev.trisect.math.Viewport}).
 * The array is the tessellator's scratch: read the values during the call, do not keep it.
 *
 * <p>With each piece come its edges' links, the topology of the input triangle's pieces as the
 * splits made it: per edge (0: a-b, 1: b-c, 2: c-a), whether it lies on the input triangle's own
 * boundary ({@link #OUTER}: it may border a neighbouring input triangle, which the tessellator does
 * not see), or inside it, then either shared with a piece handed on earlier for the same input
 * triangle, the same two corners, or not ({@link #INNER}: the piece on its other side comes later and
 * links back to this one, or is never handed on: it lies off screen, or a cap left it bigger, so that
 * the two sides meet with different corners).
 */
@FunctionalInterface
public interface PieceSink {
    /** Link of an edge on the input triangle's own boundary. */
    int OUTER = -1;
    /** Link of an inner edge that no piece handed on earlier for the same input triangle shares. */
    int INNER = -2;

    /**
     * One piece, corners in the input triangle's winding order.
     *
     * @param level    the piece's split level: how many times its most-halved edge was halved (0 for
     *                 a triangle passed on whole), for the overlay's depth colouring
     * @param fallback true when a cap stopped the splitting while the piece still fails its policy,
     *                 or the piece is a sliver ({@link Slivers#SLIVER_PIXELS}): it must be filled
     *                 per pixel (perspective-correct), not affinely, so that the bound holds on it too
     * @param links    per edge: {@link #OUTER}, {@link #INNER}, or {@code 3 * back + edge} (&gt;= 3): the
     *                 edge is edge {@code edge} of the piece handed on {@code back} &gt;= 1 pieces before
     *                 this one, which has the same two corners. Scratch, like {@code vertices}
     */
    void piece(double[] vertices, int a, int b, int c, int level, boolean fallback, int[] links);
}
