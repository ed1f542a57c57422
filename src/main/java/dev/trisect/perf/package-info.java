/**
 * <b>Internal, not part of the API</b> (the module does not export it; it may change without notice).
 * Performance measurement and control: timing frames of a scene per path, the cost/quality sweep of
 * the split thresholds with its chart, and the budget controller that holds a frame-time target. Above
 * {@code pipeline}, {@code metrics} and {@code scene}; used by the command line and the demo.
 */
package dev.trisect.perf;
