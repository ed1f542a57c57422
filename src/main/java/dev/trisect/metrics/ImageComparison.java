package dev.trisect.metrics;

import java.util.Objects;

/**
 * Compares a test render with a reference render of the same size: texel error, on-screen
 * displacement, how often a different texel is sampled, and colour RMSE / PSNR (see {@link Comparison}).
 *
 * <p>Inputs are the arrays described in the package documentation: ARGB colour images and UV buffers of
 * {@code [s, t, id]} per pixel, row 0 at the top. Screen coordinates are pixels with x to the right and
 * y down (image rows); texel coordinates are {@code (u * texWidth, v * texHeight)}.
 *
 * <h2>Displacement</h2>
 * The displacement answers "how far on screen is the texture from where true perspective puts it".
 *
 * <p><b>Exact</b>, when the geometry is known ({@link TexelToScreen}, as in {@code compare} and the
 * demo): the texel coordinates the test shows at pixel p are mapped back to the 3D point of the
 * pixel's triangle that carries them, that point is projected, and the displacement is its distance
 * in pixels from p's centre. It depends on the test render alone; the reference only decides which
 * pixels are compared (the same triangle visible in both). It is undefined (NaN, left out of the
 * statistics) where the triangle's UV mapping is degenerate (counted as
 * {@link Comparison#degenerateUvPixels()}) or the point does not project.
 *
 * <p><b>Estimate</b>, when only the two UV buffers are known ({@code diff}): at a compared pixel p,
 * let f be the reference's map from screen position to texel coordinates and
 * J = d(s, t)/d(x, y) = [[ds/dx, ds/dy], [dt/dx, dt/dy]] its Jacobian at p. The test shows texel
 * {@code (s, t)_test} at p; the reference draws that texel at p + d, where f(p + d) = {@code (s, t)_test}.
 * To first order,
 * {@code d = J^-1 ((s, t)_test - (s, t)_ref)}, and the estimate is |d| in pixels.
 * It is exact where the reference map is affine around p (within one affinely textured triangle) and,
 * for a perspective map, exact in the limit of small errors, its relative error growing with |d|
 * times the map's curvature: on a floor seen at a grazing angle it over-reports by a few percent.
 *
 * <p>J is estimated by finite differences of the <em>reference</em> UV buffer between p and its
 * neighbours covered by the same triangle id: a central difference along an axis where both neighbours
 * on that axis qualify, a one-sided difference where only one does. The estimate is undefined
 * (NaN, and left out of the statistics) where an axis has no qualifying neighbour (a
 * triangle one pixel thin), or where J is singular: {@code |det J|} at most {@link #SINGULAR_TOLERANCE}
 * times {@code |ds/dx dt/dy| + |ds/dy dt/dx|}, i.e. the texture does not change along some screen
 * direction. A merely ill-conditioned J is kept: it gives a large displacement, which to first order is
 * the truth (a tiny texel error moves the texture far along the direction where it barely changes).
 *
 * <p>Cost: one pass over the pixels (the exact displacement costs one 3x3 map, a division and a
 * square root per pixel, plus one map per visible triangle), two whole-image {@code float} scratch arrays for the percentiles
 * (found by selection, not by sorting), no allocation per pixel.
 */
public final class ImageComparison {
    /**
     * Relative size of {@code |det J|}, against {@code |ds/dx dt/dy| + |ds/dy dt/dx|}, at or below which
     * the reference Jacobian counts as singular and the displacement is undefined: only (nearly) exact
     * cancellation, as from texture coordinates that are collinear across a triangle.
     */
    public static final double SINGULAR_TOLERANCE = 1e-6;

    /** The percentile reported as p99. */
    private static final int PERCENT = 99;

    private ImageComparison() {
    }

    /**
     * Compares two renders of the same size.
     *
     * @param width         image width in pixels, at least 1
     * @param height        image height in pixels, at least 1
     * @param argbTest      the test render's colours, {@code width * height}, row 0 at the top
     * @param uvTest        the test render's UV buffer, {@code 3 * width * height}
     * @param argbReference the reference render's colours
     * @param uvReference   the reference render's UV buffer
     * @return the statistics
     * @throws IllegalArgumentException when a size is not positive or an array's length does not match
     */
    public static Comparison compare(int width, int height, int[] argbTest, double[] uvTest,
                                     int[] argbReference, double[] uvReference) {
        return compare(width, height, argbTest, uvTest, argbReference, uvReference, null);
    }

