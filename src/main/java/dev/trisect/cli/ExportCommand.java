package dev.trisect.cli;

import dev.trisect.io.ObjWriter;
import dev.trisect.content.SceneAsset;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code trisect export}: a scene as OBJ + MTL + PPM textures, for rendering it elsewhere. */
@Command(name = "export", sortOptions = false, mixinStandardHelpOptions = true,
        description = {"Write a scene as Wavefront OBJ with an MTL file and one PPM texture per material, and "
                + "print its camera, so another renderer (tools/glref, say) can draw the same frame."})
final class ExportCommand implements Callable<Integer> {
    @Mixin
    FrameOptions frame;

    @Mixin
    CommonOptions common;

    @Option(names = "--to", required = true, paramLabel = "FILE.obj", description = "OBJ file to write.")
    Path to;

    @Override
    public Integer call() {
        if (frame.listScenes) {
            FrameOptions.listScenes(common.out());
            return 0;
        }
        Outputs.checkObj("--to", to);
        SceneAsset scene = frame.loadScene(common::note);
        var camera = frame.camera(scene);
        Outputs.createParent("--to", to);
        List<Path> maps = ObjWriter.write(to, scene.mesh(), scene.textures());
        common.out().printf("wrote %s (%d triangles, %d materials: %s)%n", to, scene.mesh().triangleCount(),
                maps.size(), maps);
        common.out().printf("camera: --eye %s --target %s --up %s --fov %s --near %s --far %s%n", camera.eye(),
                camera.target(), camera.up(), camera.fovY(), camera.near(), camera.far());
        common.out().flush();
        return 0;
    }
}
