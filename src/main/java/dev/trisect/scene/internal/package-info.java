/**
 * <b>Internal.</b> How a scene's snapshot becomes a frame's draws, and the way back from a pixel to
 * the object, triangle, point and texel it shows; shared by the scene renderer and the view.
 */
package dev.trisect.scene.internal;
