package dev.trisect.view.internal;

import dev.trisect.metrics.HeatScale;
import dev.trisect.pipeline.Draws;
import dev.trisect.render.FrameStats;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.scene.internal.DrawnFrame;
import dev.trisect.render.Framebuffer;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.awt.image.DirectColorModel;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;

/**
 * One of the three frames of the triple buffer: the engine's framebuffer, a {@link BufferedImage}
 * that shows its {@code int[]} directly (no copy, no per-pixel setRGB), and what was drawn into it.
 */
public final class FrameSlot {
    public final Framebuffer frame;
    public final BufferedImage image;
    /** Statistics of the frame this slot holds. */
    public FrameStats stats;
    /** Time the border overlay took on this frame, drawn after the engine's frame (0 when off). */
    public long overlayNanos;
    /** The render settings the user chose for the frame. */
    public RenderSettings render;
    /** The render settings the frame was drawn with: the user's, with the budget controller's threshold. */
    public RenderSettings drawnRender;
    /** The pixel inspector's reading of this frame, or null when it is off. */
    public PixelInspector.Inspection inspection;
    /**
     * The frame's colours around the inspected pixel before anything was drawn over the image (outlines,
     * the hover tint), {@link InspectorPainter#MAGNIFIED} squared, row by row; null when not inspected.
     * The inspector's numbers are of these; the magnifier shows the frame as it is on screen.
     */
    public int[] underMarks;
    /** The readouts of the pinned pixels on this frame, oldest pin first; empty when none are pinned. */
    public PixelInspector.Inspection[] pins = new PixelInspector.Inspection[0];
    /** Time the inspector took on this frame, nanoseconds. */
    public long inspectNanos;
    /** What the view showed when the frame was drawn. */
    public ViewKind view = ViewKind.IMAGE;
    /** Split view divider, 0..1 of the width. */
    public double splitFraction;
    /** Heat map scale of a difference view. */
    public HeatScale heatScale;
    /** Serial number of the frame, counting from 1. */
    public long serial;
    /** The camera the frame was drawn with. */
    public Camera camera;
    /** What the frame drew: a draw per visible object (reused by the render thread for this slot). */
    public final Draws draws = new Draws();
    /** The objects the frame drew and the way back from its pixels to them, for picking. */
    public DrawnFrame drawn;

    public FrameSlot(int width, int height) {
        frame = new Framebuffer(width, height);
        int[] pixels = frame.colour();
        // An INT_RGB image over the framebuffer's own array: Java2D blits it on its fast path.
        DirectColorModel rgb = new DirectColorModel(24, 0xFF0000, 0x00FF00, 0x0000FF);
        WritableRaster raster = Raster.createPackedRaster(new DataBufferInt(pixels, pixels.length), width, height,
                width, rgb.getMasks(), null);
        image = new BufferedImage(rgb, raster, false, null);
    }

    public int width() {
        return frame.width();
    }

    public int height() {
        return frame.height();
    }

    /** Whether this slot has the given size. */
    public boolean is(int width, int height) {
        return frame.width() == width && frame.height() == height;
    }
}
