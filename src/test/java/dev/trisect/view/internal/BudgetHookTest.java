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

    private static final RenderSettings USER = RenderSettings.defaults().withMode(RenderMode.TESSELLATED);

    @Test
    void offOrOtherPathsLeaveTheSettingsAlone() {
        BudgetHook hook = new BudgetHook();
        assertSame(USER, hook.apply(USER, new ViewState.Budget(false, 10)));
        assertNull(hook.frameDone(frame(50)));
        RenderSettings perspective = USER.withMode(RenderMode.PERSPECTIVE);
        assertSame(perspective, hook.apply(perspective, new ViewState.Budget(true, 10)));
        assertNull(hook.frameDone(frame(50)));
    }

    @Test
    void fastFramesTightenTheThresholdAndSlowOnesNeverPassTheCeiling() {
        BudgetHook hook = new BudgetHook();
        ViewState.Budget budget = new ViewState.Budget(true, 10);
        double ceiling = USER.tessellation().maxEdge();
        for (int i = 0; i < 40; i++) {
            RenderSettings s = hook.apply(USER, budget);
            assertEquals(s.tessellation().maxEdge(), hook.frameDone(frame(2)).threshold());
        }
        double tightened = hook.apply(USER, budget).tessellation().maxEdge();
        assertTrue(tightened < ceiling, "fast frames buy finer pieces: " + tightened);
        for (int i = 0; i < 100; i++) {
            RenderSettings s = hook.apply(USER, budget);
            assertTrue(s.tessellation().maxEdge() <= ceiling);
            hook.frameDone(frame(80));
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
            hook.frameDone(frame(2));
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
            last = hook.frameDone(frame(5, Math.round(1000 + 4e7 / (edge * edge))));
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
                last = hook.frameDone(st);
            }
        }
        assertEquals(BudgetController.Limit.PIECE_BUDGET, last.limit(), "held there by the budget");
        assertTrue(last.threshold() > BudgetController.floorFor(SplitPolicy.EDGE, 32), "above the floor: "
                + last.threshold());
    }
}
