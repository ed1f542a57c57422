package dev.trisect.ui;

import dev.trisect.pipeline.FrameStats;
import dev.trisect.raster.Framebuffer;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.awt.image.DirectColorModel;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;

/**
 * One of the three frames of the triple buffer: the engine's framebuffer, a {@link BufferedImage}
 * that shows its {@code int[]} directly (no copy, no per-pixel setRGB), and what was drawn into it.
 */
final class FrameSlot {
    final Framebuffer frame;
    final BufferedImage image;
    /** Statistics of the frame this slot holds. */
    FrameStats stats;
    /** Time the border overlay took on this frame, drawn after the engine's frame (0 when off). */
    long overlayNanos;
    /** The render settings the frame was drawn with. */
    dev.trisect.pipeline.RenderSettings render;
    /** The pixel inspector's reading of this frame, or null when it is off. */
    PixelInspector.Inspection inspection;
    /** Time the inspector took on this frame, nanoseconds. */
    long inspectNanos;
    /** What the view showed when the frame was drawn. */
    ViewKind view = ViewKind.IMAGE;
    /** Split view divider, 0..1 of the width. */
    double splitFraction;
    /** Heat map scale of a difference view. */
    dev.trisect.metrics.HeatScale heatScale;
    /** Serial number of the frame, counting from 1. */
    long serial;
    /** The camera the frame was drawn with. */
    dev.trisect.scene.Camera camera;

    FrameSlot(int width, int height) {
        frame = new Framebuffer(width, height);
        int[] pixels = frame.color();
        // An INT_RGB image over the framebuffer's own array: Java2D blits it on its fast path.
        DirectColorModel rgb = new DirectColorModel(24, 0xFF0000, 0x00FF00, 0x0000FF);
        WritableRaster raster = Raster.createPackedRaster(new DataBufferInt(pixels, pixels.length), width, height,
                width, rgb.getMasks(), null);
        image = new BufferedImage(rgb, raster, false, null);
    }

    int width() {
        return frame.width();
    }

    int height() {
        return frame.height();
    }

    /** Whether this slot has the given size. */
    boolean is(int width, int height) {
        return frame.width() == width && frame.height() == height;
    }
}
