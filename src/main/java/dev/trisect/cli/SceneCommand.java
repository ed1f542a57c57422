package dev.trisect.cli;

import dev.trisect.scene.Camera;
import dev.trisect.content.SceneAsset;
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
    CommonOptions common;

    /** Checks made before any work, such as output file names. */
    void checkOutputs() {
    }

    /** Does the work; returns the exit status. */
    abstract int run(SceneAsset scene, Camera camera) throws Exception;

    @Override
    public final Integer call() throws Exception {
        if (frame.listScenes) {
            FrameOptions.listScenes(common.out());
            return 0;
        }
        checkOutputs();
        SceneAsset scene = frame.loadScene(common::note);
        return run(scene, frame.camera(scene));
    }
}
