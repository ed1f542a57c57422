/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * Splitting a clipped triangle into pieces small enough to fill affinely under the
 * chosen split policy (docs/conventions.md, docs/math.md): the tessellator, its edge bound, the piece
 * budget, and the vertex layout the geometry stages share.
 */
package dev.trisect.tessellate;
