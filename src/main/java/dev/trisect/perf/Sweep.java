package dev.trisect.perf;

import dev.trisect.content.SceneAsset;
import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.metrics.Comparison;
import dev.trisect.metrics.ImageComparison;
import dev.trisect.metrics.TexelToScreen;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.Texture;
import java.util.ArrayList;
import java.util.List;

/**
 * The cost/quality curve of the tessellated path and the span path: for a list of thresholds of each
 * split policy, the median frame time, the pieces, and the exact displacement against the per-pixel
 * perspective frame (largest and 99th percentile, pixels; see {@link ImageComparison}), and the same
 * for the span path at each max error of the error policy's list, with the per-pixel and affine paths
 * measured the same way as reference points.
 */
public final class Sweep {
    /** Default thresholds of the edge policy: longest piece edge, pixels. */
    public static final List<Double> DEFAULT_EDGES = List.of(8.0, 16.0, 24.0, 32.0, 48.0, 64.0, 128.0, 256.0);
    /** Default thresholds of the error policy: largest affine displacement, pixels. */
    public static final List<Double> DEFAULT_ERRORS = List.of(0.125, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0);

    /**
     * One measured setting.
     *
     * @param mode             the path
     * @param policy           the split policy (tessellated path only, else null)
     * @param threshold        the policy's threshold, or the span path's max error, pixels (NaN for the
     *                         per-pixel and affine paths)
     * @param times            frame times
     * @param pieces           triangles filled per frame
     * @param maxDisplacement  largest exact displacement against the per-pixel frame, pixels
     * @param p99Displacement  its 99th percentile, pixels
     */
    public record Point(RenderMode mode, SplitPolicy policy, double threshold, FrameTimes times, long pieces,
                        double maxDisplacement, double p99Displacement) {
        /** Short label: the path, or the policy (or spans) and threshold. */
        public String label() {
            if (policy == null) {
                return Double.isNaN(threshold) ? mode.id() : mode.id() + " " + threshold;
            }
            return policy.id() + " " + threshold;
        }
    }

    /**
     * The whole sweep.
     *
     * @param perspective the per-pixel path (the reference: displacement 0)
     * @param affine      the affine path
     * @param points      the tessellated settings, edge policy first, each policy's thresholds ascending,
     *                    then the span path's, max errors ascending
     */
    public record Result(Point perspective, Point affine, List<Point> points) {
        /** The points of one policy, thresholds ascending. */
        public List<Point> of(SplitPolicy policy) {
            return points.stream().filter(p -> p.policy() == policy).toList();
        }

        /** The span path's points, max errors ascending. */
        public List<Point> spans() {
            return points.stream().filter(p -> p.mode() == RenderMode.SPANS).toList();
        }

        /**
         * The finest max error of the span path whose median frame time is at most the per-pixel path's,
         * or NaN when none is.
         */
        public double spansBreakEven() {
            return breakEven(spans());
        }

        /**
         * The finest threshold of {@code policy} (most pieces, least displacement) whose median frame
         * time is at most the per-pixel path's, or NaN when none is.
         */
        public double breakEven(SplitPolicy policy) {
            return breakEven(of(policy));
        }

        private double breakEven(List<Point> ascending) {
            for (Point p : ascending) {
                if (p.times().medianMs() <= perspective.times().medianMs()) {
                    return p.threshold();
                }
            }
            return Double.NaN;
        }
    }

    private Sweep() {
    }

