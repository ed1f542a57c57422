package dev.trisect.view.internal;

import dev.trisect.perf.BudgetController;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;

/**
 * The render loop's side of the frame-time budget: while the budget is on and the path is
 * tessellated, it replaces the user's threshold (of the chosen split policy) by the one a
 * {@link BudgetController} chooses, the user's threshold being the ceiling, and feeds the controller
 * each frame's engine time. A change of target, policy or ceiling starts a new controller from the
 * ceiling. Render thread only.
 */
public final class BudgetHook {
    private BudgetController controller;
    private SplitPolicy policy;

    /** The settings to render this frame with. */
    RenderSettings apply(RenderSettings user, ViewState.Budget budget) {
        if (!budget.on() || user.mode() != RenderMode.TESSELLATED) {
            controller = null;
            return user;
        }
        TessellationSettings t = user.tessellation();
        boolean edge = t.policy() == SplitPolicy.EDGE;
        double ceiling = edge ? t.maxEdge() : t.maxError();
        if (controller == null || policy != t.policy() || controller.ceiling() != ceiling
                || controller.targetMs() != budget.targetMs()) {
            controller = new BudgetController(budget.targetMs(), ceiling, BudgetController.defaultFloor(ceiling),
                    ceiling);
            policy = t.policy();
        }
        double chosen = controller.threshold();
        return user.withTessellation(edge ? t.withMaxEdge(chosen) : t.withMaxError(chosen));
    }

    /**
     * Feeds the engine time (milliseconds) of the frame just rendered with {@link #apply}'s settings;
     * returns the threshold that frame used, or NaN when the budget is off.
     */
    double frameDone(double engineMs) {
        if (controller == null) {
            return Double.NaN;
        }
        double used = controller.threshold();
        controller.update(engineMs);
        return used;
    }
}
