/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * Writing what Trisect produces — colour images as PNG or binary PPM, UV buffers as PFM — and reading
 * PFM back for comparisons.
 *
 * <p>Arrays are row-major with row 0 at the top, as everywhere in Trisect. Every write goes to a
 * temporary file in the target's directory that is then renamed over the target, so a failed write
 * leaves neither a partial file nor a damaged earlier one. Problems a user can cause (a bad path, an
 * unsupported extension, a malformed file) are reported as one-line
 * {@link dev.trisect.base.InputException}s that start with the path as given.
 */
package dev.trisect.io;
