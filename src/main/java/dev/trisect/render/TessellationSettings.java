package dev.trisect.render;

/**
 * How the tessellated path splits triangles.
 *
 * @param policy    which measure decides a split
 * @param maxEdge   for {@link SplitPolicy#EDGE}: the longest edge allowed, screen pixels, &gt; 0
 * @param maxError  for {@link SplitPolicy#ERROR}, and for the knots of {@link RenderMode#SPANS}: the
 *                  largest affine displacement allowed, screen pixels, &gt; 0
 * @param maxDepth  how many times an edge of an input triangle may be halved (its level); an edge
 *                  at this level is never split again, 0..30. Capping per edge rather than per
 *                  piece keeps the cap crack-free: both triangles sharing an edge see the same level.
 * @param maxPieces the most pieces one input triangle may become, &gt;= 1; when reached, the pieces
 *                  left are filled as they are and the cap is counted
 * @param splitPoint where an edge is cut
 * @param maxFramePieces the most pieces a whole frame may have, &gt;= 1, or {@link #AUTO_FRAME_PIECES} for
 *                  one per input triangle plus one per {@link #PIXELS_PER_PIECE} pixels of the frame; a
 *                  frame that would have more is redone with a lower depth cap (see {@link #framePieceBudget})
 */
public record TessellationSettings(SplitPolicy policy, double maxEdge, double maxError, int maxDepth, int maxPieces,
                                   SplitPoint splitPoint, int maxFramePieces) {

    /** Default longest edge, pixels. */
    public static final double DEFAULT_MAX_EDGE = 32;
    /** Default largest displacement, pixels. */
    public static final double DEFAULT_MAX_ERROR = 0.5;
    /** Default edge level cap. */
    public static final int DEFAULT_MAX_DEPTH = 16;
    /** Default piece cap per input triangle. */
    public static final int DEFAULT_MAX_PIECES = 1 << 16;

    /** Default split point: the screen midpoint, which converges (see {@link SplitPoint#SCREEN}). */
    public static final SplitPoint DEFAULT_SPLIT_POINT = SplitPoint.SCREEN;

    /** {@code maxFramePieces} value meaning "scale the frame's piece budget with its pixel count". */
    public static final int AUTO_FRAME_PIECES = 0;
    /**
     * Pixels per piece of the default frame budget. Below about 16 pixels a piece costs more to cut,
     * set up and bin (a few hundred nanoseconds) than filling its pixels per pixel would, so a frame
     * that wants more pieces than this is better served by the per-pixel fallback; and at this
     * density the pieces' storage (about 200 bytes each) stays near 13 bytes per pixel.
     */
    public static final int PIXELS_PER_PIECE = 16;

    /**
     * Checks every value against the ranges above; the message names the one out of range.
     *
     * @param policy         which measure decides a split
     * @param maxEdge        longest edge allowed, screen pixels
     * @param maxError       largest displacement allowed, screen pixels
     * @param maxDepth       edge level cap, 0..30
     * @param maxPieces      piece cap per input triangle
     * @param splitPoint     where an edge is cut
     * @param maxFramePieces piece budget of a frame, or {@link #AUTO_FRAME_PIECES}
     * @throws IllegalArgumentException for a value out of range or a missing policy or split point
     */
    public TessellationSettings {
        if (policy == null) {
            throw new IllegalArgumentException("split policy is missing");
        }
        if (splitPoint == null) {
            throw new IllegalArgumentException("split point is missing");
        }
        if (!(maxEdge > 0) || Double.isInfinite(maxEdge)) {
            throw new IllegalArgumentException("max edge must be a positive number of pixels, got " + maxEdge);
        }
        if (!(maxError > 0) || Double.isInfinite(maxError)) {
            throw new IllegalArgumentException("max error must be a positive number of pixels, got " + maxError);
        }
        if (maxDepth < 0 || maxDepth > 30) {
            throw new IllegalArgumentException("max depth must be in 0..30, got " + maxDepth);
        }
        if (maxPieces < 1) {
            throw new IllegalArgumentException("max pieces must be at least 1, got " + maxPieces);
        }
        if (maxFramePieces < 0) {
            throw new IllegalArgumentException("max frame pieces must be at least 1 (or 0 for automatic), got "
                    + maxFramePieces);
        }
    }

    /**
     * The piece budget of a frame of {@code pixels} pixels drawing {@code triangles} input triangles:
     * {@code maxFramePieces}, or when automatic {@code triangles + pixels / PIXELS_PER_PIECE} — one
     * piece per triangle, which no frame can do with less, plus the pieces the frame's size is worth.
     *
     * @param pixels    the frame's pixel count
     * @param triangles the frame's input triangles
     * @return the most pieces the frame may have
     */
    public long framePieceBudget(long pixels, long triangles) {
        return maxFramePieces != AUTO_FRAME_PIECES ? maxFramePieces : triangles + Math.max(1, pixels / PIXELS_PER_PIECE);
    }

    /**
     * The defaults: edge policy, 32 px, 0.5 px, depth 16, 65536 pieces, cut at the screen midpoint,
     * automatic frame budget.
     *
     * @return the default settings
     */
    public static TessellationSettings defaults() {
        return new TessellationSettings(SplitPolicy.EDGE, DEFAULT_MAX_EDGE, DEFAULT_MAX_ERROR,
                DEFAULT_MAX_DEPTH, DEFAULT_MAX_PIECES, DEFAULT_SPLIT_POINT, AUTO_FRAME_PIECES);
    }

    /**
     * A copy with another policy.
     *
     * @param p the split policy
     * @return a copy with that policy
     */
    public TessellationSettings withPolicy(SplitPolicy p) {
        return new TessellationSettings(p, maxEdge, maxError, maxDepth, maxPieces, splitPoint, maxFramePieces);
    }

    /**
     * A copy with another max edge.
     *
     * @param px the longest edge, screen pixels
     * @return a copy with that max edge
     */
    public TessellationSettings withMaxEdge(double px) {
        return new TessellationSettings(policy, px, maxError, maxDepth, maxPieces, splitPoint, maxFramePieces);
    }

    /**
     * A copy with another max error.
     *
     * @param px the largest displacement, screen pixels
     * @return a copy with that max error
     */
    public TessellationSettings withMaxError(double px) {
        return new TessellationSettings(policy, maxEdge, px, maxDepth, maxPieces, splitPoint, maxFramePieces);
    }

    /**
     * A copy with another depth cap.
     *
     * @param depth the edge level cap
     * @return a copy with that cap
     */
    public TessellationSettings withMaxDepth(int depth) {
        return new TessellationSettings(policy, maxEdge, maxError, depth, maxPieces, splitPoint, maxFramePieces);
    }

    /**
     * A copy with another piece cap.
     *
     * @param pieces the piece cap per input triangle
     * @return a copy with that cap
     */
    public TessellationSettings withMaxPieces(int pieces) {
        return new TessellationSettings(policy, maxEdge, maxError, maxDepth, pieces, splitPoint, maxFramePieces);
    }

    /**
     * A copy with another split point.
     *
     * @param point where an edge is cut
     * @return a copy with that split point
     */
    public TessellationSettings withSplitPoint(SplitPoint point) {
        return new TessellationSettings(policy, maxEdge, maxError, maxDepth, maxPieces, point, maxFramePieces);
    }

    /**
     * A copy with another frame piece budget ({@link #AUTO_FRAME_PIECES} for automatic).
     *
     * @param pieces the frame's piece budget, or {@link #AUTO_FRAME_PIECES}
     * @return a copy with that budget
     */
    public TessellationSettings withMaxFramePieces(int pieces) {
        return new TessellationSettings(policy, maxEdge, maxError, maxDepth, maxPieces, splitPoint, pieces);
    }
}
