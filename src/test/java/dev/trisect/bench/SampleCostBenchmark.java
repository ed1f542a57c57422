package dev.trisect.bench;

import dev.trisect.raster.Rasterizer;
import dev.trisect.raster.ScreenTriangles;
import dev.trisect.render.Framebuffer;
import dev.trisect.texture.internal.LaneSampler;
import dev.trisect.texture.internal.Lod;
import dev.trisect.texture.MipChain;
import dev.trisect.texture.ProceduralTextures;
import dev.trisect.texture.internal.Sampler;
import dev.trisect.texture.internal.TexelLanes;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * What a filtered pixel costs on one core, in nanoseconds per pixel, to set against the budget the
 * per-pixel speed target leaves (docs/performance/filtering.md, "Texture filtering").
 *
 * <p>The scene is a floor seen from just above it filling a 1920x1080 frame (two triangles, every
 * pixel covered once, the 512-texel UV grid repeated, lambda from below 0 at the bottom to about 5 at
 * the top), as in the demo's floor. The {@code fill*} benchmarks fill it with the rasterizer, one
 * thread, with the depth buffer cleared first ({@code clear} alone is measured too, to subtract); the
 * {@code sample*} and {@code lod} benchmarks run only the sampler or the level of detail, on the
 * positions of every eighth row of that frame, precomputed, so they are the bare cost of one sample.
 * Run with {@code mvn -q test-compile exec:exec@jmh -Djmh.args="SampleCostBenchmark"}.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 4, time = 2)
@Measurement(iterations = 6, time = 2)
@Fork(1)
public class SampleCostBenchmark {
    private static final int W = 1920;
    private static final int H = 1080;
    private static final int PIXELS = W * H;
    private static final int ROW_STEP = 8;
    private static final int SAMPLES = W * (H / ROW_STEP);

    private final Framebuffer frame = new Framebuffer(W, H);
    private final ScreenTriangles floor = new ScreenTriangles();
    private final int[] order = {0, 1};
    private Texture[] textures;
    private MipChain mips;
    private TexelLanes lanes;
    private final Rasterizer nearest = new Rasterizer();
    private final Rasterizer bilinear = new Rasterizer();
    private final Rasterizer trilinear = new Rasterizer();
    // Per sample: level-0 texel coordinates and the plane values a per-pixel loop has at that pixel.
    private final double[] s = new double[SAMPLES];
    private final double[] t = new double[SAMPLES];
    private final double[] rq = new double[SAMPLES];
    private final long[] sFixed = new long[SAMPLES];
    private final long[] tFixed = new long[SAMPLES];
    private final int[] selection = new int[SAMPLES];
    private final int[] out = new int[SAMPLES];
    private double sDx;
    private double sDy;
    private double tDx;
    private double tDy;
    private double qDx;
    private double qDy;

    @Setup
    public void setUp() {
        Texture grid = ProceduralTextures.uvGrid(512);
        textures = new Texture[] {grid};
        mips = grid.mipChain();
        lanes = TexelLanes.of(mips);
        // A floor 1 unit below a camera looking along it, focal length 1000 px, horizon 200 px above the
        // frame, 1024 texels a unit: over pixel centres 1/w = Q = (y + 200) / 1000, s/w = S = 1.024 (x - 960)
        // and t/w = T = 1024 (t = 1024 z), the planes the rasterizer interpolates.
        qDx = 0;
        qDy = 1 / 1000.0;
        sDx = 1.024;
        sDy = 0;
        tDx = 0;
        tDy = 0;
        double[] cx = {0, W, W, 0};
        double[] cy = {0, 0, H, H};
        double[] q = new double[4];
        double[] cs = new double[4];
        double[] ct = new double[4];
        for (int k = 0; k < 4; k++) {
            // Corner k at pixel coordinates (cx, cy): the centre of pixel (x, y) is (x + 0.5, y + 0.5).
            q[k] = (cy[k] - 0.5 + 200) * qDy;
            cs[k] = sDx * (cx[k] - 0.5 - 960) / q[k];
            ct[k] = 1024 / q[k];
        }
        floor.add(cx[0], cy[0], q[0], cs[0], ct[0], cx[1], cy[1], q[1], cs[1], ct[1], cx[2], cy[2], q[2], cs[2], ct[2], 0, 0);
        floor.add(cx[0], cy[0], q[0], cs[0], ct[0], cx[2], cy[2], q[2], cs[2], ct[2], cx[3], cy[3], q[3], cs[3], ct[3], 1, 0);
        nearest.filter(TextureFilter.NEAREST);
        bilinear.filter(TextureFilter.BILINEAR);
        trilinear.filter(TextureFilter.TRILINEAR);
        int maxLevel = mips.maxLevel();
        int n = 0;
        for (int y = ROW_STEP / 2; y < H; y += ROW_STEP) {
            double qy = (y + 200) * qDy;
            for (int x = 0; x < W; x++, n++) {
                rq[n] = 1 / qy;
                s[n] = sDx * (x - 960) * rq[n];
                t[n] = 1024 * rq[n];
                sFixed[n] = (long) Math.floor(s[n] * Sampler.ONE);
                tFixed[n] = (long) Math.floor(t[n] * Sampler.ONE);
                selection[n] = Lod.select(Lod.lambdaPerspective(s[n], t[n], rq[n], sDx, sDy, tDx, tDy, qDx, qDy),
                        maxLevel);
            }
        }
    }

