package dev.trisect.cli;

import dev.trisect.scene.Camera;
import dev.trisect.content.SceneAsset;
import dev.trisect.io.OutputBatch;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Mixin;

/**
 * A command that draws a scene: it has the scene, camera and path options, answers
 * {@code --list-scenes}, and otherwise loads the scene and its camera for {@link #run}.
 */
abstract class SceneCommand implements Callable<Integer> {
    @Mixin
    FrameOptions frame;

    @Mixin
    PathOptions path;

    @Mixin
    LightOptions light;

    @Mixin
    CommonOptions common;

    /** Checks made before any work, such as output file names. */
    void checkOutputs() {
    }

    /** The files this run will write, reserved in its batch before any work (see {@link OutputBatch#reserve}). */
    List<Path> outputs() {
        return List.of();
    }

    /** Does the work, writing its files into {@code batch}; returns the exit status. */
    abstract int run(SceneAsset scene, Camera camera, OutputBatch batch) throws Exception;

    @Override
    public final Integer call() throws Exception {
        if (frame.listScenes) {
            FrameOptions.listScenes(common.out());
            return 0;
        }
        checkOutputs();
        // The option combinations every command shares, checked before the scene is read and anything is
        // printed: a usage error never follows a bench's header or a long load.
        light.check();
        frame.lineWidth();
        for (Path out : outputs()) {
            Outputs.checkNotInput(out, "the --obj input", frame.obj);
            Outputs.checkNotInput(out, "the --texture input", frame.texture);
        }
        // Every output's folder and writability are checked here, before the scene is even read.
        try (OutputBatch batch = new OutputBatch()) {
            for (Path out : outputs()) {
                if (out != null) {
                    batch.reserve(out);
                }
            }
            SceneAsset scene = frame.loadScene(common::note);
            // The material libraries and textures an OBJ names are known only now, before any rendering.
            for (Path out : outputs()) {
                Outputs.checkNotSceneInput(out, scene);
            }
            return run(scene, frame.camera(scene), batch);
        }
    }
}
