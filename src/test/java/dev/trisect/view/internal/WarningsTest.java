package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Viewport;
import dev.trisect.perf.BudgetController;
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
        assertNull(Warnings.of(frame(fine), null), "nothing to say");
        TessellationSettings capped = fine.withMaxError(0.05).withMaxDepth(2);
        FrameStats s = frame(capped);
        String w = Warnings.of(s, null);
        assertTrue(w != null && w.contains("Cap reached on " + s.capsReached() + " triangles")
                && w.contains(s.piecesFallback() + " pieces filled per pixel"), w);
    }

    @Test
    void aTargetOutOfReachIsSaidWithTheThresholdTheToolsShow() {
        FrameStats s = frame(TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.5));
        ViewState.BudgetChoice atCeiling = new ViewState.BudgetChoice(0.5, BudgetController.Limit.CEILING, 23.4, 16.7,
                0.5, 0.5, 1000, 10_000, 0.1, "");
        String w = Warnings.of(s, atCeiling);
        assertTrue(w != null && w.contains("Over budget: median 23.4 ms against 16.7 ms even at your threshold (0.50 px)"),
                w);
        // The controller still has room, or holds the target, or is held by the piece budget: no warning,
        // whatever one frame's own time (issue 18: the warning named 32 px while the tools showed 10-19 px).
        for (BudgetController.Limit l : new BudgetController.Limit[] {BudgetController.Limit.TARGET,
            BudgetController.Limit.FLOOR, BudgetController.Limit.PIECE_BUDGET}) {
            assertNull(Warnings.of(s, new ViewState.BudgetChoice(0.25, l, 23.4, 16.7, 0.5, 0.25, 1000,
                    10_000, 0.1, "")), l.name());
        }
    }

    @Test
    void trianglesTheRendererCouldNotPlaceAreSaidAsTheCommandLineNotesThem() {
        FrameStats ok = frame(TessellationSettings.defaults());
        FrameStats skipped = new FrameStats(ok.trianglesIn(), ok.culledBackFace(), ok.culledFrustum(),
                ok.culledDegenerate(), 3, ok.clipped(), ok.pieces(), ok.piecesOffScreen(), ok.splits(),
                ok.deepestSplit(), ok.capsReached(), ok.piecesFallback(), ok.pieceBudget(), ok.budgetDepth(),
                ok.pixelsWritten(), ok.threads(), ok.transformNanos(), ok.clipNanos(), ok.tessellateNanos(),
                ok.rasterNanos(), ok.overlayNanos(), ok.bandTimesEstimated(), ok.totalNanos());
        String w = Warnings.of(skipped, null);
        assertTrue(w != null && w.contains("3 of " + ok.trianglesIn() + " triangles skipped")
                && w.contains("double precision"), w);
    }
}

