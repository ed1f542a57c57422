package dev.trisect.view.internal;

import dev.trisect.scene.Node;
import dev.trisect.scene.Pick;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import java.util.List;

/**
 * Which triangle, and so which object, each pixel of a view's frame shows: the frame's triangle ids,
 * read by picking, the pointer's events and the hover highlight, so that none of them draws the frame
 * again. They are the UV output's third channel (the frame triangle's index + 1, 0 for the
 * background), which a frame records while something needs them: a pointer listener or a hover
 * highlight on a node of the scene, a pick listener on the view, or a pick asked of the view.
 */
public final class FrameIds {
    private FrameIds() {
    }

    /** Whether a frame of these objects should record its triangle ids: something listens to the pointer. */
    static boolean wanted(ViewState state, List<Scene.Placed> placed) {
        if (state.idsWanted()) {
            return true;
        }
        for (Scene.Placed p : placed) {
            for (Node n = p.object(); n != null; n = n.parent()) {
                if (n.hasPointerListeners() || n.hoverHighlight() != null) {
                    return true;
                }
            }
        }
        return false;
    }

    /** Whether {@code slot}'s frame recorded its triangle ids. */
    public static boolean has(FrameSlot slot) {
        return slot.frame.uv() != null && slot.drawn != null;
    }

    /** The frame triangle at pixel (x, y) of a slot that has ids, 0-based; -1 for the background. */
    static int id(FrameSlot slot, int x, int y) {
        return (int) slot.frame.uv()[3 * (y * slot.width() + x) + 2] - 1;
    }

    /** The object at pixel (x, y) of a slot that has ids, or null for the background. */
    public static SceneObject objectAt(FrameSlot slot, int x, int y) {
        int id = id(slot, x, y);
        return id < 0 ? null : slot.drawn.placed().get(slot.draws.drawOf(id)).object();
    }

    /** The pick at pixel (x, y) of a slot that has ids, or null for the background. */
    public static Pick pick(FrameSlot slot, int x, int y) {
        int i = 3 * (y * slot.width() + x);
        double[] uv = slot.frame.uv();
        int id = (int) uv[i + 2] - 1;
        return id < 0 ? null : slot.drawn.pick(id, uv[i], uv[i + 1], x, y);
    }
}
