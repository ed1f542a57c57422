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
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
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
 * Time of one whole frame (transform to overlay) of a built-in scene at 1280x720, per path (spans at
 * the default max error, 0.5 px), split policy and thread count. Run with {@code mvn -q test-compile exec:exec@jmh}; not part of the tests.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 4, time = 2)
@Measurement(iterations = 6, time = 2)
@Fork(1)
public class FrameBenchmark {
    @Param({"demo", "floor"})
    public String scene;

    @Param({"perspective", "affine", "tessellated", "tessellated-error", "spans"})
    public String path;

    @Param({"1", "2"})
    public int threads;

    private FrameRenderer renderer;
    private Framebuffer frame;
    private SceneAsset s;
    private Texture[] textures;
    private Mat4 viewProjection;
    private RenderSettings settings;

    @Setup
    public void setUp() {
        s = DemoScenes.byName(scene).orElseThrow();
        textures = s.textureArray();
        frame = new Framebuffer(1280, 720);
        viewProjection = s.camera().viewProjection(new Viewport(1280, 720));
        boolean error = path.endsWith("-error");
        RenderMode mode = RenderMode.valueOf(path.replace("-error", "").toUpperCase(Locale.ROOT));
        settings = RenderSettings.defaults().withMode(mode).withTessellation(
                TessellationSettings.defaults().withPolicy(error ? SplitPolicy.ERROR : SplitPolicy.EDGE));
        renderer = new FrameRenderer(threads);
    }

    @TearDown
    public void tearDown() {
        renderer.close();
    }

    @Benchmark
    public FrameStats frame() {
        return renderer.render(s.mesh(), textures, viewProjection, settings, frame);
    }
}
