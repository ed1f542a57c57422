package dev.trisect.cli;

import dev.trisect.base.internal.Counts;
import dev.trisect.io.ObjWriter;
import dev.trisect.io.OutputBatch;
import dev.trisect.content.SceneAsset;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code trisect export}: a scene as OBJ + MTL + PPM textures (PAM where a texture has alpha), for rendering it elsewhere. */
@Command(name = "export", sortOptions = false, mixinStandardHelpOptions = true,
        description = {"Write a scene as Wavefront OBJ with an MTL file and one PPM per texture, shared by the "
                + "materials that use it (PAM, with its alpha, where a texture has alpha), and "
                + "print its camera, so another renderer (tools/glref, say) can draw the same frame."})
final class ExportCommand implements Callable<Integer> {
    @Mixin
    FrameOptions frame;

    @Mixin
    LightOptions light;

    @Mixin
    CommonOptions common;

    @Option(names = "--to", paramLabel = "FILE.obj", converter = Converters.OutputFileConverter.class,
            description = "OBJ file to write (required unless --list-scenes).")
    Path to;

    @Override
    public Integer call() {
        if (frame.listScenes) {
            FrameOptions.listScenes(common.out());
            return 0;
        }
        // The frame options export shares with the drawing commands change nothing in what it writes or
        // prints (the mesh, its textures and the camera): given to export, they would be silently lost.
        for (String unused : List.of("--size", "--cull", "--background", "--line-width")) {
            if (common.spec.commandLine().getParseResult().hasMatchedOption(unused)) {
                throw dev.trisect.base.InputException.usage(unused + " does not apply to export: it writes the mesh, "
                        + "its textures and the camera, not a frame (give " + unused + " to the renderer)");
            }
        }
        if (to == null) {
            throw dev.trisect.base.InputException.usage("--to FILE.obj is required");
        }
        light.check();
        Outputs.checkObj("--to", to);
        Outputs.checkNotInput(to, "the --obj input", frame.obj);
        // The folder is made and checked before the scene is read; the MTL and textures go beside the OBJ.
        // Should nothing be written after all (a bad scene, a full disk), the folders made here are
        // removed again, so that a failed export leaves nothing behind (not after a signal, which runs
        // only the shutdown hook: see docs/reading-limits.md).
        Path made = Outputs.createParent("--to", to);
        boolean written = false;
        try {
            try (OutputBatch batch = new OutputBatch()) {
                batch.reserve(to);
                int status = export(batch);
                written = java.nio.file.Files.isRegularFile(to);
                return status;
            }
        } finally {
            if (!written) {
                Outputs.removeMadeFolders(to, made);
            }
        }
    }

    private int export(OutputBatch batch) {
        SceneAsset scene = frame.loadScene(common::note);
        // Its MTL and textures go beside the OBJ under names of their own (to.mtl, to-material.ppm or .pam): any of
        // them can be a file the scene was read from (mtllib to.mtl), and is checked before anything is written.
        for (Path out : ObjWriter.files(to, scene.mesh(), scene.textures())) {
            Outputs.checkNotInput(out, "the --texture input", frame.texture);
            Outputs.checkNotSceneInput(out, scene);
        }
        var camera = frame.camera(scene);
        String cameraLine = String.format("camera: --eye %s --target %s --up %s --fov %s --near %s --far %s",
                camera.eye(), camera.target(), camera.up(), camera.fovY(), camera.near(), camera.far());
        List<Path> maps = new ArrayList<>();
        List<String> view = new ArrayList<>(List.of(cameraLine));
        // Light and fog as the OpenGL reference reads them, so that it draws the same frame.
        Map<String, String> env = light.glrefEnvironment();
        if (!env.isEmpty()) {
            StringBuilder glref = new StringBuilder("glref:");
            env.forEach((k, v) -> glref.append(' ').append(k).append('=').append(v));
            view.add(glref.toString());
        }
        // The camera is printed even when the files fail: it is what was computed.
        Results.deliver(common.out(), batch, b -> maps.addAll(ObjWriter.write(b, to, scene.mesh(), scene.textures(),
                scene.lines())),
                written -> {
                    List<String> lines = new ArrayList<>();
                    if (written) {
                        // Each texture file once: materials that share a texture share its file.
                        List<Path> files = maps.stream().distinct().toList();
                        lines.add(String.format("wrote %s (%s, %s%s: %s)", to,
                                Counts.of(scene.mesh().triangleCount(), "triangle"),
                                scene.lines().isEmpty() ? "" : Counts.of(scene.lines().segmentCount(), "line segment")
                                        + ", ", Counts.of(maps.size(), "material"), files));
                    }
                    lines.addAll(view);
                    return lines;
                });
        return 0;
    }
}