    private long fill(Rasterizer r, boolean perspective) {
        frame.clearRows(0, H, 0);
        return r.fill(frame, floor, order, 0, 2, textures, perspective, 0, 0, W, H);
    }

    @Benchmark
    @OperationsPerInvocation(PIXELS)
    public void clear() {
        frame.clearRows(0, H, 0);
    }

    @Benchmark
    @OperationsPerInvocation(PIXELS)
    public long fillNearestPerspective() {
        return fill(nearest, true);
    }

    @Benchmark
    @OperationsPerInvocation(PIXELS)
    public long fillBilinearPerspective() {
        return fill(bilinear, true);
    }

    @Benchmark
    @OperationsPerInvocation(PIXELS)
    public long fillTrilinearPerspective() {
        return fill(trilinear, true);
    }

    @Benchmark
    @OperationsPerInvocation(PIXELS)
    public long fillTrilinearAffine() {
        return fill(trilinear, false);
    }

    /** Level of detail alone: the exact derivatives, log2, and the level/weight split. */
    @Benchmark
    @OperationsPerInvocation(SAMPLES)
    public int lod() {
        int maxLevel = mips.maxLevel();
        int acc = 0;
        for (int i = 0; i < SAMPLES; i++) {
            acc += Lod.select(Lod.lambdaPerspective(s[i], t[i], rq[i], sDx, sDy, tDx, tDy, qDx, qDy), maxLevel);
        }
        return acc;
    }

    /**
     * One bilinear sample of the first level trilinear selects, at precomputed positions: the
     * arithmetic of one bilinear sample with the cache behaviour of mipmapping.
     */
    @Benchmark
    @OperationsPerInvocation(SAMPLES)
    public int[] sampleOneLevel() {
        for (int i = 0; i < SAMPLES; i++) {
            out[i] = sample(Lod.level(selection[i]), sFixed[i], tFixed[i]);
        }
        return out;
    }

    /**
     * One bilinear sample of level 0 at precomputed positions (what the bilinear filter does; far rows
     * skip texels, so this also pays cache misses).
     */
    @Benchmark
    @OperationsPerInvocation(SAMPLES)
    public int[] sampleBilinear() {
        int[] texels = mips.texels(0);
        for (int i = 0; i < SAMPLES; i++) {
            out[i] = Sampler.bilinearPowerOfTwo(texels, 9, 9, sFixed[i] - Sampler.ONE / 2, tFixed[i] - Sampler.ONE / 2);
        }
        return out;
    }

    /** One trilinear sample (two bilinear samples and their blend) at precomputed positions and levels. */
    @Benchmark
    @OperationsPerInvocation(SAMPLES)
    public int[] sampleTrilinear() {
        for (int i = 0; i < SAMPLES; i++) {
            int sel = selection[i];
            int d = Lod.level(sel);
            int c = sample(d, sFixed[i], tFixed[i]);
            int weight = Lod.weight(sel);
            if (weight != 0) {
                c = Sampler.lerp(c, sample(d + 1, sFixed[i], tFixed[i]), weight);
            }
            out[i] = c;
        }
        return out;
    }

    /**
     * The level of detail from the float's bits ({@link Lod#fixedOfSquared}) instead of the double table's
     * logarithm: the same derivatives and division as {@link #lod}, both axes, and the split.
     */
    @Benchmark
    @OperationsPerInvocation(SAMPLES)
    public int lodFloatBits() {
        int maxLevel = mips.maxLevel();
        int acc = 0;
        for (int i = 0; i < SAMPLES; i++) {
            double r = rq[i];
            int lx = Lod.fixedOfSquared(Lod.rhoSquared(s[i], t[i], r, sDx, tDx, qDx), maxLevel);
            int ly = Lod.fixedOfSquared(Lod.rhoSquared(s[i], t[i], r, sDy, tDy, qDy), maxLevel);
            acc += Lod.select(Math.max(lx, ly), maxLevel);
        }
        return acc;
    }

    /** {@link #sampleBilinear} with {@link LaneSampler} on the padded lanes: 8-bit weights, one pass. */
    @Benchmark
    @OperationsPerInvocation(SAMPLES)
    public int[] sampleBilinearLanes() {
        long[] l = lanes.lanes();
        int stride = lanes.stride(0);
        for (int i = 0; i < SAMPLES; i++) {
            out[i] = TexelLanes.argb(LaneSampler.bilinearPowerOfTwo(l, 0, stride, 511, 511,
                    sFixed[i] - Sampler.ONE / 2, tFixed[i] - Sampler.ONE / 2));
        }
        return out;
    }

    /** {@link #sampleTrilinear} with {@link LaneSampler#trilinearPowerOfTwo}. */
    @Benchmark
    @OperationsPerInvocation(SAMPLES)
    public int[] sampleTrilinearLanes() {
        long[] l = lanes.lanes();
        int[] levels = lanes.levels();
        for (int i = 0; i < SAMPLES; i++) {
            out[i] = LaneSampler.trilinearPowerOfTwo(l, levels, selection[i], sFixed[i], tFixed[i]);
        }
        return out;
    }

    private int sample(int d, long sf, long tf) {
        int shape = mips.shape(d);
        return Sampler.bilinearPowerOfTwo(mips.texels(d), shape >>> 16 & 0xFF, shape >>> 24,
                (sf >> (shape & 0xFF)) - Sampler.ONE / 2, (tf >> (shape >>> 8 & 0xFF)) - Sampler.ONE / 2);
    }
}
