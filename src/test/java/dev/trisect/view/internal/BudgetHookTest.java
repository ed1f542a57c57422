package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Viewport;
import dev.trisect.perf.BudgetController;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.FrameStats;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import org.junit.jupiter.api.Test;

/** The demo's budget hook: it changes only the tessellated threshold, within the user's ceiling. */
class BudgetHookTest {
    /** A frame of {@code ms} engine time with {@code pieces} of a budget of 100,000 (over it when more). */
    private static FrameStats frame(double ms, long pieces) {
        boolean over = pieces > 100_000;
        return new FrameStats(1000, 0, 0, 0, 0, 0, over ? 100_000 : pieces, 0, 0, 0, 0, 0, 100_000, over ? 3 : -1, 0, 1,
                0, 0, 0, 0, 0, false, Math.round(ms * 1e6));
    }

    private static FrameStats frame(double ms) {
        return frame(ms, 1000);
    }

    /** Feeds {@code stats} as a whole frame of its own engine time, nothing spent comparing. */
    private static ViewState.BudgetChoice done(BudgetHook hook, FrameStats stats) {
        return hook.frameDone(stats, stats.totalNanos() / 1e6, 0);
    }

    private static final RenderSettings USER = RenderSettings.defaults().withMode(RenderMode.TESSELLATED);

    @Test
    void offOrOtherPathsLeaveTheSettingsAlone() {
        BudgetHook hook = new BudgetHook();
        assertSame(USER, hook.apply(USER, new ViewState.Budget(false, 10)));
        assertNull(done(hook, frame(50)));
        RenderSettings perspective = USER.withMode(RenderMode.PERSPECTIVE);
        assertSame(perspective, hook.apply(perspective, new ViewState.Budget(true, 10)));
        assertNull(done(hook, frame(50)));
    }

    @Test
    void fastFramesTightenTheThresholdAndSlowOnesNeverPassTheCeiling() {
        BudgetHook hook = new BudgetHook();
        ViewState.Budget budget = new ViewState.Budget(true, 10);
        double ceiling = USER.tessellation().maxEdge();
        for (int i = 0; i < 40; i++) {
            RenderSettings s = hook.apply(USER, budget);
            assertEquals(s.tessellation().maxEdge(), done(hook, frame(2)).drawnAt());
        }
        double tightened = hook.apply(USER, budget).tessellation().maxEdge();
        assertTrue(tightened < ceiling, "fast frames buy finer pieces: " + tightened);
        for (int i = 0; i < 100; i++) {
            RenderSettings s = hook.apply(USER, budget);
            assertTrue(s.tessellation().maxEdge() <= ceiling);
            done(hook, frame(80));
        }
        assertEquals(ceiling, hook.apply(USER, budget).tessellation().maxEdge(), "slow frames: back to the ceiling");
    }

    @Test
    void followsTheErrorPolicyAndRestartsWhenTheCeilingMoves() {
        BudgetHook hook = new BudgetHook();
        ViewState.Budget budget = new ViewState.Budget(true, 10);
        RenderSettings error = USER.withTessellation(USER.tessellation().withPolicy(SplitPolicy.ERROR).withMaxError(2));
        for (int i = 0; i < 40; i++) {
            hook.apply(error, budget);
            done(hook, frame(2));
        }
        RenderSettings chosen = hook.apply(error, budget);
        assertTrue(chosen.tessellation().maxError() < 2);
        assertEquals(USER.tessellation().maxEdge(), chosen.tessellation().maxEdge(), "the other policy is untouched");
        RenderSettings lower = error.withTessellation(error.tessellation().withMaxError(1));
        assertEquals(1, hook.apply(lower, budget).tessellation().maxError(), "a new ceiling starts over from it");
    }

    @Test
    void thePieceBudgetIsAFloorAndTheChoiceSaysSo() {
        BudgetHook hook = new BudgetHook();
        ViewState.Budget generous = new ViewState.Budget(true, 40);
        double ceiling = USER.tessellation().maxEdge();
        ViewState.BudgetChoice last = null;
        for (int i = 0; i < 200; i++) {
            double edge = hook.apply(USER, generous).tessellation().maxEdge();
            // Pieces as 1000 + 4e7 / edge^2: 100,000 (the budget) at about 20 px; frames always fast.
            last = done(hook, frame(5, Math.round(1000 + 4e7 / (edge * edge))));
            assertTrue(1000 + 4e7 / (edge * edge) <= 100_000, "over the piece budget at " + edge + " px, frame " + i);
        }
        assertTrue(last.threshold() < ceiling, "it refined: " + last.threshold());
        assertEquals(BudgetController.Limit.PIECE_BUDGET, last.limit());
        assertEquals("piece budget", last.reason());
    }

