package dev.trisect.cli;

import dev.trisect.base.InputException;
import dev.trisect.base.internal.Counts;
import dev.trisect.base.internal.JsonObject;
import dev.trisect.content.SceneAsset;
import dev.trisect.io.ImageFiles;
import dev.trisect.io.ObjWriter;
import dev.trisect.io.OutputBatch;
import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.perf.BudgetChart;
import dev.trisect.perf.BudgetRun;
import dev.trisect.perf.FrameBench;
import dev.trisect.perf.FrameTimes;
import dev.trisect.mesh.Lines;
import dev.trisect.perf.ScatteredLines;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.internal.Sprites;
import dev.trisect.perf.Sweep;
import dev.trisect.perf.SweepChart;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.raster.PixelState;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.texture.Texture;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code trisect bench}: frame times of each path on one scene, and optionally of Mesa's llvmpipe
 * (through tools/glref) on the same frame. Times are wall clock after a warm-up, so the JIT has
 * compiled the hot loops; the median is reported because a shared machine adds outliers.
 */
@Command(name = "bench", sortOptions = false, mixinStandardHelpOptions = true,
        description = {"Measure frame times of each texturing path on a scene (and of OpenGL's llvmpipe through "
                + "tools/glref with --glref) and print a table, or JSON lines with --json."})
final class BenchCommand extends SceneCommand {
    @Option(names = "--modes", split = ",", paramLabel = "MODE[,MODE...]", converter = Converters.ModeConverter.class,
            defaultValue = "perspective,affine,tessellated,spans", description = "Paths to measure (default: all four).")
    List<RenderMode> modes;

    /** Most frames measured, or rendered to warm up, per path. */
    static final int MAX_FRAMES = 1_000_000;
    /** Most segments of --lines, and labels of --labels. */
    static final int MAX_SCATTERED = 1_000_000;

    @Option(names = "--frames", paramLabel = "N", defaultValue = "200",
            description = "Frames measured per path (default: ${DEFAULT-VALUE}).")
    int frames;

    @Option(names = "--warmup", paramLabel = "N", defaultValue = "100",
            description = "Frames rendered first and not measured, for the JIT (default: ${DEFAULT-VALUE}).")
    int warmup;

    @Option(names = "--glref", paramLabel = "PROGRAM",
            description = "Also time the frame in OpenGL with this glref binary (built from tools/glref), using the "
                    + "same thread count; both renderers then use the first material's texture everywhere.")
    Path glref;

    @Option(names = "--lines", paramLabel = "N", defaultValue = "0",
            description = "Add N line segments scattered through the view (deterministic), drawn after the triangles "
                    + "--line-width pixels wide, in Trisect and in glref alike (default: none); each path is then "
                    + "also timed without them, frame by frame in turn, and glref run with and without them, and "
                    + "each row ends with what the lines cost (the difference of the two).")
    int scatteredLines;

    @Option(names = "--labels", paramLabel = "N", defaultValue = "0",
            description = "Add N labels (\"label 0\", \"label 1\", ...; 16-pixel sans-serif, depth-tested) at points "
                    + "scattered through the view (deterministic); each path is then also timed without them, frame "
                    + "by frame in turn, and each row ends with what the labels cost, their layout included "
                    + "(default: none; not with --lines or --glref).")
    int scatteredLabels;

    @Option(names = "--alpha-test", description = "Time each path also with every material alpha-tested (drawn where "
            + "its texel's alpha is at least 0.5; the scene's textures are opaque, so the same pixels), frame by frame "
            + "in turn with the opaque frame; each row ends with the alpha-tested median over the opaque one "
            + "(not with --lines, --labels or --glref).")
    boolean alphaTest;

    @Option(names = "--json", description = "One JSON line per path instead of a table (with a light or fog "
            + "option it also records the light and fog in force: light, point, ambient, shade, fog).")
    boolean json;

    @Option(names = "--sweep", description = "Measure the cost/quality curve instead: for each threshold of "
            + "--edges and --errors, the tessellated path's median ms, pieces and exact displacement against the "
            + "per-pixel frame (max and p99, pixels), and the span path's at each of --errors as max error, with "
            + "the per-pixel and affine paths as references.")
    boolean sweep;

