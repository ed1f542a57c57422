package dev.trisect.view.internal;

import dev.trisect.render.FrameStats;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import java.util.Locale;

/** The status bar's warning when a frame hit a cap or its time budget; null when all is well. */
public final class Warnings {
    private Warnings() {
    }

    /**
     * @param stats  the frame on screen
     * @param budget the frame-time budget
     * @param chosen the threshold the budget controller used, pixels (NaN when off)
     * @param t      the user's split settings (their threshold is the controller's ceiling)
     */
    static String of(FrameStats stats, ViewState.Budget budget, double chosen, TessellationSettings t) {
        StringBuilder w = new StringBuilder();
        if (stats.capsReached() > 0) {
            w.append(String.format(Locale.ROOT, "Cap reached on %d triangle%s: %d piece%s filled per pixel "
                    + "(slivers included; outlined in magenta with the borders, B)", stats.capsReached(), stats.capsReached() == 1 ? "" : "s",
                    stats.piecesFallback(), stats.piecesFallback() == 1 ? "" : "s"));
        }
        double ceiling = t.policy() == SplitPolicy.EDGE ? t.maxEdge() : t.maxError();
        double engineMs = stats.totalNanos() / 1e6;
        if (budget.on() && chosen >= ceiling * (1 - 1e-9) && engineMs > budget.targetMs()) {
            if (w.length() > 0) {
                w.append(". ");
            }
            w.append(String.format(Locale.ROOT, "Over budget: %.1f ms against %.1f ms even at your threshold "
                    + "(%.2f px)", engineMs, budget.targetMs(), ceiling));
        }
        return w.length() == 0 ? null : "\u26a0 " + w;
    }
}
