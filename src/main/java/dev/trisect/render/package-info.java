/**
 * <b>API.</b> The values of drawing a frame: how ({@link dev.trisect.render.RenderSettings}: the
 * texturing path, the split policy and its limits, culling, background, filter, polygon borders), into
 * what ({@link dev.trisect.render.Framebuffer}: colour, depth and, on request, each pixel's texel
 * coordinates and triangle), and what it did ({@link dev.trisect.render.FrameStats}: counts and
 * milliseconds per stage).
 */
package dev.trisect.render;