    @Option(names = "--edges", split = ",", paramLabel = "PX[,PX...]", converter = Converters.PositiveConverter.class,
            description = "Edge-policy thresholds for --sweep (default: 8,16,24,32,48,64,128,256).")
    List<Double> edges;

    @Option(names = "--errors", split = ",", paramLabel = "PX[,PX...]", converter = Converters.PositiveConverter.class,
            description = "Error-policy thresholds, and the span path's max errors, for --sweep "
                    + "(default: 0.125,0.25,0.5,1,2,4,8).")
    List<Double> errors;

    @Option(names = "--plot", paramLabel = "FILE.png", converter = Converters.OutputFileConverter.class,
            description = "With --sweep: also draw the cost/quality curve (one panel per policy) to this PNG; "
                    + "with --target-ms: the threshold and frame time of every frame.")
    Path plot;

    @Option(names = "--target-ms", paramLabel = "MS", converter = Converters.PositiveConverter.class,
            description = "Run the tessellated path with the budget controller holding this frame time: it adjusts "
                    + "the --split policy's threshold every frame, never looser than --max-edge or --max-error, "
                    + "and prints the thresholds and times it went through.")
    Double targetMs;

    @Option(names = "--orbit", description = "With --target-ms: the camera circles its target once over the frames.")
    boolean orbit;

    @Override
    void checkOutputs() {
        // Bounded so that the per-frame times (and the run) stay of a sensible size.
        if (frames < 1 || frames > MAX_FRAMES) {
            throw InputException.usage("--frames must be between 1 and " + MAX_FRAMES + ", got " + frames);
        }
        if (warmup < 0 || warmup > MAX_FRAMES) {
            throw InputException.usage("--warmup must be between 0 and " + MAX_FRAMES + ", got " + warmup);
        }
        if (common.spec.commandLine().getParseResult().hasMatchedOption("--mode")) {
            // bench measures the paths of --modes (the sweep and the budget run their own): a --mode
            // here would be silently ignored, and the user would read times of paths they did not ask for.
            throw InputException.usage("--mode does not apply to bench: choose the paths to measure with --modes "
                    + "(e.g. --modes " + path.mode.id() + ")");
        }
        if ((sweep || targetMs != null) && common.spec.commandLine().getParseResult().hasMatchedOption("--modes")) {
            // The sweep measures its fixed set of paths, the budget run the tessellated one: --modes would be ignored.
            throw InputException.usage("--modes does not go with " + (sweep ? "--sweep" : "--target-ms"));
        }
        if (sweep && targetMs != null) {
            throw InputException.usage("--sweep and --target-ms do not go together");
        }
        if (sweep || targetMs != null) {
            // Both draw the scene's textured triangles alone (Sweep, BudgetRun): whatever else was asked for
            // would be silently left out of the times.
            String extra = scatteredLines > 0 ? "--lines" : scatteredLabels > 0 ? "--labels" : alphaTest ? "--alpha-test"
                    : common.spec.commandLine().getParseResult().hasMatchedOption("--line-width") ? "--line-width"
                    : light.given();
            if (extra != null) {
                throw InputException.usage(extra + " does not go with " + (sweep ? "--sweep" : "--target-ms")
                        + ": it times the textured triangles alone, without lines, labels, alpha test, light or fog");
            }
        }
        if (!sweep && (edges != null || errors != null)) {
            throw InputException.usage("--edges and --errors go with --sweep");
        }
        if (!sweep && targetMs == null && plot != null) {
            throw InputException.usage("--plot goes with --sweep or --target-ms");
        }
        if (targetMs == null && orbit) {
            throw InputException.usage("--orbit goes with --target-ms");
        }
        if (targetMs != null && glref != null) {
            throw InputException.usage("--glref does not go with --target-ms");
        }
        if (sweep && glref != null) {
            throw InputException.usage("--glref does not go with --sweep");
        }
        if (plot != null) {
            Outputs.checkPng("--plot", plot);
        }
        if (glref != null) {
            Programs.checkRunnable("--glref", glref);
        }
        // Bounded as --frames is: far more than any frame shows, and refused before the table's header
        // rather than running out of memory after it.
        if (scatteredLines < 0 || scatteredLines > MAX_SCATTERED) {
            throw InputException.usage("--lines must be between 0 and " + MAX_SCATTERED + ", got " + scatteredLines);
        }
        if (scatteredLabels < 0 || scatteredLabels > MAX_SCATTERED) {
            throw InputException.usage("--labels must be between 0 and " + MAX_SCATTERED + ", got " + scatteredLabels);
        }
        if (scatteredLabels > 0 && (scatteredLines > 0 || glref != null)) {
            throw InputException.usage("--labels times the labels alone: give it without --lines and --glref");
        }
        if (alphaTest && (scatteredLines > 0 || scatteredLabels > 0 || glref != null)) {
            throw InputException.usage("--alpha-test times the alpha test alone: give it without --lines, --labels "
                    + "and --glref");
        }
    }

