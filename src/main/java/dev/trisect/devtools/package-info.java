/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * The developer tools: a panel of sections (overlay, path, split policy, frame
 * budget, the comparison with the per-pixel path, statistics, frame time, camera, render) and the F12
 * window that holds one. Programs show them through {@link dev.trisect.view.TrisectView}; nothing here
 * is API.
 */
package dev.trisect.devtools;
