/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * Drawing one frame: the draws of a frame, the transform to clip space, culling,
 * clipping, tessellation or projection, the bands the frame is filled in on the worker threads, the
 * border overlay and the statistics ({@code FrameRenderer} is the entry; docs/architecture.md has the
 * stages). Programs draw through {@link dev.trisect.scene.SceneRenderer} or
 * {@link dev.trisect.view.TrisectView}.
 */
package dev.trisect.pipeline;