    @Override
    List<Path> outputs() {
        return Arrays.asList(plot);
    }

    @Override
    int run(SceneAsset given, Camera camera, OutputBatch batch) throws IOException, InterruptedException {
        SceneAsset scene = scatteredLines == 0 ? given : given.withLines(ScatteredLines.of(camera,
                frame.size.viewport().aspect(), scatteredLines, 1, 0xFFFFFF));
        Texture[] textures = scene.textureArray();
        // A model of lines alone has no material: glref is given a white texel it never samples (below).
        if (glref != null && textures.length > 0) {
            Arrays.fill(textures, textures[0]);
        }
        Mat4 vp = camera.viewProjection(frame.size.viewport());
        int lineWidth = frame.lineWidth();
        List<String> lines = new ArrayList<>();
        int threads;
        try (FrameRenderer renderer = common.renderer();
             ProgressLine progress = ProgressLine.forTerminal(common.err())) {
            threads = renderer.threads();
            if (sweep) {
                List<Double> e = edges == null ? Sweep.DEFAULT_EDGES : edges;
                List<Double> r = errors == null ? Sweep.DEFAULT_ERRORS : errors;
                SweepOutput output = new SweepOutput(scene.name(), frame.size.toString(), threads);
                Sweep.Result result;
                // As the paths' rows below: each setting's row when it is measured, kept should the sweep be stopped.
                try (InterruptNotice notice = new InterruptNotice(common.err(), progress,
                        Sweep.settingsCount(e, r), "setting")) {
                    Results.print(common.out(), json ? List.of() : output.header(frames));
                    result = Sweep.run(renderer, scene, textures, vp, frame.size.width(), frame.size.height(),
                            path.settings(frame), e, r, warmup, frames, progress.task("sweep"), p -> {
                                progress.close();
                                Results.print(common.out(), List.of(output.row(p, json)));
                                notice.measured();
                            });
                }
                progress.close();
                lines.addAll(output.summary(result, json));
                Results.deliver(common.out(), batch, b -> {
                    if (plot != null) {
                        SweepChart.write(b, result, scene.name() + " " + frame.size + ", " + Counts.of(threads, "thread"),
                                plot);
                    }
                }, lines);
                return 0;
            }
            if (targetMs != null) {
                BudgetRun.Trace trace = BudgetRun.run(renderer, scene, textures, camera, frame.size.width(),
                        frame.size.height(), path.settings(frame), targetMs, orbit, warmup, frames,
                        progress.task("budget"));
                progress.close();
                lines.addAll(new BudgetOutput(scene.name(), frame.size.toString(), threads).lines(trace, json));
                Results.deliver(common.out(), batch, b -> {
                    if (plot != null) {
                        BudgetChart.write(b, trace, String.format(Locale.ROOT, "%s %s, %s: budget %.1f ms%s",
                                scene.name(), frame.size, Counts.of(threads, "thread"), targetMs, orbit ? ", orbiting" : ""), plot);
                    }
                }, lines);
                return 0;
            }
            if (!json) {
                lines.add(String.format(Locale.ROOT, "scene %s, %s, %s%s, %s, %s filter, %s after %s", scene.name(),
                        frame.size, Counts.of(scene.mesh().triangleCount(), "triangle"), scene.lines().isEmpty() ? ""
                                : ", " + Counts.of(scene.lines().segmentCount(), "line segment") + " " + lineWidth
                                + " px wide", Counts.of(threads, "thread"),
                        path.filter.id(), Counts.of(frames, "frame"), Counts.of(warmup, "warm-up frame")));
                lines.add(String.format(Locale.ROOT, "%-12s %10s %10s %10s %10s %8s %10s", "path", "median ms",
                        "min ms", "mean ms", "p95 ms", "fps", "pieces"));
            }
            // Each row is printed as soon as its path is measured, not with the others at the end: a user who
            // stops a long bench (Ctrl-C) keeps what was measured, and is told the table is short.
            try (InterruptNotice notice = new InterruptNotice(common.err(), progress,
                    modes.size() + (glref == null ? 0 : 1), "path")) {
                Results.print(common.out(), lines);
                Draws draws = alphaTest ? light.draws(scene.mesh(), textures, alphaTested(textures.length), vp)
                        : light.draws(scene, textures, vp, lineWidth);
                FrameBench bench = new FrameBench(renderer, draws, Frames.allocate(frame.size));
                // With lines, every path is also timed without them, frame by frame in turn: the
                // difference of the medians is what the lines cost, measured alike for glref below.
                // With --alpha-test, without the test: the ratio of the medians is what it costs.
                Draws bare = scene.lines().isEmpty() && scatteredLabels == 0 && !alphaTest ? null
                        : light.draws(scene.mesh(), textures, vp);
                // Labels are laid out again before every frame, as a view does.
                Runnable labels = scatteredLabels == 0 ? null : labelLayout(camera, draws);
                for (RenderMode mode : modes) {
                    RenderSettings settings = path.settings(frame).withMode(mode);
                    FrameBench.Result r;
                    double extraMs = Double.NaN;
                    if (bare == null) {
                        r = bench.time(settings, warmup, frames, progress.task(mode.id()));
                    } else {
                        FrameBench.Result[] pair = bench.timeAlternately(bare, settings, warmup, frames,
                                progress.task(mode.id()), labels);
                        r = pair[0];
                        extraMs = alphaTest ? pair[0].times().medianMs() / pair[1].times().medianMs()
                                : pair[0].times().medianMs() - pair[1].times().medianMs();
                    }
                    progress.close(); // erased before the row, which goes to the same terminal
                    Results.print(common.out(), List.of(row(mode.id(), r, threads, extraMs)));
                    notice.measured();
                }
                if (glref != null) {
                    Texture first = textures.length == 0 ? Texture.solid("white", 0xFFFFFFFF) : textures[0];
                    double with = glrefMs(scene, first, camera, threads, lineWidth);
                    double without = scene.lines().isEmpty() ? Double.NaN
                            : glrefMs(scene.withLines(Lines.EMPTY), first, camera, threads, lineWidth);
                    Results.print(common.out(), List.of(glrefRow(with, with - without, threads)));
                }
            }
        }
        return 0;
    }

