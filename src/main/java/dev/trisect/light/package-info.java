/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * Light and fog as OpenGL 1.x's fixed function computes them: the fog pass over a frame's filled rows
 * ({@link dev.trisect.light.FogPass}). The pipeline applies it; the scene and the command line
 * describe the fog ({@link dev.trisect.render.Fog}).
 */
package dev.trisect.light;
