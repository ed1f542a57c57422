package dev.trisect.pipeline;

import dev.trisect.raster.RowKnots;

/**
 * What a {@link FrameRenderer} drew last, for the questions asked after the frame: which filled
 * triangle shows a pixel ({@link #pieceAt}), whose magenta outline marks it ({@link #fallbackOutlineAt}),
 * the knots of its row ({@link #knotsAt}), how many filled triangles cover each pixel
 * ({@link #coverage}). The pixel inspector, the golden frames and the overdraw tests ask these, one
 * query at a time, never per pixel.
 *
 * <p>The record holds the frame's size, its path's knot error and how many chunks of screen triangles
 * it drew; the triangles themselves stay in the renderer's storage, which the next frame reuses. So a
 * record answers until its renderer draws again (or is closed): after that every question throws
 * {@link IllegalStateException} rather than answer from another frame's triangles.
 */
public final class FrameRecord {
    private final FrameRenderer renderer;
    private final Chunks chunks;
    private final int chunkCount;
    private final int width;
    private final int height;
    private final double knotError;
    private final int[] probed;

    FrameRecord(FrameRenderer renderer, Chunks chunks, int chunkCount, int width, int height, double knotError,
                int[] probed) {
        this.probed = probed;
        this.renderer = renderer;
        this.chunks = chunks;
        this.chunkCount = chunkCount;
        this.width = width;
        this.height = height;
        this.knotError = knotError;
    }

    /** The frame's width, pixels. */
    public int width() {
        return width;
    }

    /** The frame's height, pixels. */
    public int height() {
        return height;
    }

    /**
     * The span path's knot error the frame was filled with (see
     * {@link dev.trisect.render.RenderSettings#knotError()}), screen pixels; 0 when the frame took
     * another path.
     */
    public double knotError() {
        return knotError;
    }

    /**
     * The filled triangle (tessellated piece) of this frame that shows pixel (x, y): among those of input
     * triangle {@code triangle} (the id in the UV output, numbered across the draws) whose area holds
     * the pixel centre, the one whose 1/w plane there is closest to {@code depth} (the frame's depth
     * buffer value). See {@link PieceLookup#find}.
     *
     * @return the piece, or null when none holds the pixel
     * @throws IllegalStateException when the renderer has drawn since, or is closed
     */
    public PieceInfo pieceAt(int x, int y, int triangle, double depth) {
        check();
        return PieceLookup.find(chunks, chunkCount, x, y, triangle, depth);
    }

    /**
     * The piece filled per pixel (the fallback: a sliver, or one a cap stopped short) whose outline
     * lights pixel (x, y) of this frame when the borders are drawn, by the overlay's own rules and depth
     * test against {@code depth} (the frame's 1/w there); the last in drawing order when several do.
     * It explains a magenta mark.
     *
     * @return the piece, or null when no fallback piece's outline lights the pixel
     * @throws IllegalStateException when the renderer has drawn since, or is closed
     */
    public PieceInfo fallbackOutlineAt(int x, int y, double depth) {
        check();
        return PieceLookup.fallbackOutline(chunks, chunkCount, x, y, height, depth);
    }

    /**
     * The knots of row y of the filled triangle that shows pixel (x, y), when this frame took the span
     * path: found as {@link #pieceAt} finds the triangle, placed as the fill placed them.
     *
     * @return the row's knots, or null when the frame did not take the span path or no triangle holds
     *         the pixel
     * @throws IllegalStateException when the renderer has drawn since, or is closed
     */
    public RowKnots knotsAt(int x, int y, int triangle, double depth) {
        check();
        if (knotError <= 0) {
            return null;
        }
        return PieceLookup.knots(chunks, chunkCount, x, y, triangle, depth, width, knotError);
    }

    /**
     * Counts, per pixel, how many of the frame's filled triangles (pieces, in the tessellated path)
     * cover its centre, ignoring depth: 1 everywhere inside a closed or tiled surface seen from one
     * side means no gaps and no overlaps. On the renderer's threads.
     *
     * @return {@code width * height} counts, row 0 at the top
     * @throws IllegalStateException when the renderer has drawn since, or is closed
     */
    public int[] coverage() {
        check();
        return renderer.coverage(chunks, chunkCount, width, height);
    }

    /**
     * The line segment or quad drawn last at the pixel {@link FrameRenderer#probe} named when the frame was
     * drawn (over the triangles there), found by the fill itself: {@code {Commands.LINE, line draw,
     * segment}} (the draw as {@link Draws#lines(int)} numbers it, the segment in its lines) or
     * {@code {Commands.QUAD, quad}} (the quad's index in {@link Draws#quads()}). Answers after the
     * renderer drew again too (it is a copy).
     *
     * @return a new array, or null when no line or quad wrote the pixel or none was probed
     */
    public int[] probed() {
        return probed == null ? null : probed.clone();
    }

    /** The chunks of screen triangles drawn, for the renderer's own passes over this frame. */
    int chunkCount() {
        return chunkCount;
    }

    private void check() {
        renderer.checkCurrent(this);
    }
}
