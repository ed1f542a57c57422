package dev.trisect.cli;

import dev.trisect.base.InputException;
import dev.trisect.base.internal.JsonObject;
import dev.trisect.io.ImageFiles;
import dev.trisect.io.OutputBatch;
import dev.trisect.io.Pfm;
import dev.trisect.metrics.Comparison;
import dev.trisect.metrics.HeatMap;
import dev.trisect.metrics.HeatScale;
import dev.trisect.metrics.ImageComparison;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureReader;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code trisect diff}: compares two renders given as files, such as Trisect's and OpenGL's (the glref
 * tool writes the same UV output).
 */
@Command(name = "diff", sortOptions = false, mixinStandardHelpOptions = true,
        description = {"Compare two renders given as files (an image and its UV output each), for example "
                + "Trisect's against OpenGL's from tools/glref, and print one JSON line: the metrics of "
                + "compare plus how many pixels differ in colour. Files carry no geometry, so the displacement "
                + "is an estimate (the texel difference through the reference's screen-space Jacobian, which "
                + "over-reports where perspective bends the mapping) and its fields say so: "
                + "max_displacement_estimate, p99_displacement_estimate, mean_displacement_estimate."})
final class DiffCommand implements Callable<Integer> {
    @Mixin
    CommonOptions common;

    @Spec
    CommandSpec spec;

    @Option(names = "--image", required = true, paramLabel = "FILE", description = "Image under test (PNG, PPM, ...).")
    Path image;

    @Option(names = "--uv", required = true, paramLabel = "FILE.pfm", description = "Its UV output.")
    Path uv;

    @Option(names = "--reference", required = true, paramLabel = "FILE", description = "Reference image.")
    Path referenceImage;

    @Option(names = "--reference-uv", required = true, paramLabel = "FILE.pfm", description = "Reference UV output.")
    Path referenceUv;

    @Option(names = "--heatmap", paramLabel = "FILE.png", converter = Converters.OutputFileConverter.class,
            description = "Also write the heat map of the displacement estimate.")
    Path heatmap;

    @Option(names = "--heatmap-max", paramLabel = "PX", converter = Converters.PositiveConverter.class,
            description = "Displacement estimate at the top of the heat map's scale, pixels (default: the largest, "
                    + "so that the worst pixel is white).")
    double heatmapMax;

    @Override
    public Integer call() {
        if (heatmap == null && spec.commandLine().getParseResult().hasMatchedOption("--heatmap-max")) {
            // As compare: a scale for a heat map nobody asked for is a mistake worth saying.
            throw InputException.usage("--heatmap-max needs --heatmap");
        }
        try (OutputBatch batch = new OutputBatch()) {
            if (heatmap != null) {
                Outputs.checkPng("--heatmap", heatmap);
                Outputs.checkNotInput(heatmap, "the --image input", image);
                Outputs.checkNotInput(heatmap, "the --reference input", referenceImage);
                batch.reserve(heatmap);
            }
            return diff(batch);
        }
    }

    private int diff(OutputBatch batch) {
        Texture a = TextureReader.read(image);
        Texture b = TextureReader.read(referenceImage);
        Pfm.Image ua = Pfm.read(uv);
        Pfm.Image ub = Pfm.read(referenceUv);
        int w = a.width();
        int h = a.height();
        same(image, w, h, referenceImage, b.width(), b.height());
        same(image, w, h, uv, ua.width(), ua.height());
        same(image, w, h, referenceUv, ub.width(), ub.height());
        if (ua.channels() != 3 || ub.channels() != 3) {
            throw new InputException((ua.channels() != 3 ? uv : referenceUv)
                    + ": a UV output has 3 channels (a colour PFM, PF)");
        }
        // The files hold floats; widening is exact, so the estimate sees exactly what was stored.
        double[] uvA = ua.widened();
        double[] uvB = ub.widened();
        float[] displacement = heatmap == null ? null : new float[w * h];
        Comparison c = ImageComparison.compare(w, h, a.argb(), uvA, b.argb(), uvB, displacement);
        int differ = 0;
        for (int i = 0; i < w * h; i++) {
            if (((a.argb()[i] ^ b.argb()[i]) & 0xFFFFFF) != 0) {
                differ++;
            }
        }
        String json = new JsonObject()
                .put("colour_differ_pixels", differ)
                .put("colour_differ_share", (double) differ / (w * h))
                .putAll(c.json())
                .toString();
        Results.deliver(common.out(), batch, files -> {
            if (heatmap != null) {
                int[] argb = new int[w * h];
                HeatScale scale = heatmapMax > 0 ? HeatScale.linear(heatmapMax) : HeatScale.linear(1).fitted(displacement);
                HeatMap.render(displacement, uvA, uvB, w, h, scale, argb);
                HeatMap.drawLegend(argb, w, h, scale);
                ImageFiles.write(files, heatmap, w, h, argb);
            }
        }, List.of(json));
        return 0;
    }

    private static void same(Path a, int wa, int ha, Path b, int wb, int hb) {
        if (wa != wb || ha != hb) {
            throw new InputException(b + ": is " + wb + "x" + hb + " but " + a + " is " + wa + "x" + ha);
        }
    }
}
