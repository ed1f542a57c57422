package dev.trisect.tessellate;

/**
 * Receives the pieces a {@link Tessellator} produces, in order.
 *
 * <p>Each vertex is {@link VertexLayout#PROJECTED_STRIDE} doubles in {@code vertices} starting at its
 * offset, at the offsets {@link VertexLayout} names: clip-space x, y, z, w; texel coordinates
 * s = u * width and t = v * height; screen-space x and y in pixels (see {@link dev.trisect.math.Viewport}).
 * The array is the tessellator's scratch: read the values during the call, do not keep it.
 */
@FunctionalInterface
public interface PieceSink {
    /**
     * One piece, corners in the input triangle's winding order.
     *
     * @param level    the piece's split level: how many times its most-halved edge was halved (0 for
     *                 a triangle passed on whole), for the overlay's depth colouring
     * @param fallback true when a cap stopped the splitting while the piece still fails its policy,
     *                 or the piece is a sliver ({@link Tessellator#SLIVER_PIXELS}): it must be filled
     *                 per pixel (perspective-correct), not affinely, so that the bound holds on it too
     */
    void piece(double[] vertices, int a, int b, int c, int level, boolean fallback);
}