    private String row(String name, FrameBench.Result r, int threads, double linesMs) {
        FrameTimes t = r.times();
        if (json) {
            JsonObject o = new JsonObject()
                    .put("path", name)
                    .put("size", frame.size.toString())
                    .put("frames", t.frames())
                    .put("median_ms", t.medianMs(), 3)
                    .put("mean_ms", t.meanMs(), 3)
                    .put("p95_ms", t.p95Ms(), 3)
                    .put("fps", 1000 / t.medianMs(), 1)
                    .put("pieces", r.last().pieces())
                    .put("threads", threads)
                    .put("filter", path.filter.id())
                    .put("min_ms", t.minMs(), 3)
                    .put("pixels", (long) frame.size.width() * frame.size.height())
                    .put("pixels_written", r.last().pixelsWritten())
                    .putAll(light.json());
            if (!Double.isNaN(linesMs)) {
                o.put(extraName() + (alphaTest ? "_ratio" : "_ms"), linesMs, 3);
            }
            return o.toString();
        }
        return String.format(Locale.ROOT, "%-12s %10.3f %10.3f %10.3f %10.3f %8.1f %10d", name, t.medianMs(),
                t.minMs(), t.meanMs(), t.p95Ms(), 1000 / t.medianMs(), r.last().pieces()) + linesColumn(linesMs);
    }

    /** The lines' (or labels') cost after a row, when measured; with --alpha-test, its ratio to the opaque frame. */
    private String linesColumn(double ms) {
        return Double.isNaN(ms) ? "" : String.format(Locale.ROOT, alphaTest ? "  %s %.3fx opaque" : "  %s %.3f ms",
                extraName(), ms);
    }