    /**
     * Compares two renders of the same size, estimating the displacement from the UV buffers alone
     * (see the class comment; {@link Comparison#displacementExact()} is false), and also writes each
     * pixel's estimate, for a heat map ({@link HeatMap}) without recomputing. For when the geometry is
     * unknown, such as renders read from files; otherwise use the exact overload.
     *
     * @param width           image width in pixels, at least 1
     * @param height          image height in pixels, at least 1
     * @param argbTest        the test render's colours, {@code width * height}, row 0 at the top
     * @param uvTest          the test render's UV buffer, {@code 3 * width * height}
     * @param argbReference   the reference render's colours
     * @param uvReference     the reference render's UV buffer
     * @param displacementOut {@code width * height} floats, filled with the estimated displacement in
     *                        pixels of every pixel, row 0 at the top, NaN where it is undefined (not
     *                        compared, or no usable reference Jacobian); may be null
     * @return the statistics
     * @throws IllegalArgumentException when a size is not positive or an array's length does not match
     */
    public static Comparison compare(int width, int height, int[] argbTest, double[] uvTest,
                                     int[] argbReference, double[] uvReference, float[] displacementOut) {
        return measure(width, height, argbTest, uvTest, argbReference, uvReference, null, displacementOut);
    }

    /**
     * Compares two renders of the same frame with the exact displacement (see the class comment;
     * {@link Comparison#displacementExact()} is true), and also writes each pixel's displacement.
     *
     * @param width           image width in pixels, at least 1
     * @param height          image height in pixels, at least 1
     * @param argbTest        the test render's colours, {@code width * height}, row 0 at the top
     * @param uvTest          the test render's UV buffer, {@code 3 * width * height}
     * @param argbReference   the reference render's colours
     * @param uvReference     the reference render's UV buffer
     * @param exact           the frame's texel-to-screen maps (same mesh, textures, camera and size as
     *                        the renders); not null
     * @param displacementOut {@code width * height} floats, filled with the exact displacement in pixels
     *                        of every pixel, row 0 at the top, NaN where it is undefined (not compared,
     *                        degenerate UV mapping, or a point that does not project); may be null
     * @return the statistics
     * @throws IllegalArgumentException when a size is not positive or an array's length does not match
     */
    public static Comparison compare(int width, int height, int[] argbTest, double[] uvTest,
                                     int[] argbReference, double[] uvReference, TexelToScreen exact,
                                     float[] displacementOut) {
        return measure(width, height, argbTest, uvTest, argbReference, uvReference,
                Objects.requireNonNull(exact, "exact"), displacementOut);
    }

