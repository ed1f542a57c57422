import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.light.Lights;
import dev.trisect.light.Surface;
import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.Shading;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.Texture;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * What light and fog cost, side by side in one JVM: per path, frames of the same scene alternate
 * between the plain frame and each variant (the renderer's threads), so that the shared machine's
 * load falls on both alike. Each frame is timed twice: wall time, and CPU time (steadier than wall
 * time on a loaded machine, as waiting for a core is not counted): with one thread the rendering
 * thread's own (the frame is drawn on the calling thread), else the sum over the JVM's Java threads
 * (the renderer's, each by its own clock; not the collector's or the compiler's). Prints per path and
 * variant the median wall ms of each and the median, lowest and highest of the per-round ratios of
 * wall time and of CPU time; then the median ms of each stage of the frame as FrameStats times it
 * (transform, clip, tessellate, fill) in the plain frame and the variant, and their median ratio.
 *
 *   java -cp target/trisect.jar scripts/light/LightCost.java SCENE WxH THREADS ROUNDS [VARIANT...]
 *
 * VARIANT: fog-linear, fog-exp, flat, smooth (the default: all four), flat-uncached, smooth-uncached,
 * fog-linear-1-10. Fog is the haze (0.6, 0.7, 0.8): fog-linear from 5 to 60 view units (which leaves
 * sphere160k, all nearer than 3.1, unfogged: its pass stops after the factors), fog-linear-1-10 from 1
 * to 10 (blends every pixel of sphere160k), fog-exp of density 0.05;
 * flat and smooth light every material by a white directional light from (0.3, -1, -0.5) and an
 * ambient grey of 0.2, as {@code bench --shade flat|smooth --light 0.3,-1,-0.5} does. The -uncached
 * variants are drawn by a second renderer of as many threads whose lit copies of textures are off
 * ({@code FrameRenderer.cacheLitTextures(false)}): what the copies save, side by side.
 *
 * <p>A steady frame to profile, one path and variant drawn again and again on one thread (PATH:
 * perspective, spans or tessellated, as above; VARIANT: plain, unlit and unfogged, or one of the above
 * without -uncached), 1920x1080:
 *
 *   java -XX:StartFlightRecording=filename=flat.jfr,settings=profile -cp target/trisect.jar \
 *       scripts/light/LightCost.java --repeat SCENE PATH VARIANT FRAMES
 *   jfr print --stack-depth 64 --events jdk.ExecutionSample flat.jfr
 */
public final class LightCost {
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    public static void main(String[] args) {
        try {
            run(args);
        } catch (IllegalArgumentException | ArrayIndexOutOfBoundsException e) {
            // A bad scene, path, variant, size or count: one line, not a stack trace.
            System.err.println("LightCost: " + (e instanceof NumberFormatException || e instanceof ArrayIndexOutOfBoundsException
                    ? "bad number or size (" + e.getMessage() + ")" : e.getMessage()));
            System.exit(2);
        }
    }

    private static void run(String[] args) {
        if (args.length > 0 && args[0].equals("--repeat")) {
            repeat(args);
            return;
        }
        String scene = args.length > 0 ? args[0] : "demo";
        String[] size = (args.length > 1 ? args[1] : "1920x1080").split("x");
        int threads = args.length > 2 ? Integer.parseInt(args[2]) : 2;
        int rounds = args.length > 3 ? Integer.parseInt(args[3]) : 15;
        List<String> variants = args.length > 4 ? Arrays.asList(args).subList(4, args.length)
                : List.of("fog-linear", "fog-exp", "flat", "smooth");
        int w = Integer.parseInt(size[0]);
        int h = Integer.parseInt(size[1]);
        SceneAsset s = DemoScenes.byName(scene).orElseThrow(() -> new IllegalArgumentException("no scene " + scene));
        for (String v : variants) {
            variant(v.replace("-uncached", "")); // an unknown variant fails here, before any frame
        }
        Mat4 vp = s.camera().viewProjection(new Viewport(w, h));
        RenderSettings base = RenderSettings.defaults();
        RenderSettings[] paths = {base.withMode(RenderMode.PERSPECTIVE), base.withMode(RenderMode.SPANS)
                .withKnotError(0.5), base.withMode(RenderMode.TESSELLATED).withTessellation(
                TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.5))};
        Framebuffer fb = new Framebuffer(w, h);
        Draws draws = new Draws();
        System.out.printf(Locale.ROOT, "scene %s %dx%d, %d threads, %d rounds%n", scene, w, h, threads, rounds);
        try (FrameRenderer r = new FrameRenderer(threads); FrameRenderer uncached = new FrameRenderer(threads)) {
            uncached.cacheLitTextures(false);
            for (RenderSettings path : paths) {
                List<Setup> setups = new ArrayList<>();
                List<FrameRenderer> renderers = new ArrayList<>();
                setups.add((d, mesh, textures, m) -> d.add(mesh, textures, m));
                renderers.add(r);
                for (String v : variants) {
                    setups.add(variant(v.replace("-uncached", "")));
                    renderers.add(v.endsWith("-uncached") ? uncached : r);
                }
                double[][] ms = new double[setups.size()][rounds];
                double[][] cpu = new double[setups.size()][rounds];
                double[][][] stage = new double[setups.size()][STAGES.length][rounds];
                for (int warm = 0; warm < 10; warm++) {
                    for (int k = 0; k < setups.size(); k++) {
                        frame(renderers.get(k), draws, s, vp, setups.get(k), path, fb);
                    }
                }
                for (int round = 0; round < rounds; round++) {
                    for (int k = 0; k < setups.size(); k++) {
                        long c = cpuNanos(threads);
                        ms[k][round] = frame(renderers.get(k), draws, s, vp, setups.get(k), path, fb);
                        cpu[k][round] = (cpuNanos(threads) - c) / 1e6;
                        stages(lastStats, stage[k], round);
                    }
                }
                for (int k = 1; k < setups.size(); k++) {
                    double[] ratio = ratios(ms[k], ms[0]);
                    double[] cpuRatio = ratios(cpu[k], cpu[0]);
                    System.out.printf(Locale.ROOT, "%-12s %-16s plain %7.2f ms  variant %7.2f ms  ratio median %.3f "
                                    + "(min %.3f, max %.3f)  cpu ratio %.3f (min %.3f, max %.3f)%n",
                            path.mode().name().toLowerCase(Locale.ROOT), variants.get(k - 1), median(ms[0]),
                            median(ms[k]), ratio[rounds / 2], ratio[0], ratio[rounds - 1], cpuRatio[cpuRatio.length / 2], cpuRatio[0],
                            cpuRatio[cpuRatio.length - 1]);
                    StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "%-12s %-16s stages",
                            path.mode().name().toLowerCase(Locale.ROOT), variants.get(k - 1)));
                    for (int i = 0; i < STAGES.length; i++) {
                        line.append(String.format(Locale.ROOT, "  %s %.2f/%.2f ms (%.3f)", STAGES[i],
                                median(stage[0][i]), median(stage[k][i]), ratios(stage[k][i], stage[0][i])[rounds / 2]));
                    }
                    System.out.println(line);
                }
                System.out.printf(Locale.ROOT, "%-12s lit copies kept: %d, %.1f MB%n",
                        path.mode().name().toLowerCase(Locale.ROOT), r.litTextures().size(),
                        r.litTextures().bytes() / 1e6);
            }
        }
    }

    /**
     * {@code --repeat SCENE PATH VARIANT FRAMES}: one path and variant drawn FRAMES times on one thread,
     * a steady frame to profile; prints the mean wall ms of the second half of the frames.
     */
    private static void repeat(String[] args) {
        if (args.length != 5) {
            System.err.println("usage: LightCost --repeat SCENE perspective|spans|tessellated VARIANT FRAMES");
            System.exit(2);
        }
        String scene = args[1];
        String mode = args[2];
        String variant = args[3];
        int frames = Integer.parseInt(args[4]);
        int w = 1920;
        int h = 1080;
        SceneAsset s = DemoScenes.byName(scene).orElseThrow(() -> new IllegalArgumentException("no scene " + scene));
        Mat4 vp = s.camera().viewProjection(new Viewport(w, h));
        RenderSettings base = RenderSettings.defaults();
        RenderSettings path = switch (mode) {
            case "perspective" -> base.withMode(RenderMode.PERSPECTIVE);
            case "spans" -> base.withMode(RenderMode.SPANS).withKnotError(0.5);
            case "tessellated" -> base.withMode(RenderMode.TESSELLATED).withTessellation(
                    TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.5));
            default -> throw new IllegalArgumentException("no path " + mode);
        };
        Setup setup = variant.equals("plain") ? (d, mesh, t, m) -> d.add(mesh, t, m) : variant(variant);
        Framebuffer fb = new Framebuffer(w, h);
        Draws draws = new Draws();
        try (FrameRenderer r = new FrameRenderer(1)) {
            double sum = 0;
            for (int i = 0; i < frames; i++) {
                double ms = frame(r, draws, s, vp, setup, path, fb);
                if (i >= frames / 2) {
                    sum += ms;
                }
            }
            System.out.printf(Locale.ROOT, "%s %s %s: mean %.2f ms over the last %d frames%n", scene, mode, variant,
                    sum / (frames - frames / 2), frames - frames / 2);
        }
    }

    /** How a frame's draws are made: the scene's mesh and textures, with light or fog or neither. */
    private interface Setup {
        void add(Draws d, Mesh mesh, Texture[] textures, Mat4 viewProjection);
    }

    private static Setup variant(String name) {
        Colour haze = new Colour(0.6, 0.7, 0.8);
        return switch (name) {
            case "fog-linear" -> (d, mesh, t, m) -> {
                d.add(mesh, t, m);
                d.setFog(Fog.linear(5, 60, haze));
            };
            case "fog-exp" -> (d, mesh, t, m) -> {
                d.add(mesh, t, m);
                d.setFog(Fog.exp(0.05, haze));
            };
            case "fog-linear-1-10" -> (d, mesh, t, m) -> {
                d.add(mesh, t, m);
                d.setFog(Fog.linear(1, 10, haze));
            };
            case "flat" -> lit(Shading.FLAT);
            case "smooth" -> lit(Shading.SMOOTH);
            default -> throw new IllegalArgumentException("unknown variant " + name);
        };
    }

    private static Setup lit(Shading shading) {
        Lights lights = Lights.builder().ambient(0.2, 0.2, 0.2)
                .directional(0.3, -1, -0.5, new double[3], new double[] {1, 1, 1}).build();
        return (d, mesh, t, m) -> {
            Surface[] surfaces = new Surface[mesh.materialCount()];
            Arrays.fill(surfaces, new Surface(shading, Colour.WHITE, Colour.WHITE));
            d.add(mesh, t, m, Mat4.identity(), surfaces);
            d.setLights(lights);
        };
    }

    private static double frame(FrameRenderer r, Draws draws, SceneAsset s, Mat4 vp, Setup setup,
                                RenderSettings path, Framebuffer fb) {
        draws.clear();
        setup.add(draws, s.mesh(), s.textureArray(), vp);
        long t = System.nanoTime();
        lastStats = r.render(draws, path, fb);
        return (System.nanoTime() - t) / 1e6;
    }

    /**
     * The frame's stages as {@link FrameStats} times them: the transform (with the vertex colours and
     * the lit copies' bookkeeping between frames), culling and clipping, splitting and projecting, and
     * the fill; the middle two summed over the threads' chunks.
     */
    private static final String[] STAGES = {"transform", "clip", "tessellate", "fill"};

    /** The stages of the frame last drawn ({@link #frame}). */
    private static FrameStats lastStats;

    /** Puts {@code f}'s stage times, ms, at {@code round} of {@code into}'s rows, in {@link #STAGES} order. */
    private static void stages(FrameStats f, double[][] into, int round) {
        into[0][round] = f.transformNanos() / 1e6;
        into[1][round] = f.clipNanos() / 1e6;
        into[2][round] = f.tessellateNanos() / 1e6;
        into[3][round] = f.rasterNanos() / 1e6;
    }

    /**
     * CPU time now, ns: the calling thread's with one rendering thread, else the sum of every live Java
     * thread's (the idle ones add nothing between two readings).
     */
    private static long cpuNanos(int threads) {
        if (threads == 1) {
            return THREADS.getCurrentThreadCpuTime();
        }
        long sum = 0;
        for (long id : THREADS.getAllThreadIds()) {
            sum += Math.max(0, THREADS.getThreadCpuTime(id));
        }
        return sum;
    }

    /** The per-round ratios a / b, sorted. */
    private static double[] ratios(double[] a, double[] b) {
        double[] r = new double[a.length];
        for (int i = 0; i < a.length; i++) {
            r[i] = a[i] / b[i];
        }
        Arrays.sort(r);
        return r;
    }

    private static double median(double[] v) {
        double[] c = v.clone();
        Arrays.sort(c);
        return c[c.length / 2];
    }
}
