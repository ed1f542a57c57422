package dev.trisect.cli;

import dev.trisect.content.SceneAsset;
import dev.trisect.io.ImageFiles;
import dev.trisect.io.OutputBatch;
import dev.trisect.io.Pfm;
import dev.trisect.math.Mat4;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code trisect render}: one frame to an image file. */
@Command(name = "render", sortOptions = false, mixinStandardHelpOptions = true,
        description = "Render one frame of a scene or OBJ file to an image.")
final class RenderCommand extends SceneCommand {
    @Option(names = "--out", paramLabel = "FILE.png|FILE.ppm", converter = Converters.OutputFileConverter.class,
            description = "Image to write (required unless --list-scenes).")
    Path out;

    @Option(names = "--uv-out", paramLabel = "FILE.pfm", converter = Converters.OutputFileConverter.class,
            description = "Also write the UV output: per pixel the texel coordinates u*W, v*H and triangle index + 1 "
                    + "(PFM, see docs/conventions.md).")
    Path uvOut;

    @Option(names = "--stats", description = "Print the frame statistics as one JSON line on standard output.")
    boolean stats;

    @Override
    void checkOutputs() {
        if (out == null) {
            throw dev.trisect.base.InputException.usage("--out FILE.png|FILE.ppm is required");
        }
        Outputs.checkImage("--out", out);
        if (uvOut != null) {
            Outputs.checkPfm("--uv-out", uvOut);
            Outputs.checkDistinct("--out", out, "--uv-out", uvOut);
        }
    }

    @Override
    List<Path> outputs() {
        return Arrays.asList(out, uvOut);
    }

    @Override
    int run(SceneAsset scene, Camera camera, OutputBatch batch) {
        RenderSettings settings = path.settings(frame);
        Framebuffer fb = Frames.allocate(frame.size);
        fb.recordUv(uvOut != null);
        FrameStats s;
        try (FrameRenderer renderer = common.renderer()) {
            Mat4 vp = camera.viewProjection(frame.size.viewport());
            s = renderer.render(light.draws(scene, scene.textureArray(), vp, frame.lineWidth()), settings, fb);
        }
        Frames.noteSkipped(common, s);
        // The image and its UV output belong together: both are written, or neither is changed.
        Results.deliver(common.out(), batch, b -> {
            ImageFiles.write(b, out, fb.width(), fb.height(), fb.colour());
            if (uvOut != null) {
                Pfm.write(b, uvOut, fb.width(), fb.height(), fb.uv());
            }
        }, stats ? List.of(s.toJson()) : List.of());
        return 0;
    }
}
