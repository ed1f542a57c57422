/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * Light and fog as OpenGL 1.x's fixed function computes them: a frame's lights in world space
 * ({@link dev.trisect.light.Lights}), how light falls on a material ({@link dev.trisect.light.Surface}),
 * the per-vertex lighting equation without emission and specular
 * ({@link dev.trisect.light.LightingEquation}), and the fog pass over a frame's filled rows
 * ({@link dev.trisect.light.FogPass}). The pipeline applies them; the scene and the command line
 * describe them.
 */
package dev.trisect.light;
