package dev.trisect.cli;

import dev.trisect.base.internal.Counts;
import dev.trisect.base.internal.JsonObject;
import dev.trisect.perf.Sweep;
import dev.trisect.render.RenderMode;
import dev.trisect.render.SplitPolicy;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The lines {@code bench --sweep} prints: a table, or one JSON object per setting, each row printed as its
 * setting is measured, then a summary.
 */
final class SweepOutput {
    private final String scene;
    private final String size;
    private final int threads;
    /** The per-pixel path's median ms, the table's "vs pp" reference; set by its row. */
    private double reference = Double.NaN;

    SweepOutput(String scene, String size, int threads) {
        this.scene = scene;
        this.size = size;
        this.threads = threads;
    }

    /** The table's two header lines. */
    List<String> header(int frames) {
        return List.of(String.format(Locale.ROOT, "scene %s, %s, %s, %s per setting", scene, size,
                        Counts.of(threads, "thread"), Counts.of(frames, "frame")),
                String.format(Locale.ROOT, "%-12s %10s %10s %10s %12s %12s", "setting", "median ms", "vs pp",
                        "pieces", "max disp px", "p99 disp px"));
    }

    /**
     * One setting's row, printed as soon as it is measured: a table row, its time against the per-pixel
     * path's (which is measured first), or a JSON object.
     */
    String row(Sweep.Point p, boolean json) {
        if (p.mode() == RenderMode.PERSPECTIVE) {
            reference = p.times().medianMs();
        }
        if (json) {
            return new JsonObject()
                    .put("scene", scene)
                    .put("size", size)
                    .put("threads", threads)
                    .put("path", p.mode().id())
                    .put("policy", p.policy() == null ? null : name(p.policy()))
                    .put("threshold", p.threshold())
                    .put("frames", p.times().frames())
                    .put("median_ms", p.times().medianMs(), 3)
                    .put("min_ms", p.times().minMs(), 3)
                    .put("pieces", p.pieces())
                    .put("max_displacement", p.maxDisplacement(), 4)
                    .put("p99_displacement", p.p99Displacement(), 4)
                    .toString();
        }
        return String.format(Locale.ROOT, "%-12s %10.3f %9.2fx %10d %12.3f %12.3f", p.label(),
                p.times().medianMs(), p.times().medianMs() / reference, p.pieces(), p.maxDisplacement(),
                p.p99Displacement());
    }

    /** What follows the rows, drawn from all of them: each policy's break-even threshold. */
    List<String> summary(Sweep.Result r, boolean json) {
        if (json) {
            return List.of(new JsonObject()
                    .put("scene", scene)
                    .put("size", size)
                    .put("threads", threads)
                    .put("break_even_max_edge", r.breakEven(SplitPolicy.EDGE))
                    .put("break_even_max_error", r.breakEven(SplitPolicy.ERROR))
                    .put("break_even_spans_max_error", r.spansBreakEven())
                    .toString());
        }
        List<String> lines = new ArrayList<>();
        for (SplitPolicy policy : SplitPolicy.values()) {
            double t = r.breakEven(policy);
            lines.add(Double.isNaN(t)
                    ? String.format(Locale.ROOT, "%s policy: no threshold measured is as fast as the per-pixel path",
                    name(policy))
                    : String.format(Locale.ROOT, "%s policy: the finest threshold as fast as the per-pixel path is %s px",
                    name(policy), t));
        }
        double s = r.spansBreakEven();
        lines.add(Double.isNaN(s) ? "spans: no max error measured is as fast as the per-pixel path"
                : String.format(Locale.ROOT, "spans: the finest max error as fast as the per-pixel path is %s px", s));
        return lines;
    }

    private static String name(SplitPolicy policy) {
        return policy.id();
    }
}
