package dev.trisect.cli;

import dev.trisect.base.InputException;
import dev.trisect.base.internal.JsonObject;
import dev.trisect.content.SceneAsset;
import dev.trisect.io.ImageFiles;
import dev.trisect.io.OutputBatch;
import dev.trisect.metrics.Comparison;
import dev.trisect.metrics.HeatMap;
import dev.trisect.metrics.HeatScale;
import dev.trisect.metrics.ImageComparison;
import dev.trisect.metrics.TexelToScreen;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code trisect compare}: one frame in two paths, and how far apart they are. */
@Command(name = "compare", sortOptions = false, mixinStandardHelpOptions = true,
        description = {"Render the same frame with --mode and with --against, and print how far the first is "
                + "from the second as one JSON line: texel error (texels) over pixels both cover with the same "
                + "triangle, the share of those pixels whose texel differs, colour RMSE and PSNR, and the exact "
                + "displacement (pixels) of the --mode image over those pixels: each pixel's texel coordinates "
                + "mapped back to the 3D point that carries them, projected, and measured from the pixel centre "
                + "(max_displacement, p99_displacement, mean_displacement). With a light or fog option the line "
                + "also records the light and fog in force (light, point, ambient, shade, fog)."})
final class CompareCommand extends SceneCommand {
    @Spec
    CommandSpec spec;

    @Option(names = "--against", paramLabel = "MODE", converter = Converters.ModeConverter.class,
            defaultValue = "perspective", description = "Reference path (default: ${DEFAULT-VALUE}).")
    RenderMode against;

    @Option(names = "--heatmap", paramLabel = "FILE.png", converter = Converters.OutputFileConverter.class,
            description = "Also write the exact displacement heat map: black nothing drawn, grey not comparable, "
                    + "then dark to bright up to --heatmap-max pixels.")
    Path heatmap;

    @Option(names = "--heatmap-max", paramLabel = "PX", converter = Converters.PositiveConverter.class,
            description = "Displacement drawn at the top of the heat map's scale, pixels (default: the frame's "
                    + "largest, so that its worst pixel is white).")
    double heatmapMax;

    @Option(names = "--heatmap-scale", paramLabel = "linear|log", defaultValue = "linear",
            description = "Heat map scale: linear from 0, or logarithmic over " + HeatScale.DECADES
                    + " decades below --heatmap-max, so that small and huge errors both show (default: ${DEFAULT-VALUE}).")
    String heatmapScale;

    @Option(names = "--out", paramLabel = "FILE.png|FILE.ppm", converter = Converters.OutputFileConverter.class,
            description = "Also write the --mode image.")
    Path out;

    @Override
    void checkOutputs() {
        // Case ignored, as for every named value (--mode, --filter, --split).
        String scale = heatmapScale.toLowerCase(java.util.Locale.ROOT);
        if (!scale.equals("linear") && !scale.equals("log")) {
            throw InputException.usage("--heatmap-scale must be linear or log, got '" + heatmapScale + "'");
        }
        heatmapScale = scale;
        if (heatmap == null && (heatmapScaleGiven() || heatmapMaxGiven())) {
            throw InputException.usage((heatmapScaleGiven() ? "--heatmap-scale" : "--heatmap-max") + " needs --heatmap");
        }
        if (heatmap != null) {
            Outputs.checkPng("--heatmap", heatmap);
        }
        if (out != null) {
            Outputs.checkImage("--out", out);
            if (heatmap != null) {
                Outputs.checkDistinct("--heatmap", heatmap, "--out", out);
            }
        }
    }

    private boolean heatmapScaleGiven() {
        return spec.commandLine().getParseResult().hasMatchedOption("--heatmap-scale");
    }

    private boolean heatmapMaxGiven() {
        return spec.commandLine().getParseResult().hasMatchedOption("--heatmap-max");
    }

    @Override
    List<Path> outputs() {
        return Arrays.asList(heatmap, out);
    }

    @Override
    int run(SceneAsset scene, Camera camera, OutputBatch batch) {
        RenderSettings settings = path.settings(frame);
        Framebuffer test = Frames.allocate(frame.size);
        Framebuffer reference = Frames.allocate(frame.size);
        test.recordUv(true);
        reference.recordUv(true);
        var vp = camera.viewProjection(frame.size.viewport());
        int w = test.width();
        int h = test.height();
        float[] displacement = heatmap == null ? null : new float[w * h];
        TexelToScreen exact = new TexelToScreen(scene.mesh(), scene.textureArray(), vp, frame.size.viewport());
        Comparison c;
        try (FrameRenderer renderer = common.renderer()) {
            Draws draws = light.draws(scene.mesh(), scene.textureArray(), vp);
            renderer.render(draws, settings.withMode(against).withBorders(false), reference);
            // Measure the rendered image, never the overlay: borders are drawn only after comparing,
            // and only into the --out image.
            Frames.noteSkipped(common, renderer.render(draws, settings.withBorders(false), test));
            c = ImageComparison.compare(w, h, test.colour(), test.uv(), reference.colour(), reference.uv(),
                    exact, displacement);
            if (settings.borders()) {
                renderer.drawBorders(test, settings.borderStyle(), settings.tessellation());
            }
        }
        String json = new JsonObject()
                .put("mode", path.mode.id())
                .put("against", against.id())
                // The demo opens with trilinear, the command line defaults to nearest: say which was used.
                .put("filter", settings.filter().id())
                // The light and fog options given (none: nothing), so that a line says what it measured.
                .putAll(light.json())
                .putAll(c.json())
                .toString();
        Results.deliver(common.out(), batch, b -> {
            if (heatmap != null) {
                int[] argb = new int[w * h];
                HeatScale scale = heatmapMaxGiven() ? new HeatScale(heatmapScale.equals("log"), heatmapMax)
                        : new HeatScale(heatmapScale.equals("log"), 1).fitted(displacement);
                HeatMap.render(displacement, test.uv(), reference.uv(), w, h, scale, argb);
                HeatMap.drawLegend(argb, w, h, scale);
                ImageFiles.write(b, heatmap, w, h, argb);
            }
            if (out != null) {
                ImageFiles.write(b, out, w, h, test.colour());
            }
        }, List.of(json));
        return 0;
    }
}
