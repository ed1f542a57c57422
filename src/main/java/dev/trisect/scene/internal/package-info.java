/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * How a scene's snapshot becomes a frame's draws, and the way back from a pixel to
 * the object, triangle, point and texel it shows; shared by the scene renderer and the view.
 */
package dev.trisect.scene.internal;
