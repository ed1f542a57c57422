package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Viewport;
import dev.trisect.raster.OverlayColours;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The inspector's answer to "whose magenta mark is this": {@link FrameRecord#fallbackOutlineAt} names
 * a fallback piece exactly where the overlay draws one's outline — on the demo at start, whose magenta
 * marks are all slivers (issue 18: the inspector named the pixel's own piece, with no fallback flag).
 */
class FallbackOutlineLookupTest {
    private static final int W = 640;
    private static final int H = 360;

    @Test
    void aPieceIsNamedExactlyWhereTheOverlayDrawsAFallbackOutline() {
        SceneAsset demo = DemoScenes.demo();
        Framebuffer fb = new Framebuffer(W, H);
        try (FrameRenderer r = new FrameRenderer(2)) {
            FrameStats st = r.render(demo.mesh(), demo.textureArray(), demo.camera().viewProjection(new Viewport(W, H)),
                    RenderSettings.defaults(), fb);
            assertTrue(st.piecesFallback() > 0 && st.capsReached() == 0, "slivers only");
            int[] before = fb.colour().clone();
            float[] depth = fb.depth().clone();
            // The fallback pieces' outlines alone, opaque magenta: the pixels they light.
            r.drawBorders(fb, BorderStyle.fallbackOnly(), RenderSettings.defaults().tessellation());
            int[] after = fb.colour();
            int marked = 0;
            int slivers = 0;
            Random random = new Random(3);
            for (int i = 0; i < W * H; i++) {
                boolean lit = after[i] == OverlayColours.FALLBACK && before[i] != OverlayColours.FALLBACK;
                // Every lit pixel, and its neighbours and a sample of the rest (a lookup scans every piece).
                boolean near = lit || i % W > 0 && after[i - 1] == OverlayColours.FALLBACK
                        || i >= W && after[i - W] == OverlayColours.FALLBACK;
                if (!near && random.nextInt(100) != 0) {
                    continue;
                }
                PieceInfo p = r.drawn().fallbackOutlineAt(i % W, i / W, depth[i]);
                if (lit) {
                    assertNotNull(p, "the mark at " + i % W + "," + i / W + " is a fallback piece's");
                    assertTrue(p.fallback());
                    marked++;
                    slivers += p.sliver() ? 1 : 0;
                } else if (before[i] != OverlayColours.FALLBACK) {
                    assertNull(p, "no mark at " + i % W + "," + i / W);
                }
            }
            assertTrue(marked > 50, "marks checked: " + marked);
            assertEquals(marked, slivers, "the demo's marks at start are all slivers'");
        }
    }
}
