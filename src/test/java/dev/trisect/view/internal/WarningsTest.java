package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Viewport;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import org.junit.jupiter.api.Test;

/** The status bar's warnings, from a real frame's statistics. */
class WarningsTest {
    private static FrameStats frame(TessellationSettings t) {
        SceneAsset floor = DemoScenes.floor();
        try (FrameRenderer r = new FrameRenderer(1)) {
            return r.render(floor.mesh(), floor.textureArray(), floor.camera().viewProjection(new Viewport(320, 180)),
                    RenderSettings.defaults().withTessellation(t), new Framebuffer(320, 180));
        }
    }

    @Test
    void aCapReachedIsSaidWithItsFallbackPieces() {
        TessellationSettings fine = TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.5);
        ViewState.Budget off = new ViewState.Budget(false, 16);
        assertNull(Warnings.of(frame(fine), off, Double.NaN, fine), "nothing to say");
        TessellationSettings capped = fine.withMaxError(0.05).withMaxDepth(2);
        FrameStats s = frame(capped);
        String w = Warnings.of(s, off, Double.NaN, capped);
        assertTrue(w != null && w.contains("Cap reached on " + s.capsReached() + " triangles")
                && w.contains(s.piecesFallback() + " pieces filled per pixel"), w);
    }

    @Test
    void aBudgetMissedAtTheUsersThresholdIsSaid() {
        TessellationSettings t = TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.5);
        FrameStats s = frame(t);
        ViewState.Budget impossible = new ViewState.Budget(true, 1e-6);
        String w = Warnings.of(s, impossible, 0.5, t);
        assertTrue(w != null && w.contains("Over budget"), w);
        assertNull(Warnings.of(s, impossible, 0.25, t), "the controller still has room: no warning");
        assertNull(Warnings.of(s, new ViewState.Budget(true, 1e6), 0.5, t), "within budget");
    }
}
