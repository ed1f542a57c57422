package dev.trisect.view.internal;

import dev.trisect.perf.BudgetController;
import dev.trisect.render.FrameStats;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import java.util.Locale;

/**
 * The render loop's side of the frame-time budget: while the budget is on and the path is
 * tessellated, it replaces the user's threshold (of the chosen split policy) by the one a
 * {@link BudgetController} chooses, the user's threshold being the ceiling, and feeds the controller
 * each frame's whole time — from one frame's start to the next, overlay, the developer tools'
 * measuring and presenting included: the time the status bar's frames per second count — so that the
 * target is the frame time the user sees. The comparison with the per-pixel path runs on one frame in
 * several and costs several frames' time: its cost is spread over the frames (a running mean), so that
 * the controller's median sees it, as the frame rate does. A change of target, policy or ceiling starts
 * a new controller from the ceiling. The frame's piece budget is a floor on the threshold it chooses
 * ({@link BudgetController#update(double, long, long, boolean)}). Every change of threshold is
 * explained ({@link ViewState.BudgetChoice#lastChange}). Render thread only.
 */
public final class BudgetHook {
    /** Frames the comparison's cost is spread over (the weight of a running mean). */
    static final int COMPARE_FRAMES = 16;

    private BudgetController controller;
    private SplitPolicy policy;
    private double targetMs;
    private double compareMeanMs;
    private String lastChange = "";
    private long frames;

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
            lastChange = String.format(Locale.ROOT, "started at your threshold, %.3f px", ceiling);
        }
        double chosen = controller.threshold();
        return user.withTessellation(t.policy().withThreshold(t, chosen));
    }

    /**
     * Feeds a frame drawn with {@link #apply}'s settings to the controller, once its whole time is known;
     * returns the threshold chosen for the next frame and why, or null when the budget is off.
     *
     * @param stats     the frame's statistics (its pieces and piece budget)
     * @param wholeMs   the frame's whole time, start to the next frame's start, milliseconds
     * @param compareMs the part of it the comparison with the per-pixel path took (0 on most frames)
     */
    ViewState.BudgetChoice frameDone(FrameStats stats, double wholeMs, double compareMs) {
        if (controller == null) {
            return null;
        }
        frames++;
        compareMeanMs += (compareMs - compareMeanMs) / Math.min(frames, COMPARE_FRAMES);
        double seenMs = wholeMs - compareMs + compareMeanMs;
        long pieces = stats.pieces() + stats.piecesOffScreen();
        double used = controller.threshold();
        controller.update(seenMs, pieces, stats.pieceBudget(), stats.budgetReached());
        double next = controller.threshold();
        if (next != used) {
            lastChange = change(used, next, controller, pieces, stats.pieceBudget());
        }
        // All of one moment: the threshold chosen now, what holds it, and the frame that decided it.
        return new ViewState.BudgetChoice(next, controller.limit(), controller.lastMedianMs(), targetMs,
                controller.ceiling(), used, pieces, stats.pieceBudget(), controller.pieceFloor(), lastChange);
    }

    /** Why the threshold went from {@code from} to {@code to} (the controller's state just after). */
    private static String change(double from, double to, BudgetController c, long pieces, long budget) {
        String move = String.format(Locale.ROOT, "%.3f \u2192 %.3f px", from, to);
        if (c.limit() == BudgetController.Limit.PIECE_BUDGET && to > from) {
            return String.format(Locale.ROOT, "%s: %,d pieces, over %.0f %% of the %,d-piece budget", move, pieces,
                    100 * BudgetController.BUDGET_HIGH, budget);
        }
        return String.format(Locale.ROOT, "%s: median frame %.1f ms %s the %.1f ms target", move, c.lastMedianMs(),
                c.lastMedianMs() > c.targetMs() ? "over" : "under", c.targetMs());
    }
}
