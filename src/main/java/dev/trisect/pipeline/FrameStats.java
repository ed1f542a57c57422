package dev.trisect.pipeline;

import dev.trisect.base.JsonObject;

/**
 * What one frame did. Times are wall-clock nanoseconds per stage.
 *
 * @param trianglesIn      input triangles
 * @param culledBackFace   dropped as seen from behind
 * @param culledFrustum    dropped as wholly outside the view volume (or clipped away entirely)
 * @param culledDegenerate dropped for having no area
 * @param skippedInvalid   skipped for NaN or infinite coordinates
 * @param clipped          cut by the near, far or guard-band planes
 * @param pieces           triangles filled (tessellated pieces, or clipped triangles in the other paths)
 * @param piecesOffScreen  tessellated pieces dropped unsplit for lying wholly outside the viewport
 * @param splits           edge cuts made
 * @param deepestSplit     highest edge level reached (times an input edge was halved)
 * @param capsReached      input triangles whose splitting a depth or piece cap stopped short
 * @param piecesFallback   pieces filled per pixel instead of affinely (included in {@code pieces}): those
 *                         a cap stopped short of their split policy, and slivers thinner than 1/16 px
 * @param pieceBudget      the frame's piece budget (0 outside the tessellated path)
 * @param budgetDepth      the edge level cap the budget forced on the frame (its pieces beyond that
 *                         cap are among the fallback pieces), or -1 when the frame fit its budget
 * @param pixelsWritten    pixels that passed the depth test
 * @param threads          threads that filled the frame
 * @param transformNanos   vertex transform
 * @param clipNanos        culling and clipping
 * @param tessellateNanos  splitting and projection to screen triangles
 * @param rasterNanos      clearing and filling
 * @param overlayNanos     border overlay (0 when off)
 * @param totalNanos       the whole frame
 */
public record FrameStats(long trianglesIn, long culledBackFace, long culledFrustum, long culledDegenerate,
                         long skippedInvalid, long clipped, long pieces, long piecesOffScreen, long splits,
                         int deepestSplit, long capsReached, long piecesFallback, long pieceBudget,
                         int budgetDepth, long pixelsWritten, int threads,
                         long transformNanos, long clipNanos, long tessellateNanos, long rasterNanos,
                         long overlayNanos, long totalNanos) {

    /** Whether the frame's pieces exceeded its budget, so that its depth cap was lowered. */
    public boolean budgetReached() {
        return budgetDepth >= 0;
    }

    /** All culled triangles. */
    public long culled() {
        return culledBackFace + culledFrustum + culledDegenerate;
    }

    /** The statistics as a JSON object: snake_case keys in this order, times in milliseconds. */
    public JsonObject json() {
        return new JsonObject()
                .put("triangles_in", trianglesIn)
                .put("culled", culled())
                .put("culled_back_face", culledBackFace)
                .put("culled_frustum", culledFrustum)
                .put("culled_degenerate", culledDegenerate)
                .put("skipped_invalid", skippedInvalid)
                .put("clipped", clipped)
                .put("pieces", pieces)
                .put("pieces_off_screen", piecesOffScreen)
                .put("splits", splits)
                .put("deepest_split", deepestSplit)
                .put("caps_reached", capsReached)
                .put("pieces_fallback", piecesFallback)
                .put("piece_budget", pieceBudget)
                .put("budget_reached", budgetReached())
                .put("budget_depth", budgetDepth)
                .put("pixels_written", pixelsWritten)
                .put("threads", threads)
                .put("ms", new JsonObject()
                        .put("transform", transformNanos / 1e6, 3)
                        .put("clip", clipNanos / 1e6, 3)
                        .put("tessellate", tessellateNanos / 1e6, 3)
                        .put("raster", rasterNanos / 1e6, 3)
                        .put("overlay", overlayNanos / 1e6, 3)
                        .put("total", totalNanos / 1e6, 3));
    }

    /** {@link #json()} as one line. */
    public String toJson() {
        return json().toString();
    }
}
