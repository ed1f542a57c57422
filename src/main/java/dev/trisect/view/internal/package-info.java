/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * The engine room of a {@link dev.trisect.view.TrisectView}: the render thread and
 * the state it shares with the event thread, the triple buffer of frames, the camera controls, the
 * view's commands and keys, its life in a window, the pixel inspector and what is painted over a
 * frame. Public only so that the view and the developer tools can reach it; not part of the API.
 */
package dev.trisect.view.internal;