    /**
     * Runs the sweep.
     *
     * @param base     settings whose cull, background and caps are kept; mode and thresholds are set here
     * @param edges    edge-policy thresholds, pixels, each &gt; 0 (sorted here)
     * @param errors   error-policy thresholds, and the span path's max errors, pixels, each &gt; 0 (sorted here)
     * @param progress told after every frame of the whole sweep
     * @param measured told each point as soon as it is measured, in the order of the result: the per-pixel
     *                 path, the affine path, then the points
     */
    public static Result run(FrameRenderer renderer, SceneAsset scene, Texture[] textures, Mat4 viewProjection,
                             int width, int height, RenderSettings base, List<Double> edges, List<Double> errors,
                             int warmup, int frames, FrameBench.Progress progress,
                             java.util.function.Consumer<Point> measured) {
        List<Double> e = sortedPositive(edges, "edge");
        List<Double> r = sortedPositive(errors, "error");
        int settingsCount = settingsCount(e, r);
        int perSetting = warmup + frames + 1;
        int total = settingsCount * perSetting;
        FrameBench bench = new FrameBench(renderer, scene, textures, viewProjection, new Framebuffer(width, height));
        Framebuffer reference = new Framebuffer(width, height);
        reference.recordUv(true);
        Framebuffer test = new Framebuffer(width, height);
        test.recordUv(true);
        renderer.render(scene.mesh(), textures, viewProjection,
                base.withMode(RenderMode.PERSPECTIVE).withBorders(false), reference);
        TexelToScreen exact = new TexelToScreen(scene.mesh(), textures, viewProjection, new Viewport(width, height));
        int[] done = {0};
        Measure measure = (settings, policy, threshold) -> {
            int offset = done[0];
            FrameBench.Result timed = bench.time(settings, warmup, frames,
                    (d, t) -> progress.frameDone(offset + d, total));
            renderer.render(scene.mesh(), textures, viewProjection, settings, test);
            Comparison c = ImageComparison.compare(width, height, test.colour(), test.uv(), reference.colour(),
                    reference.uv(), exact, null);
            done[0] += perSetting;
            progress.frameDone(done[0], total);
            Point p = new Point(settings.mode(), policy, threshold, timed.times(), timed.last().pieces(),
                    c.maxDisplacement(), c.p99Displacement());
            measured.accept(p);
            return p;
        };
        RenderSettings plain = base.withBorders(false);
        Point perspective = measure.run(plain.withMode(RenderMode.PERSPECTIVE), null, Double.NaN);
        Point affine = measure.run(plain.withMode(RenderMode.AFFINE), null, Double.NaN);
        List<Point> points = new ArrayList<>();
        TessellationSettings t = base.tessellation();
        for (double edge : e) {
            points.add(measure.run(plain.withMode(RenderMode.TESSELLATED).withTessellation(
                    t.withPolicy(SplitPolicy.EDGE).withMaxEdge(edge)), SplitPolicy.EDGE, edge));
        }
        for (double error : r) {
            points.add(measure.run(plain.withMode(RenderMode.TESSELLATED).withTessellation(
                    t.withPolicy(SplitPolicy.ERROR).withMaxError(error)), SplitPolicy.ERROR, error));
        }
        for (double error : r) {
            points.add(measure.run(plain.withMode(RenderMode.SPANS).withKnotError(error), null,
                    error));
        }
        return new Result(perspective, affine, List.copyOf(points));
    }

    /**
     * How many settings a sweep of these thresholds measures: the per-pixel and affine paths, each distinct
     * edge threshold, and each distinct error threshold twice (tessellated and spans).
     *
     * @param edges  edge-policy thresholds, pixels
     * @param errors error-policy thresholds, pixels
     * @return the number of settings
     */
    public static int settingsCount(List<Double> edges, List<Double> errors) {
        return 2 + (int) edges.stream().distinct().count() + 2 * (int) errors.stream().distinct().count();
    }

    @FunctionalInterface
    private interface Measure {
        Point run(RenderSettings settings, SplitPolicy policy, double threshold);
    }

    private static List<Double> sortedPositive(List<Double> values, String what) {
        for (double v : values) {
            if (!(v > 0) || !Double.isFinite(v)) {
                throw new IllegalArgumentException(what + " thresholds must be positive and finite, got " + v);
            }
        }
        return values.stream().sorted().distinct().toList();
    }
}
