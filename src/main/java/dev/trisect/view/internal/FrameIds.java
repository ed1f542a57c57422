package dev.trisect.view.internal;

import dev.trisect.scene.Pick;

/**
 * Which triangle, and so which object, each pixel of a view's frame shows: the frame's triangle ids
 * ({@link dev.trisect.render.Framebuffer#ids()}: the frame triangle's index + 1, 0 for the background),
 * which every frame of a view records — 4 bytes a pixel, and up to 6 % of a frame's time with trilinear
 * filtering, up to 17 % with nearest (scripts/uv-output-cost.sh, docs/view.md) — so that
 * picking, the pointer's events and the hover highlight read the frame on screen and never draw it
 * again. A pick's point and texel follow from the triangle and the frame's camera
 * ({@link dev.trisect.scene.internal.DrawnFrame#pick}).
 */
public final class FrameIds {
    private FrameIds() {
    }

    /** Whether {@code slot}'s frame recorded its triangle ids (every drawn frame does). */
    public static boolean has(FrameSlot slot) {
        return slot.frame.ids() != null && slot.drawn != null;
    }

    /** The frame triangle at pixel (x, y) of a slot that has ids, 0-based; -1 for the background. */
    static int id(FrameSlot slot, int x, int y) {
        return slot.frame.ids()[y * slot.width() + x] - 1;
    }

    /** The pick at pixel (x, y) of a slot that has ids, or null for the background. */
    public static Pick pick(FrameSlot slot, int x, int y) {
        int id = id(slot, x, y);
        return id < 0 ? null : slot.drawn.pick(id, x, y);
    }
}
