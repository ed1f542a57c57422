/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * How far one render is from another, in numbers ({@link dev.trisect.metrics.ImageComparison},
 * {@link dev.trisect.metrics.Comparison}) and in pictures ({@link dev.trisect.metrics.HeatMap}), and
 * how far each pixel's texture is from where true perspective puts it
 * ({@link dev.trisect.metrics.TexelToScreen}, the exact displacement, for callers that know the
 * geometry).
 *
 * <p>Everything here works on plain arrays, row 0 at the top: colour images as {@code int[]} ARGB,
 * {@code width * height}; UV buffers as {@code double[]}, {@code 3 * width * height}, pixel (x, y) at
 * {@code 3 * (y * width + x)} holding {@code [s, t, id]} — the texel coordinates
 * {@code (u * texWidth, v * texHeight)} the pixel was textured with (before wrapping) and the triangle
 * index + 1 (0 where nothing covers the pixel), as in the "UV output" of the rendering conventions.
 * No AWT: the code runs in the live developer panel and on the command line alike.
 */
package dev.trisect.metrics;