    /** The comparison, with the exact displacement where {@code exact} is not null, else the estimate. */
    private static Comparison measure(int width, int height, int[] argbTest, double[] uvTest,
                                      int[] argbReference, double[] uvReference, TexelToScreen exact,
                                      float[] displacementOut) {
        int pixels = checkSizes(width, height, argbTest, uvTest, argbReference, uvReference, displacementOut);
        float[] texelErrors = new float[pixels];
        float[] displacements = new float[pixels];
        int compared = 0;
        int other = 0;
        int defined = 0;
        int degenerateUv = 0;
        int texelDiffers = 0;
        double texelSum = 0;
        double displacementSum = 0;
        float texelMax = 0;
        float displacementMax = 0;

        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int i = y * width + x;
                int k = 3 * i;
                double id = uvReference[k + 2];
                double idTest = uvTest[k + 2];
                float displacement = Float.NaN;
                if (id != 0 || idTest != 0) {
                    double sRef = uvReference[k];
                    double tRef = uvReference[k + 1];
                    double sTest = uvTest[k];
                    double tTest = uvTest[k + 1];
                    // NaN ids never equal each other, so they land in "other" as well.
                    if (id != idTest || !Double.isFinite(sRef + tRef + sTest + tTest)) {
                        other++;
                    } else {
                        double ds = sTest - sRef;
                        double dt = tTest - tRef;
                        // Stats are taken from the float values stored for the percentile, so that
                        // p99 <= max and mean <= max hold exactly.
                        float texelError = (float) Math.sqrt(ds * ds + dt * dt);
                        texelErrors[compared++] = texelError;
                        texelSum += texelError;
                        texelMax = Math.max(texelMax, texelError);
                        if (!sameFloor(uvTest[k], uvReference[k]) || !sameFloor(uvTest[k + 1], uvReference[k + 1])) {
                            texelDiffers++;
                        }

                        displacement = exact == null
                                ? displacementAt(uvReference, k, id, x, y, width, height, ds, dt)
                                : exactAt(exact, id, sTest, tTest, x, y);
                        if (!Float.isNaN(displacement)) {
                            displacements[defined++] = displacement;
                            displacementSum += displacement;
                            displacementMax = Math.max(displacementMax, displacement);
                        } else if (exact != null && exact.isDegenerate(triangleOf(id))) {
                            degenerateUv++;
                        }
                    }
                }
                if (displacementOut != null) {
                    displacementOut[i] = displacement;
                }
            }
        }

        double rmse = colourRmse(argbTest, argbReference);
        return new Comparison(width, height, compared, other,
                compared == 0 ? Double.NaN : texelMax,
                Percentiles.nearestRank(texelErrors, compared, PERCENT),
                compared == 0 ? Double.NaN : texelSum / compared,
                defined == 0 ? Double.NaN : displacementMax,
                Percentiles.nearestRank(displacements, defined, PERCENT),
                defined == 0 ? Double.NaN : displacementSum / defined,
                defined,
                degenerateUv,
                exact != null,
                compared == 0 ? Double.NaN : (double) texelDiffers / compared,
                rmse,
                rmse == 0 ? Double.POSITIVE_INFINITY : 20 * Math.log10(255 / rmse));
    }

    /**
     * The exact displacement (pixels, as a float) of pixel (x, y) showing texel coordinates (s, t) of
     * the triangle with UV-output id {@code id}; NaN where undefined.
     */
    private static float exactAt(TexelToScreen exact, double id, double s, double t, int x, int y) {
        float d = (float) exact.displacement(triangleOf(id), s, t, x, y);
        return d <= Float.MAX_VALUE ? d : Float.NaN;
    }

    /**
     * The 0-based triangle index of a UV-output id; -1 (no triangle) where the id is not a whole number
     * from 1 to 2^31 - 1 (the in-memory buffer holds every int id exactly; a non-integer or larger one
     * never picks a wrong triangle).
     */
    private static int triangleOf(double id) {
        return id >= 1 && id < 0x1p31 && id == (int) id ? (int) id - 1 : -1;
    }

    /**
     * Only the estimated displacement of every pixel (see
     * {@link #compare(int, int, int[], double[], int[], double[], float[])}), without the statistics.
     *
     * @param displacementOut {@code width * height} floats: pixels, NaN where undefined
     */
    public static void displacements(int width, int height, double[] uvTest, double[] uvReference,
                                     float[] displacementOut) {
        perPixel(width, height, uvTest, uvReference, null, displacementOut);
    }

    /**
     * Only the exact displacement of every pixel (see
     * {@link #compare(int, int, int[], double[], int[], double[], TexelToScreen, float[])}), without the
     * statistics: what a live heat map or a pixel inspector needs each frame, at a fraction of the cost.
     *
     * @param exact           the frame's texel-to-screen maps; not null
     * @param displacementOut {@code width * height} floats: pixels, NaN where undefined
     */
    public static void displacements(int width, int height, double[] uvTest, double[] uvReference, TexelToScreen exact,
                                     float[] displacementOut) {
        perPixel(width, height, uvTest, uvReference, Objects.requireNonNull(exact, "exact"), displacementOut);
    }

    /** Per-pixel displacements, exact where {@code exact} is not null, else estimated. */
    private static void perPixel(int width, int height, double[] uvTest, double[] uvReference, TexelToScreen exact,
                                 float[] displacementOut) {
        long pixels = (long) width * height;
        if (width < 1 || height < 1 || uvTest.length != 3 * pixels || uvReference.length != 3 * pixels
                || displacementOut.length != pixels) {
            throw new IllegalArgumentException("array lengths do not match a " + width + "x" + height + " image");
        }
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int i = y * width + x;
                int k = 3 * i;
                double id = uvReference[k + 2];
                float displacement = Float.NaN;
                if (id != 0 && id == uvTest[k + 2]) {
                    double ds = uvTest[k] - uvReference[k];
                    double dt = uvTest[k + 1] - uvReference[k + 1];
                    if (Double.isFinite(ds + dt)) {
                        displacement = exact == null
                                ? displacementAt(uvReference, k, id, x, y, width, height, ds, dt)
                                : exactAt(exact, id, uvTest[k], uvTest[k + 1], x, y);
                    }
                }
                displacementOut[i] = displacement;
            }
        }
    }

    /**
     * The displacement in pixels at pixel (x, y) (UV offset {@code k}) of a texel error (ds, dt),
     * through the reference's Jacobian from neighbours drawn by the same triangle; NaN where an axis
     * has no such neighbour or the Jacobian is singular.
     */
    private static float displacementAt(double[] uvReference, int k, double id, int x, int y, int width, int height,
                                        double ds, double dt) {
        int rowStride = 3 * width;
        boolean left = x > 0 && uvReference[k - 1] == id;
        boolean right = x < width - 1 && uvReference[k + 5] == id;
        boolean up = y > 0 && uvReference[k + 2 - rowStride] == id;
        boolean down = y < height - 1 && uvReference[k + 2 + rowStride] == id;
        if (!((left || right) && (up || down))) {
            return Float.NaN;
        }
        double sx = derivative(uvReference, k, 3, left, right);
        double tx = derivative(uvReference, k + 1, 3, left, right);
        double sy = derivative(uvReference, k, rowStride, up, down);
        double ty = derivative(uvReference, k + 1, rowStride, up, down);
        return displacement(sx, sy, tx, ty, ds, dt);
    }

    /**
     * Derivative per pixel of the value at {@code uv[k]} along the axis whose neighbours are
     * {@code stride} values away: central where both neighbours qualify, else one-sided.
     */
    private static double derivative(double[] uv, int k, int stride, boolean previous, boolean next) {
        if (previous && next) {
            return (uv[k + stride] - uv[k - stride]) * 0.5;
        }
        return next ? uv[k + stride] - uv[k] : uv[k] - uv[k - stride];
    }

    /**
     * |J^-1 (ds, dt)| for J = [[sx, sy], [tx, ty]], as a float; NaN when J is singular or the result
     * does not fit a float.
     */
    private static float displacement(double sx, double sy, double tx, double ty, double ds, double dt) {
        double det = sx * ty - sy * tx;
        // Written so that NaN entries fail the test too.
        if (!(Math.abs(det) > SINGULAR_TOLERANCE * (Math.abs(sx * ty) + Math.abs(sy * tx)))) {
            return Float.NaN;
        }
        double inverse = 1 / det;
        double dx = (ty * ds - sy * dt) * inverse;
        double dy = (sx * dt - tx * ds) * inverse;
        float length = (float) Math.sqrt(dx * dx + dy * dy);
        return length <= Float.MAX_VALUE ? length : Float.NaN;
    }

    /**
     * Whether {@code floor(a) == floor(b)} for finite a and b: the same texel row or column is sampled.
     * Through int conversion where that is exact, as it measured several times faster here than
     * {@link Math#floor}; beyond 2^30 texels {@code Math.floor} itself.
     */
    private static boolean sameFloor(double a, double b) {
        if (Math.abs(a) < 0x1p30 && Math.abs(b) < 0x1p30) {
            int floorA = (int) a;
            int floorB = (int) b;
            // (int) truncates toward zero: step down for negative non-integers.
            floorA -= a < floorA ? 1 : 0;
            floorB -= b < floorB ? 1 : 0;
            return floorA == floorB;
        }
        return Math.floor(a) == Math.floor(b);
    }

    /** RMSE of the R, G and B channels (0..255) over all pixels. */
    private static double colourRmse(int[] argbTest, int[] argbReference) {
        long sum = 0;
        for (int i = 0; i < argbTest.length; i++) {
            int p = argbTest[i];
            int q = argbReference[i];
            int dr = (p >> 16 & 0xFF) - (q >> 16 & 0xFF);
            int dg = (p >> 8 & 0xFF) - (q >> 8 & 0xFF);
            int db = (p & 0xFF) - (q & 0xFF);
            sum += dr * dr + dg * dg + db * db;
        }
        return Math.sqrt(sum / (3.0 * argbTest.length));
    }

    private static int checkSizes(int width, int height, int[] argbTest, double[] uvTest,
                                  int[] argbReference, double[] uvReference, float[] displacementOut) {
        if (width < 1 || height < 1 || 3L * width * height > Integer.MAX_VALUE) {
            throw new IllegalArgumentException("image size " + width + "x" + height + " is not supported");
        }
        int pixels = width * height;
        checkLength("test colour image", argbTest.length, pixels);
        checkLength("reference colour image", argbReference.length, pixels);
        checkLength("test UV buffer", uvTest.length, 3 * pixels);
        checkLength("reference UV buffer", uvReference.length, 3 * pixels);
        if (displacementOut != null) {
            checkLength("displacement output", displacementOut.length, pixels);
        }
        return pixels;
    }

    private static void checkLength(String what, int actual, int expected) {
        if (actual != expected) {
            throw new IllegalArgumentException(what + " has " + actual + " values, expected " + expected);
        }
    }
}
