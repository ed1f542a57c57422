package dev.trisect.pipeline;

import java.util.Locale;

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
 * @param splits           midpoint splits made
 * @param deepestSplit     highest edge level reached (times an input edge was halved)
 * @param capsReached      input triangles whose splitting a depth or piece cap stopped short
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
                         int deepestSplit, long capsReached, long pixelsWritten, int threads,
                         long transformNanos, long clipNanos, long tessellateNanos, long rasterNanos,
                         long overlayNanos, long totalNanos) {

    /** All culled triangles. */
    public long culled() {
        return culledBackFace + culledFrustum + culledDegenerate;
    }

    /** One line of JSON, snake_case keys, times in milliseconds. */
    public String toJson() {
        return String.format(Locale.ROOT,
                "{\"triangles_in\":%d,\"culled\":%d,\"culled_back_face\":%d,\"culled_frustum\":%d,"
                        + "\"culled_degenerate\":%d,\"skipped_invalid\":%d,\"clipped\":%d,\"pieces\":%d,"
                        + "\"pieces_off_screen\":%d,\"splits\":%d,\"deepest_split\":%d,\"caps_reached\":%d,"
                        + "\"pixels_written\":%d,\"threads\":%d,\"ms\":{\"transform\":%.3f,\"clip\":%.3f,\"tessellate\":%.3f,"
                        + "\"raster\":%.3f,\"overlay\":%.3f,\"total\":%.3f}}",
                trianglesIn, culled(), culledBackFace, culledFrustum, culledDegenerate, skippedInvalid, clipped,
                pieces, piecesOffScreen, splits, deepestSplit, capsReached, pixelsWritten, threads,
                transformNanos / 1e6, clipNanos / 1e6, tessellateNanos / 1e6, rasterNanos / 1e6,
                overlayNanos / 1e6, totalNanos / 1e6);
    }
}
