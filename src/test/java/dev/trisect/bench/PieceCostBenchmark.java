package dev.trisect.bench;

import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.Texture;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.AuxCounters;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * The cost of one extra piece on one core: the same frame (1280x720, one thread) drawn affinely and
 * tessellated. Both fill exactly the same pixels with the same depth tests, so the difference of the
 * two times is what tessellation adds: splitting, projecting, binning, setting up each piece and the
 * per-row overhead of filling many small triangles instead of few large ones. Divided by the
 * difference in pieces (printed by {@code trisect bench --json --threads 1 --size 1280x720}, or the
 * {@code pieces} line this benchmark prints at setup) it gives nanoseconds per extra piece;
 * scripts/performance.sh does the division.
 *
 * <p>On a shared machine the two averages drift apart by more than the difference itself, so
 * {@link #paired} measures it directly: each invocation draws the affine frame and then the
 * tessellated one, timing each by the thread's CPU time, and counts the difference
 * ({@code paired:extraNanos}) and the extra pieces ({@code paired:extraPieces}); JMH sums each
 * over the iterations, and their quotient is the cost of one extra piece (scripts/performance.sh
 * divides). Run with
 * {@code mvn -q test-compile exec:exec@jmh -Djmh.args="PieceCostBenchmark"}.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
@Warmup(iterations = 4, time = 2)
@Measurement(iterations = 8, time = 2)
@Fork(1)
public class PieceCostBenchmark {
    @Param({"demo", "floor"})
    public String scene;

    /** The tessellated path's policy: {@code edge} at 32 px or {@code error} at 0.5 px (the defaults). */
    @Param({"edge", "error"})
    public String policy;

    private FrameRenderer renderer;
    private Framebuffer frame;
    private SceneAsset s;
    private Texture[] textures;
    private Mat4 viewProjection;
    private RenderSettings affine;
    private RenderSettings tessellated;

    @Setup
    public void setUp() {
        s = DemoScenes.byName(scene).orElseThrow();
        textures = s.textureArray();
        frame = new Framebuffer(1280, 720);
        viewProjection = s.camera().viewProjection(new Viewport(1280, 720));
        affine = RenderSettings.defaults().withMode(RenderMode.AFFINE);
        tessellated = RenderSettings.defaults().withMode(RenderMode.TESSELLATED).withTessellation(
                TessellationSettings.defaults().withPolicy("error".equals(policy) ? SplitPolicy.ERROR : SplitPolicy.EDGE));
        renderer = new FrameRenderer(1);
        long a = render(affine).pieces();
        long t = render(tessellated).pieces();
        System.out.println("pieces " + scene + " " + policy + " affine " + a + " tessellated " + t);
    }

    private FrameStats render(RenderSettings settings) {
        return renderer.render(s.mesh(), textures, viewProjection, settings, frame);
    }

    @TearDown
    public void tearDown() {
        renderer.close();
    }

    @Benchmark
    public FrameStats affine() {
        return render(affine);
    }

    @Benchmark
    public FrameStats tessellated() {
        return render(tessellated);
    }

    /** The paired measurement's counters, per iteration: CPU nanoseconds and pieces the tessellated frames added. */
    @State(Scope.Thread)
    @AuxCounters(AuxCounters.Type.EVENTS)
    public static class PairedCost {
        private static final ThreadMXBean CPU = ManagementFactory.getThreadMXBean();
        public long extraNanos;
        public long extraPieces;

        @Setup(Level.Iteration)
        public void reset() {
            extraNanos = 0;
            extraPieces = 0;
        }
    }

    /** The affine and the tessellated frame back to back, their CPU time difference counted per extra piece. */
    @Benchmark
    public long paired(PairedCost cost) {
        long t0 = PairedCost.CPU.getCurrentThreadCpuTime();
        long a = render(affine).pieces();
        long t1 = PairedCost.CPU.getCurrentThreadCpuTime();
        long t = render(tessellated).pieces();
        long t2 = PairedCost.CPU.getCurrentThreadCpuTime();
        cost.extraNanos += (t2 - t1) - (t1 - t0);
        cost.extraPieces += t - a;
        return t;
    }
}
