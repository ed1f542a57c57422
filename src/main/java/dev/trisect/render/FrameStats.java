package dev.trisect.render;

import dev.trisect.base.internal.Counts;
import dev.trisect.base.internal.JsonObject;

/**
 * What one frame did. Times are wall-clock nanoseconds. The transform and the whole frame are
 * measured; clipping and tessellation run interleaved on all threads, so the geometry stage's wall
 * time is shared between them in proportion to the time the threads spent on each. With the borders
 * on or lines or quads drawn, filling, outlining and drawing lines and quads also run interleaved
 * (each band is outlined and its lines and quads drawn right after it is filled), so {@code rasterNanos} and {@code overlayNanos} are
 * then an estimate of the same kind, flagged by {@code bandTimesEstimated} and named
 * {@code ..._estimate} in {@link #toJson()}; without borders and lines the raster time is the measured
 * wall time of the fill and the overlay's is 0. (The developer tools
 * time the overlay exactly by drawing it as a pass of its own after a frame drawn without borders; the
 * API offers no such pass.)
 *
 * @param trianglesIn      input triangles
 * @param culledBackFace   dropped as seen from behind
 * @param culledFrustum    dropped as wholly outside the view volume (or clipped away entirely)
 * @param culledDegenerate dropped for having no area
 * @param skippedInvalid   skipped for NaN or infinite coordinates, or for corners so far from the part of
 *                         the triangle in view that double precision cannot clip it (see
 *                         docs/reading-limits.md)
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
 * @param rasterNanos      clearing and filling: measured without borders and lines, else an estimate
 *                         (its share of the band pass's wall time)
 * @param overlayNanos     border overlay, 0 when off; when on, an estimate: the band pass's wall time
 *                         shared out in proportion to the threads' time preparing the chunks' outlines
 *                         and outlining bands, over that and their time clearing and filling (the time
 *                         a band waits for the preparations is in neither)
 * @param bandTimesEstimated whether {@code rasterNanos} and {@code overlayNanos} are that estimate
 *                         (borders on or lines drawn) rather than measured
 * @param totalNanos       the whole frame
 * @param segmentsIn       line segments of the frame's line draws
 * @param segmentsDrawn    of those, the ones set up to draw: what clipping left, with length on screen
 * @param linePixels       pixels the lines wrote (depth test passed); not in {@code pixelsWritten}
 * @param lineNanos        the lines: their set-up before the fill, measured, and their share of the
 *                         band pass's wall time (an estimate, as the overlay's); 0 without lines
 * @param billboards       billboards in the frame (each a screen-aligned quad), before clipping to the screen
 * @param glyphs           glyphs of labels and screen text in the frame, likewise
 * @param quadPixels       pixels the billboards, glyphs and text backdrops wrote (or blended); not in
 *                         {@code pixelsWritten}
 * @param quadNanos        the quads: their set-up before the fill, measured, and their share of the
 *                         band pass's wall time (an estimate, as the lines'); 0 without quads
 */
