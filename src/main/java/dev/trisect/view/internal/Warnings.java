package dev.trisect.view.internal;

import dev.trisect.perf.BudgetController;
import dev.trisect.render.FrameStats;
import java.util.Locale;

/**
 * The status bar's warning when a frame hit a cap, skipped triangles it could not place, or missed its
 * time budget; null when all is well.
 */
public final class Warnings {
    private Warnings() {
    }

    /**
     * @param stats  the frame on screen
     * @param choice what the budget controller chose for it, or null when the budget is off
     */
    static String of(FrameStats stats, ViewState.BudgetChoice choice) {
        StringBuilder w = new StringBuilder();
        if (stats.capsReached() > 0) {
            w.append(String.format(Locale.ROOT, "Cap reached on %d triangle%s: %d piece%s filled per pixel "
                    + "(slivers included; outlined in magenta with the borders, B)", stats.capsReached(),
                    stats.capsReached() == 1 ? "" : "s", stats.piecesFallback(), stats.piecesFallback() == 1 ? "" : "s"));
        }
        // Never silently: triangles the renderer could not place (as the command line notes them).
        String skipped = stats.skippedNote();
        if (skipped != null) {
            if (w.length() > 0) {
                w.append(". ");
            }
            w.append(Character.toUpperCase(skipped.charAt(0))).append(skipped.substring(1));
        }
        // Said only when the controller itself found the target out of reach: then the threshold it chose,
        // which the tools show, is the ceiling named here.
        if (choice != null && choice.limit() == BudgetController.Limit.CEILING) {
            if (w.length() > 0) {
                w.append(". ");
            }
            w.append(String.format(Locale.ROOT, "Over budget: median %.1f ms against %.1f ms even at your threshold "
                    + "(%.2f px), the loosest Auto may choose", choice.medianMs(), choice.targetMs(), choice.threshold()));
        }
        return w.length() == 0 ? null : "\u26a0 " + w;
    }
}