    /** What the rows' extra cost is of. */
    private String extraName() {
        return alphaTest ? "alpha_test" : scatteredLabels > 0 ? "labels" : "lines";
    }

    /** Every one of {@code materials} alpha-tested, the texel its colour. */
    private static int[] alphaTested(int materials) {
        int[] states = new int[materials];
        Arrays.fill(states, PixelState.TEXEL | PixelState.ALPHA_TEST);
        return states;
    }

    /** Lays out the scattered labels into {@code draws}' quads, replacing those there. */
    private Runnable labelLayout(Camera camera, Draws draws) {
        Scene labels = new Scene();
        labels.add(SceneObject.labels(ScatteredLines.labels(camera, frame.size.viewport().aspect(), scatteredLabels,
                1)));
        List<Scene.Placed> placed = labels.snapshot();
        return () -> {
            draws.quads().clear();
            Sprites.layOut(placed, camera, frame.size.width(), frame.size.height(), draws.quads());
        };
    }

    /** glref's row: its mean frame time and, when it drew lines, what they cost (NaN otherwise). */
    private String glrefRow(double ms, double linesMs, int threads) {
        if (json) {
            JsonObject o = new JsonObject()
                    .put("path", "glref-llvmpipe")
                    .put("size", frame.size.toString())
                    .put("frames", frames + warmup)
                    .put("mean_ms", ms, 3)
                    .put("fps", 1000 / ms, 1)
                    .put("threads", threads)
                    .put("filter", path.filter.id())
                    .putAll(light.json());
            if (!Double.isNaN(linesMs)) {
                o.put("lines_ms", linesMs, 3);
            }
            return o.toString();
        }
        // glref reports a mean alone: it goes under "mean ms", the other times are dashes (as in row()'s columns).
        return String.format(Locale.ROOT, "%-12s %10s %10s %10.3f %10s %8.1f %10s  (Mesa llvmpipe, LP_NUM_THREADS=%d, "
                + "GLREF_FILTER=%s, mean of %s incl. glFinish)", "glref", "-", "-", ms, "-", 1000 / ms, "-",
                threads, path.filter.id(), Counts.of(frames + warmup, "frame")) + linesColumn(linesMs);
    }

    /** Exports the scene, runs glref with LP_NUM_THREADS set, and gives its mean frame time, ms. */
    private double glrefMs(SceneAsset scene, Texture texture, Camera camera, int threads, int lineWidth)
            throws IOException, InterruptedException {
        if (!camera.up().normalize().equals(Vec3.UP)) {
            common.note("glref always uses up = 0,1,0; its frame differs from ours for --up " + camera.up());
        }
        Map<String, String> environment = new HashMap<>();
        environment.put("LP_NUM_THREADS", Integer.toString(threads));
        environment.put("GLREF_FILTER", path.filter.id());
        environment.putAll(light.glrefEnvironment());
        environment.put("GLREF_LINE_WIDTH", Integer.toString(lineWidth));
        try (GlrefRun run = new GlrefRun(glref)) {
            return run.meanMs(dir -> {
                Path obj = dir.resolve("scene.obj");
                List<Path> maps = ObjWriter.write(obj, scene.mesh(), List.of(Arrays.stream(scene.textureArray())
                        .map(t -> texture).toArray(Texture[]::new)), scene.lines());
                Path map = maps.isEmpty() ? dir.resolve("white.ppm") : maps.get(0);
                if (maps.isEmpty()) {
                    ImageFiles.write(map, texture.width(), texture.height(), texture.argb());
                }
                List<String> args = new ArrayList<>(List.of(obj.toString(), map.toString(),
                        dir.resolve("gl.ppm").toString(), Integer.toString(frame.size.width()),
                        Integer.toString(frame.size.height())));
                for (Vec3 v : List.of(camera.eye(), camera.target())) {
                    args.addAll(List.of(Double.toString(v.x()), Double.toString(v.y()), Double.toString(v.z())));
                }
                args.addAll(List.of(Double.toString(camera.fovY()), Double.toString(camera.near()),
                        Double.toString(camera.far()), frame.cull.name().toLowerCase(Locale.ROOT),
                        Integer.toString(frames + warmup)));
                return args;
            }, environment);
        }
    }
}