public record FrameStats(long trianglesIn, long culledBackFace, long culledFrustum, long culledDegenerate,
                         long skippedInvalid, long clipped, long pieces, long piecesOffScreen, long splits,
                         int deepestSplit, long capsReached, long piecesFallback, long pieceBudget,
                         int budgetDepth, long pixelsWritten, int threads,
                         long transformNanos, long clipNanos, long tessellateNanos, long rasterNanos,
                         long overlayNanos, boolean bandTimesEstimated, long totalNanos, long segmentsIn,
                         long segmentsDrawn, long linePixels, long lineNanos, long billboards, long glyphs,
                         long quadPixels, long quadNanos) {

    /**
     * The statistics of a frame without billboards or text.
     *
     * @param trianglesIn        input triangles
     * @param culledBackFace     dropped as seen from behind
     * @param culledFrustum      dropped as outside the view volume
     * @param culledDegenerate   dropped for having no area
     * @param skippedInvalid     skipped for invalid coordinates
     * @param clipped            cut by a plane
     * @param pieces             triangles filled
     * @param piecesOffScreen    pieces dropped off screen
     * @param splits             edge cuts made
     * @param deepestSplit       highest edge level reached
     * @param capsReached        input triangles a cap stopped short
     * @param piecesFallback     pieces filled per pixel
     * @param pieceBudget        the frame's piece budget
     * @param budgetDepth        the depth cap the budget forced, or -1
     * @param pixelsWritten      pixels that passed the depth test
     * @param threads            threads that filled the frame
     * @param transformNanos     vertex transform
     * @param clipNanos          culling and clipping
     * @param tessellateNanos    splitting and projection
     * @param rasterNanos        clearing and filling
     * @param overlayNanos       border overlay
     * @param bandTimesEstimated whether the band times are estimates
     * @param totalNanos         the whole frame
     * @param segmentsIn         line segments given
     * @param segmentsDrawn      line segments set up to draw
     * @param linePixels         pixels the lines wrote
     * @param lineNanos          the line pass
     */
    public FrameStats(long trianglesIn, long culledBackFace, long culledFrustum, long culledDegenerate,
                      long skippedInvalid, long clipped, long pieces, long piecesOffScreen, long splits,
                      int deepestSplit, long capsReached, long piecesFallback, long pieceBudget,
                      int budgetDepth, long pixelsWritten, int threads,
                      long transformNanos, long clipNanos, long tessellateNanos, long rasterNanos,
                      long overlayNanos, boolean bandTimesEstimated, long totalNanos, long segmentsIn,
                      long segmentsDrawn, long linePixels, long lineNanos) {
        this(trianglesIn, culledBackFace, culledFrustum, culledDegenerate, skippedInvalid, clipped, pieces,
                piecesOffScreen, splits, deepestSplit, capsReached, piecesFallback, pieceBudget, budgetDepth,
                pixelsWritten, threads, transformNanos, clipNanos, tessellateNanos, rasterNanos, overlayNanos,
                bandTimesEstimated, totalNanos, segmentsIn, segmentsDrawn, linePixels, lineNanos, 0, 0, 0, 0);
    }

    /**
     * The statistics of a frame without lines.
     *
     * @param trianglesIn        input triangles
     * @param culledBackFace     dropped as seen from behind
     * @param culledFrustum      dropped as outside the view volume
     * @param culledDegenerate   dropped for having no area
     * @param skippedInvalid     skipped for invalid coordinates
     * @param clipped            cut by a plane
     * @param pieces             triangles filled
     * @param piecesOffScreen    pieces dropped off screen
     * @param splits             edge cuts made
     * @param deepestSplit       highest edge level reached
     * @param capsReached        input triangles a cap stopped short
     * @param piecesFallback     pieces filled per pixel
     * @param pieceBudget        the frame's piece budget
     * @param budgetDepth        the depth cap the budget forced, or -1
     * @param pixelsWritten      pixels that passed the depth test
     * @param threads            threads that filled the frame
     * @param transformNanos     vertex transform
     * @param clipNanos          culling and clipping
     * @param tessellateNanos    splitting and projection
     * @param rasterNanos        clearing and filling
     * @param overlayNanos       border overlay
     * @param bandTimesEstimated whether the band times are estimates
     * @param totalNanos         the whole frame
     */
    public FrameStats(long trianglesIn, long culledBackFace, long culledFrustum, long culledDegenerate,
                      long skippedInvalid, long clipped, long pieces, long piecesOffScreen, long splits,
                      int deepestSplit, long capsReached, long piecesFallback, long pieceBudget,
                      int budgetDepth, long pixelsWritten, int threads,
                      long transformNanos, long clipNanos, long tessellateNanos, long rasterNanos,
                      long overlayNanos, boolean bandTimesEstimated, long totalNanos) {
        this(trianglesIn, culledBackFace, culledFrustum, culledDegenerate, skippedInvalid, clipped, pieces,
                piecesOffScreen, splits, deepestSplit, capsReached, piecesFallback, pieceBudget, budgetDepth,
                pixelsWritten, threads, transformNanos, clipNanos, tessellateNanos, rasterNanos, overlayNanos,
                bandTimesEstimated, totalNanos, 0, 0, 0, 0, 0, 0, 0, 0);
    }

    /**
     * Whether the frame's pieces exceeded its budget, so that its depth cap was lowered.
     *
     * @return true when the budget lowered the depth cap
     */
    public boolean budgetReached() {
        return budgetDepth >= 0;
    }

    /**
     * What to tell the user when the frame skipped triangles it could not place ({@code skippedInvalid}
     * above 0): the line the command line notes on standard error and the view shows as its warning, so
     * that geometry never vanishes silently.
     *
     * @return e.g. "2 of 12 triangles skipped: coordinates not finite, or too far from the view to place in
     *         double precision (see docs/reading-limits.md)", or null when none was skipped
     */
    public String skippedNote() {
        if (skippedInvalid <= 0) {
            return null;
        }
        return skippedInvalid + " of " + Counts.of(trianglesIn, "triangle") + " skipped: coordinates not finite, "
                + "or too far from the view to place in double precision (see docs/reading-limits.md)";
    }

    /**
     * All culled triangles.
     *
     * @return back-face, frustum and degenerate culls together
     */
    public long culled() {
        return culledBackFace + culledFrustum + culledDegenerate;
    }

    /**
     * The statistics as a JSON object: snake_case keys in this order, times in milliseconds. The raster
     * and overlay times are named {@code raster_estimate} and {@code overlay_estimate} when they are
     * estimated ({@link #bandTimesEstimated}), so that a field called plainly "raster" or "overlay" is
     * always measured.
     */
    private JsonObject json() {
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
                .put("segments_in", segmentsIn)
                .put("segments_drawn", segmentsDrawn)
                .put("line_pixels", linePixels)
                .put("billboards", billboards)
                .put("glyphs", glyphs)
                .put("quad_pixels", quadPixels)
                .put("ms", new JsonObject()
                        .put("transform", transformNanos / 1e6, 3)
                        .put("clip", clipNanos / 1e6, 3)
                        .put("tessellate", tessellateNanos / 1e6, 3)
                        .put(bandTimesEstimated ? "raster_estimate" : "raster", rasterNanos / 1e6, 3)
                        .put(bandTimesEstimated ? "overlay_estimate" : "overlay", overlayNanos / 1e6, 3)
                        .put("lines", lineNanos / 1e6, 3)
                        .put("quads", quadNanos / 1e6, 3)
                        .put("total", totalNanos / 1e6, 3));
    }

    /**
     * The statistics as one line of JSON: snake_case keys, times in milliseconds (see {@code json}).
     *
     * @return the JSON line, without a line break
     */
    public String toJson() {
        return json().toString();
    }
}
