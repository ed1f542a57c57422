/**
 * <b>API.</b> What to draw and from where: a {@link dev.trisect.scene.Scene} of
 * {@link dev.trisect.scene.SceneObject}s (a mesh with its {@link dev.trisect.scene.Material}s and a
 * transform) in {@link dev.trisect.scene.Group}s, changed from any thread while it is drawn; the
 * {@link dev.trisect.scene.Camera}; {@link dev.trisect.scene.SceneRenderer}, which draws a scene
 * headless into a framebuffer or an image, and {@link dev.trisect.scene.Pick}, what a pixel shows.
 * To show a scene in a window, see {@code dev.trisect.view}.
 */
package dev.trisect.scene;
