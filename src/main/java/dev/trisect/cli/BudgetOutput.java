package dev.trisect.cli;

import dev.trisect.base.internal.Counts;
import dev.trisect.base.internal.JsonObject;
import dev.trisect.perf.BudgetController;
import dev.trisect.perf.BudgetRun;
import dev.trisect.perf.FrameTimes;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * The lines {@code bench --target-ms} prints: every frame's threshold, time and pieces (a table, or one
 * JSON object per frame), then a summary of the second half of the run, where the controller has had
 * time to settle.
 */
final class BudgetOutput {
    private final String scene;
    private final String size;
    private final int threads;

    BudgetOutput(String scene, String size, int threads) {
        this.scene = scene;
        this.size = size;
        this.threads = threads;
    }

    /** What held the controller, as the table and JSON name it: target, ceiling, floor or pieces. */
    static String heldBy(BudgetController.Limit l) {
        return l == BudgetController.Limit.PIECE_BUDGET ? "pieces" : l.name().toLowerCase(Locale.ROOT);
    }

    List<String> lines(BudgetRun.Trace t, boolean json) {
        List<String> lines = new ArrayList<>();
        String policy = t.policy().id();
        int n = t.ms().length;
        if (!json) {
            lines.add(String.format(Locale.ROOT, "scene %s, %s, %s, target %.3f ms, %s policy, ceiling %s px",
                    scene, size, Counts.of(threads, "thread"), t.targetMs(), policy, t.ceiling()));
            lines.add(String.format(Locale.ROOT, "%6s %12s %10s %10s %6s %8s", "frame", "threshold", "ms", "pieces",
                    "over", "held_by"));
        }
        for (int i = 0; i < n; i++) {
            lines.add(json
                    ? new JsonObject().put("frame", i).put("threshold", t.thresholds()[i], 4)
                    .put("ms", t.ms()[i], 3).put("pieces", t.pieces()[i]).put("budget_reached", t.overBudget()[i])
                    .put("held_by", heldBy(t.heldBy()[i])).toString()
                    : String.format(Locale.ROOT, "%6d %12.4f %10.3f %10d %6s %8s", i, t.thresholds()[i], t.ms()[i],
                    t.pieces()[i], t.overBudget()[i] ? "over" : "-", heldBy(t.heldBy()[i])));
        }
        int half = n / 2;
        FrameTimes late = FrameTimes.of(Arrays.copyOfRange(t.ms(), half, n));
        double[] thresholds = Arrays.copyOfRange(t.thresholds(), half, n);
        Arrays.sort(thresholds);
        double medianThreshold = thresholds[thresholds.length / 2];
        if (json) {
            lines.add(new JsonObject()
                    .put("scene", scene).put("size", size).put("threads", threads).put("policy", policy)
                    .put("target_ms", t.targetMs(), 3).put("ceiling", t.ceiling())
                    .put("second_half_median_ms", late.medianMs(), 3)
                    .put("second_half_median_threshold", medianThreshold, 4)
                    .put("final_threshold", t.thresholds()[n - 1], 4)
                    .put("piece_budget", t.pieceBudget())
                    .put("frames_over_piece_budget", t.framesOverBudget())
                    .put("second_half_reversals", t.reversals(half))
                    .toString());
        } else {
            lines.add(String.format(Locale.ROOT, "second half: median %.3f ms (target %.3f), median threshold %.4f px,"
                    + " final %.4f px", late.medianMs(), t.targetMs(), medianThreshold, t.thresholds()[n - 1]));
            lines.add(String.format(Locale.ROOT, "frames over the piece budget (%d): %d of %d; threshold reversals in "
                    + "the second half: %d", t.pieceBudget(), t.framesOverBudget(), n, t.reversals(half)));
        }
        return lines;
    }
}
