/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * Filling screen triangles and pieces: the fixed-point setup and the top-left fill
 * rule, the span loops of each path and filter (per pixel, affine pieces, the one-pass fill, the span
 * path's knots), and the border overlay's lines. Plain arrays, no AWT, no allocation in the loops.
 */
package dev.trisect.raster;
