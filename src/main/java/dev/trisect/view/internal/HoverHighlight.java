package dev.trisect.view.internal;

import dev.trisect.pipeline.Draws;
import dev.trisect.render.Framebuffer;
import dev.trisect.scene.Highlight;
import dev.trisect.scene.Node;
import dev.trisect.scene.Scene;
import java.util.List;

/**
 * Marks the node under the pointer in a frame already filled: a tint of its pixels or an outline
 * along its visible edge, found from the frame's triangle ids ({@link FrameIds}), never by drawing it
 * again and never touching a texture. Runs after the fill and the comparison (which therefore never
 * measure it), before the border overlay. Render thread; keeps a mark buffer from frame to frame.
 */
final class HoverHighlight {
    private byte[] marks = new byte[0];
    private int[] ranges = new int[8];

    /**
     * Marks in {@code frame} every object of {@code placed} (drawn as {@code draws}) that is
     * {@code owner} or inside it, as {@code owner}'s highlight says. Does nothing when the owner has no
     * highlight now or the frame kept no ids.
     */
    void apply(Framebuffer frame, Draws draws, List<Scene.Placed> placed, Node owner) {
        Highlight h = owner == null ? null : owner.hoverHighlight();
        int[] ids = frame.ids();
        if (h == null || ids == null) {
            return;
        }
        // The frame triangles of the marked objects: one range of ids per draw.
        int n = 0;
        for (int k = 0; k < placed.size(); k++) {
            if (inside(placed.get(k).object(), owner)) {
                if (2 * n + 2 > ranges.length) {
                    ranges = java.util.Arrays.copyOf(ranges, 2 * ranges.length);
                }
                ranges[2 * n] = draws.firstTriangle(k);
                ranges[2 * n + 1] = draws.firstTriangle(k + 1);
                n++;
            }
        }
        if (n == 0) {
            return;
        }
        int w = frame.width();
        int hgt = frame.height();
        int[] color = frame.colour();
        if (marks.length < w * hgt) {
            marks = new byte[w * hgt];
        }
        for (int i = 0; i < w * hgt; i++) {
            marks[i] = marked(ids[i] - 1, n) ? (byte) 1 : 0;
        }
        int rgb = h.rgb();
        for (int y = 0; y < hgt; y++) {
            for (int x = 0; x < w; x++) {
                int i = y * w + x;
                if (marks[i] == 0) {
                    continue;
                }
                if (!h.outline()) {
                    color[i] = 0xFF000000 | (((color[i] & 0xFEFEFE) >> 1) + ((rgb & 0xFEFEFE) >> 1));
                } else if (x == 0 || y == 0 || x == w - 1 || y == hgt - 1 || marks[i - 1] == 0 || marks[i + 1] == 0
                        || marks[i - w] == 0 || marks[i + w] == 0) {
                    color[i] = 0xFF000000 | rgb;
                }
            }
        }
    }

    private boolean marked(int id, int n) {
        for (int r = 0; r < n; r++) {
            if (id >= ranges[2 * r] && id < ranges[2 * r + 1]) {
                return true;
            }
        }
        return false;
    }

    /** Whether {@code node} is {@code owner} or inside it. */
    static boolean inside(Node node, Node owner) {
        for (Node n = node; n != null; n = n.parent()) {
            if (n == owner) {
                return true;
            }
        }
        return false;
    }
}
