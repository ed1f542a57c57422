package dev.trisect.metrics;

import dev.trisect.base.internal.JsonObject;

/**
 * How far a test render is from a reference render of the same scene and size, as measured by
 * {@link ImageComparison#compare}.
 *
 * <p>A pixel is <em>compared</em> when both renders cover it with the same triangle id; only compared
 * pixels enter the texel and displacement statistics. Statistics over no values (no compared pixel, or
 * no defined displacement) are {@code NaN}. Percentiles are nearest-rank: the p99 is the smallest
 * value that at least 99% of the values do not exceed.
 *
 * <p>The displacement is exact ({@link #displacementExact()}: the texel coordinates a pixel shows
 * mapped back to the 3D point that carries them, projected, distance to the pixel centre) when the
 * comparison knew the geometry, and otherwise a first-order estimate from the UV buffers alone; see
 * {@link ImageComparison}. {@link #toJson()} names the estimate's fields {@code ..._estimate} so that
 * a field called plainly "displacement" is always exact.
 *
 * @param width              image width in pixels
 * @param height             image height in pixels
 * @param comparedPixels     pixels covered in both renders by the same triangle id (with finite s, t)
 * @param otherPixels        pixels covered in one render only, by different ids in the two, or with a
 *                           non-finite s or t; pixels covered in neither render are in neither count
 * @param maxTexelError      largest texel error over compared pixels, in texels: the Euclidean distance
 *                           between the (s, t) of the two renders
 * @param p99TexelError      99th percentile of the texel error, in texels
 * @param meanTexelError     mean texel error, in texels
 * @param maxDisplacement    largest on-screen displacement, in pixels: how far from where true
 *                           perspective puts it the test draws a texel (see {@link ImageComparison})
 * @param p99Displacement    99th percentile of the displacement, in pixels
 * @param meanDisplacement   mean displacement, in pixels
 * @param displacementPixels compared pixels whose displacement is defined (exact: the triangle's UV
 *                           mapping is not degenerate and the point projects; estimate: the reference's
 *                           screen-space Jacobian exists there and is not singular)
 * @param degenerateUvPixels compared pixels left out of the exact displacement because their triangle's
 *                           texel coordinates span no area (no single 3D point carries them); 0 for
 *                           the estimate, which does not know the triangles
 * @param displacementExact  whether the displacement statistics are exact (true) or the estimate
 * @param texelDifferShare   share (0..1) of compared pixels that sample a different texel, that is whose
 *                           {@code floor(s)} or {@code floor(t)} differs between the renders
 * @param colourRmse         root mean square difference of the R, G and B channels (0..255) over all
 *                           pixels; alpha is ignored
 * @param psnrDb             peak signal-to-noise ratio {@code 20 log10(255 / colourRmse)} in decibels;
 *                           {@code +Infinity} when the colours are identical
 */
public record Comparison(
        int width,
        int height,
        int comparedPixels,
        int otherPixels,
        double maxTexelError,
        double p99TexelError,
        double meanTexelError,
        double maxDisplacement,
        double p99Displacement,
        double meanDisplacement,
        int displacementPixels,
        int degenerateUvPixels,
        boolean displacementExact,
        double texelDifferShare,
        double colourRmse,
        double psnrDb) {

    /**
     * The components as a JSON object under snake_case keys in declaration order, for example
     * {@code {"width":1280,"height":720,"compared_pixels":...,"psnr_db":null}}.
     * The exact displacement's keys are {@code max_displacement}, {@code p99_displacement},
     * {@code mean_displacement}, {@code displacement_pixels} and {@code degenerate_uv_pixels}; an
     * estimate's are {@code max_displacement_estimate}, {@code p99_displacement_estimate},
     * {@code mean_displacement_estimate} and {@code displacement_estimate_pixels}, and the flag itself is
     * not written (the keys say it). Non-finite numbers (NaN, infinities) are written as {@code null}, as
     * JSON has no literal for them.
     *
     * @return the JSON object
     */
    public JsonObject json() {
        JsonObject json = new JsonObject()
                .put("width", width)
                .put("height", height)
                .put("compared_pixels", comparedPixels)
                .put("other_pixels", otherPixels)
                .put("max_texel_error", maxTexelError)
                .put("p99_texel_error", p99TexelError)
                .put("mean_texel_error", meanTexelError)
                .put(displacementExact ? "max_displacement" : "max_displacement_estimate", maxDisplacement)
                .put(displacementExact ? "p99_displacement" : "p99_displacement_estimate", p99Displacement)
                .put(displacementExact ? "mean_displacement" : "mean_displacement_estimate", meanDisplacement)
                .put(displacementExact ? "displacement_pixels" : "displacement_estimate_pixels", displacementPixels);
        if (displacementExact) {
            json.put("degenerate_uv_pixels", degenerateUvPixels);
        }
        return json
                .put("texel_differ_share", texelDifferShare)
                .put("colour_rmse", colourRmse)
                .put("psnr_db", psnrDb);
    }

    /** {@link #json()} as one line (no trailing newline). */
    public String toJson() {
        return json().toString();
    }
}
