package dev.trisect.view.internal;

import dev.trisect.perf.BudgetController;
import dev.trisect.render.FrameStats;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;

/**
 * The render loop's side of the frame-time budget: while the budget is on and the path is
 * tessellated, it replaces the user's threshold (of the chosen split policy) by the one a
 * {@link BudgetController} chooses, the user's threshold being the ceiling, and feeds the controller
 * each frame's engine time. A change of target, policy or ceiling starts a new controller from the
 * ceiling. The frame's piece budget is a floor on the threshold it chooses
 * ({@link BudgetController#update(double, long, long, boolean)}). Render thread only.
 */
public final class BudgetHook {
    private BudgetController controller;
    private SplitPolicy policy;
    private double targetMs;

    /** The settings to render this frame with. */
    RenderSettings apply(RenderSettings user, ViewState.Budget budget) {
        if (!budget.on() || !user.mode().splits()) {
            controller = null;
            return user;
        }
        TessellationSettings t = user.tessellation();
        double ceiling = t.policy().threshold(t);
        if (controller == null || policy != t.policy() || controller.ceiling() != ceiling
                || controller.targetMs() != budget.targetMs()) {
            controller = new BudgetController(budget.targetMs(), ceiling, BudgetController.floorFor(t.policy(), ceiling),
                    ceiling);
            policy = t.policy();
            targetMs = budget.targetMs();
        }
        double chosen = controller.threshold();
        return user.withTessellation(t.policy().withThreshold(t, chosen));
    }

    /**
     * Feeds the frame just rendered with {@link #apply}'s settings (its engine time, pieces and piece
     * budget) to the controller; returns the threshold that frame used and why, or null when the
     * budget is off.
     */
    ViewState.BudgetChoice frameDone(FrameStats stats) {
        if (controller == null) {
            return null;
        }
        ViewState.BudgetChoice used = new ViewState.BudgetChoice(controller.threshold(), controller.limit(),
                controller.lastMedianMs(), targetMs, controller.ceiling());
        controller.update(stats.totalNanos() / 1e6, stats.pieces() + stats.piecesOffScreen(), stats.pieceBudget(),
                stats.budgetReached());
        return used;
    }
}
