package dev.trisect.perf;

import dev.trisect.content.SceneAsset;
import dev.trisect.math.Mat4;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.internal.BlendOrder;
import dev.trisect.texture.Texture;

/**
 * Times frames of one scene from one camera: a warm-up (so the JIT has compiled the hot loops), then
 * frames measured one by one with the wall clock. Not thread-safe; one run at a time.
 */
public final class FrameBench {
    /** Told after every frame, warm-up included: which of how many frames (warm-up first) is done. */
    @FunctionalInterface
    public interface Progress {
        void frameDone(int done, int total);

        /** Reports nothing. */
        Progress NONE = (done, total) -> { };
    }

    /** What one timed run gave: the times and the statistics of its last frame. */
    public record Result(FrameTimes times, FrameStats last) {
    }

    private final FrameRenderer renderer;
    private final Draws draws;
    private final Framebuffer frame;

    /**
     * @param textures       the texture of each material, by material index
     * @param viewProjection world space to clip space
     * @param frame          the frame to draw into, whose size is the benchmark's
     */
    public FrameBench(FrameRenderer renderer, SceneAsset scene, Texture[] textures, Mat4 viewProjection,
                      Framebuffer frame) {
        this(renderer, one(scene, textures, viewProjection), frame);
    }

    /**
     * @param draws what to draw, with its lights and fog
     * @param frame the frame to draw into, whose size is the benchmark's
     */
    public FrameBench(FrameRenderer renderer, Draws draws, Framebuffer frame) {
        this.renderer = renderer;
        this.draws = draws;
        this.frame = frame;
    }

    private static Draws one(SceneAsset scene, Texture[] textures, Mat4 viewProjection) {
        Draws d = new Draws();
        d.add(scene.mesh(), textures, BlendOrder.states(textures), viewProjection);
        if (!scene.lines().isEmpty()) {
            d.addLines(scene.lines(), viewProjection, 1);
        }
        return d;
    }

    /** The frame drawn into (it holds the last frame rendered). */
    public Framebuffer frame() {
        return frame;
    }

    /** Renders one frame with these settings, untimed. */
    public FrameStats render(RenderSettings settings) {
        return renderer.render(draws, settings, frame);
    }

    /**
     * Times this bench's draws and {@code without} (the same draws less what is measured, such as their
     * lines) frame by frame in turn, into the same frame, so that the machine's drift and load fall on
     * both alike: their difference is what the extra costs.
     *
     * @param prepare run before each frame of this bench's draws, inside its time (a layout that a frame
     *                of a view makes each time, such as its labels'); null for nothing
     * @return the times of this bench's draws, then those of {@code without}
     */
    public Result[] timeAlternately(Draws without, RenderSettings settings, int warmup, int frames,
                                    Progress progress, Runnable prepare) {
        if (frames < 1 || warmup < 0) {
            throw new IllegalArgumentException("frames must be at least 1 and warmup at least 0");
        }
        int total = 2 * (warmup + frames);
        double[][] ms = new double[2][frames];
        FrameStats[] last = new FrameStats[2];
        for (int i = 0; i < warmup + frames; i++) {
            for (int k = 0; k < 2; k++) {
                long t0 = System.nanoTime();
                if (k == 0 && prepare != null) {
                    prepare.run();
                }
                last[k] = renderer.render(k == 0 ? draws : without, settings, frame);
                if (i >= warmup) {
                    ms[k][i - warmup] = (System.nanoTime() - t0) / 1e6;
                }
                progress.frameDone(2 * i + k + 1, total);
            }
        }
        return new Result[] {new Result(FrameTimes.of(ms[0]), last[0]), new Result(FrameTimes.of(ms[1]), last[1])};
    }

    /** Renders {@code warmup} frames, then times {@code frames} frames (at least 1). */
    public Result time(RenderSettings settings, int warmup, int frames, Progress progress) {
        if (frames < 1 || warmup < 0) {
            throw new IllegalArgumentException("frames must be at least 1 and warmup at least 0");
        }
        int total = warmup + frames;
        FrameStats last = null;
        for (int i = 0; i < warmup; i++) {
            last = render(settings);
            progress.frameDone(i + 1, total);
        }
        double[] ms = new double[frames];
        for (int i = 0; i < frames; i++) {
            long t0 = System.nanoTime();
            last = render(settings);
            ms[i] = (System.nanoTime() - t0) / 1e6;
            progress.frameDone(warmup + i + 1, total);
        }
        return new Result(FrameTimes.of(ms), last);
    }
}