    @Test
    void onTheDemoAGenerousTargetNeverDrivesAFrameOverItsPieceBudget() {
        // Any frame beats 10 s, so time alone would refine to the floor: the piece budget must stop it.
        SceneAsset demo = DemoScenes.demo();
        BudgetHook hook = new BudgetHook();
        ViewState.Budget generous = new ViewState.Budget(true, 10_000);
        Framebuffer fb = new Framebuffer(480, 270);
        ViewState.BudgetChoice last = null;
        try (FrameRenderer r = new FrameRenderer(2)) {
            for (int i = 0; i < 120; i++) {
                RenderSettings s = hook.apply(USER, generous);
                FrameStats st = r.render(demo.mesh(), demo.textureArray(),
                        demo.camera().viewProjection(new Viewport(480, 270)), s, fb);
                assertTrue(!st.budgetReached(), "frame " + i + " at " + s.tessellation().maxEdge() + " px: "
                        + (st.pieces() + st.piecesOffScreen()) + " pieces of " + st.pieceBudget());
                last = done(hook, st);
            }
        }
        assertEquals(BudgetController.Limit.PIECE_BUDGET, last.limit(), "held there by the budget");
        assertTrue(last.threshold() > BudgetController.floorFor(SplitPolicy.EDGE, 32), "above the floor: "
                + last.threshold());
    }

    @Test
    void theTargetIsTheWholeFrameWithTheComparisonSpreadOverTheFrames() {
        // Engine time 10 ms, but the whole frame (overlay, presenting) 30 ms, and one frame in 8 also
        // compares for 160 ms: the frame rate counts 30 + 160 / 8 = 50 ms a frame. A 40 ms target is met on
        // the engine's time alone, and must not be on what the user sees: the controller coarsens.
        BudgetHook hook = new BudgetHook();
        ViewState.Budget budget = new ViewState.Budget(true, 40);
        RenderSettings fine = USER.withTessellation(USER.tessellation().withMaxEdge(8));
        ViewState.BudgetChoice c = null;
        for (int i = 0; i < 200; i++) {
            hook.apply(fine, budget);
            boolean compares = i % 8 == 0;
            c = hook.frameDone(frame(10), compares ? 190 : 30, compares ? 160 : 0);
        }
        assertEquals(BudgetController.Limit.CEILING, c.limit(), "out of reach even at 8 px: " + c.why());
        assertTrue(c.medianMs() > 45 && c.medianMs() < 55, "the median seen is the frame rate's: " + c.medianMs());
        assertTrue(c.why().startsWith("out of reach: median frame"), c.why());
    }

    @Test
    void everyReasonAndChangeFollowsFromTheNumbersItShows() {
        BudgetHook hook = new BudgetHook();
        ViewState.Budget generous = new ViewState.Budget(true, 40);
        double lastThreshold = USER.tessellation().maxEdge();
        for (int i = 0; i < 300; i++) {
            double edge = hook.apply(USER, generous).tessellation().maxEdge();
            long pieces = Math.round(1000 + 4e7 / (edge * edge));
            ViewState.BudgetChoice c = hook.frameDone(frame(5, pieces), 5, 0);
            if (c.limit() == BudgetController.Limit.PIECE_BUDGET) {
                // A budget reason only when the budget binds: the frame filled more than the aim of it.
                assertTrue(c.pieces() > BudgetController.BUDGET_AIM * c.pieceBudget() * 0.99
                        || c.pieceFloor() >= c.threshold() * 0.99, c.why());
                assertTrue(c.why().contains(String.format(java.util.Locale.ROOT, "%,d of %,d pieces", c.pieces(),
                        c.pieceBudget())), c.why());
            }
            if (c.threshold() != lastThreshold) {
                // No jump without a stated reason, naming the jump itself.
                assertTrue(c.lastChange().startsWith(String.format(java.util.Locale.ROOT, "%.3f \u2192 %.3f px",
                        lastThreshold, c.threshold())), i + ": " + c.lastChange());
            }
            lastThreshold = c.threshold();
        }
    }
}
