package dev.trisect.perf;

import dev.trisect.content.SceneAsset;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.scene.Camera;
import dev.trisect.texture.Texture;

/**
 * Renders frames of the tessellated path with a {@link BudgetController} choosing the threshold of
 * the settings' split policy each frame, the settings' own threshold being the ceiling; optionally
 * while the camera orbits its target once, so the load changes under the controller.
 */
public final class BudgetRun {
    /**
     * What each measured frame did.
     *
     * @param thresholds the threshold each frame was rendered with, pixels
     * @param ms         each frame's wall-clock time, milliseconds
     * @param pieces     each frame's pieces (filled and dropped off screen: what the piece budget counts)
     * @param overBudget whether each frame went over its piece budget (and was redone with a lower depth cap)
     * @param pieceBudget the frames' piece budget
     * @param heldBy     what held the controller where it chose each frame's threshold
     */
    public record Trace(SplitPolicy policy, double targetMs, double ceiling, double[] thresholds, double[] ms,
                        long[] pieces, boolean[] overBudget, long pieceBudget, BudgetController.Limit[] heldBy) {
        /** Frames that went over their piece budget. */
        public int framesOverBudget() {
            int n = 0;
            for (boolean b : overBudget) {
                n += b ? 1 : 0;
            }
            return n;
        }

        /** Times the threshold turned from falling to rising or back, from frame {@code from} on. */
        public int reversals(int from) {
            int n = 0;
            int last = 0;
            for (int i = Math.max(1, from + 1); i < thresholds.length; i++) {
                int d = Double.compare(thresholds[i], thresholds[i - 1]);
                if (d != 0) {
                    n += last != 0 && d != last ? 1 : 0;
                    last = d;
                }
            }
            return n;
        }
    }

    private BudgetRun() {
    }

    /**
     * @param settings tessellated settings; their policy's threshold is the ceiling and the start
     * @param orbit    whether the camera circles its target (about the up axis) once over the frames
     */
    public static Trace run(FrameRenderer renderer, SceneAsset scene, Texture[] textures, Camera camera, int width,
                            int height, RenderSettings settings, double targetMs, boolean orbit, int warmup,
                            int frames, FrameBench.Progress progress) {
        RenderSettings base = settings.withMode(RenderMode.TESSELLATED);
        TessellationSettings t = base.tessellation();
        SplitPolicy policy = t.policy();
        double ceiling = policy.threshold(t);
        BudgetController controller = new BudgetController(targetMs, ceiling, BudgetController.floorFor(policy, ceiling),
                ceiling);
        Framebuffer frame = new Framebuffer(width, height);
        Viewport viewport = new Viewport(width, height);
        for (int i = 0; i < warmup; i++) {
            renderer.render(scene.mesh(), textures, camera.viewProjection(viewport), base, frame);
            progress.frameDone(i + 1, warmup + frames);
        }
        double[] thresholds = new double[frames];
        double[] ms = new double[frames];
        long[] pieces = new long[frames];
        boolean[] over = new boolean[frames];
        BudgetController.Limit[] heldBy = new BudgetController.Limit[frames];
        long pieceBudget = 0;
        for (int i = 0; i < frames; i++) {
            double threshold = controller.threshold();
            RenderSettings s = base.withTessellation(policy.withThreshold(t, threshold));
            Camera c = orbit ? orbit(camera, 2 * Math.PI * i / frames) : camera;
            long t0 = System.nanoTime();
            FrameStats stats = renderer.render(scene.mesh(), textures, c.viewProjection(viewport), s, frame);
            ms[i] = (System.nanoTime() - t0) / 1e6;
            thresholds[i] = threshold;
            heldBy[i] = controller.limit();
            pieces[i] = stats.pieces() + stats.piecesOffScreen();
            over[i] = stats.budgetReached();
            pieceBudget = stats.pieceBudget();
            controller.update(ms[i], pieces[i], pieceBudget, over[i]);
            progress.frameDone(warmup + i + 1, warmup + frames);
        }
        return new Trace(t.policy(), targetMs, ceiling, thresholds, ms, pieces, over, pieceBudget, heldBy);
    }

    /** The camera with its eye turned by {@code angle} radians about the vertical through its target. */
    static Camera orbit(Camera camera, double angle) {
        Vec3 d = camera.eye().sub(camera.target());
        double cos = Math.cos(angle);
        double sin = Math.sin(angle);
        Vec3 eye = camera.target().add(new Vec3(d.x() * cos + d.z() * sin, d.y(), -d.x() * sin + d.z() * cos));
        return new Camera(eye, camera.target(), camera.up(), camera.fovY(), camera.near(), camera.far());
    }
}
