package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import org.junit.jupiter.api.Test;

/** The demo's budget hook: it changes only the tessellated threshold, within the user's ceiling. */
class BudgetHookTest {
    private static double frame(double ms) {
        return ms;
    }

    private static final RenderSettings USER = RenderSettings.defaults().withMode(RenderMode.TESSELLATED);

    @Test
    void offOrOtherPathsLeaveTheSettingsAlone() {
        BudgetHook hook = new BudgetHook();
        assertSame(USER, hook.apply(USER, new ViewState.Budget(false, 10)));
        assertTrue(Double.isNaN(hook.frameDone(frame(50))));
        RenderSettings perspective = USER.withMode(RenderMode.PERSPECTIVE);
        assertSame(perspective, hook.apply(perspective, new ViewState.Budget(true, 10)));
        assertTrue(Double.isNaN(hook.frameDone(frame(50))));
    }

    @Test
    void fastFramesTightenTheThresholdAndSlowOnesNeverPassTheCeiling() {
        BudgetHook hook = new BudgetHook();
        ViewState.Budget budget = new ViewState.Budget(true, 10);
        double ceiling = USER.tessellation().maxEdge();
        for (int i = 0; i < 40; i++) {
            RenderSettings s = hook.apply(USER, budget);
            assertEquals(s.tessellation().maxEdge(), hook.frameDone(frame(2)));
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
}
