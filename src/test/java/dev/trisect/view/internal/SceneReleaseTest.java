package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.Primitives;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.texture.ProceduralTextures;
import java.lang.ref.WeakReference;
import org.junit.jupiter.api.Test;

/**
 * A scene replaced in the view gives back the storage the renderer kept for the old one at its next
 * frame, not after the retention policy's frames: the view can then load the largest model that fits
 * alone after another.
 */
class SceneReleaseTest {
    private static Scene of(int cells) {
        Scene s = new Scene();
        s.add(new SceneObject(Primitives.plane(20, 20, cells, cells), Material.of(ProceduralTextures.uvGrid(64))));
        return s;
    }

    /** Waits (bounded, polling) until the loop has drawn {@code frames} frames in all. */
    private static void awaitFrames(ViewState state, long frames) throws InterruptedException {
        for (int poll = 0; poll < 15000 && state.progress().frames() < frames; poll++) {
            Thread.sleep(2);
        }
        assertTrue(state.progress().frames() >= frames, "the loop draws");
    }

    @Test
    void theOldScenesStorageGoesAtTheFirstFrameOfTheNewOne() throws Exception {
        ViewState state = new ViewState(of(300), Camera.looking(new Vec3(0, 4, 8), Vec3.ZERO));
        state.viewSize(320, 200);
        RenderLoop loop = new RenderLoop(state, new TripleBuffer(), () -> { }, 2);
        Thread t = new Thread(loop, "test-render");
        t.start();
        long large;
        try {
            // A still scene's view draws one frame and then idles until something changes.
            awaitFrames(state, 1);
            large = loop.renderer().retainedTriangleCapacity();
            long drawn = state.progress().frames();
            state.scene(of(1));
            // The one frame of the new scene, then stop: fewer frames than the retention policy waits for.
            awaitFrames(state, drawn + 1);
        } finally {
            loop.stop();
            t.join(10_000);
        }
        long small = loop.renderer().retainedTriangleCapacity();
        assertTrue(large >= 20_000, "the 180,000-triangle grid's storage: " + large);
        assertTrue(small < large / 10, "kept " + small + " triangles of room after the scene was replaced, " + large
                + " before");
    }

    /** In a still view too, the old scene's meshes can be collected once the new scene is drawn. */
    @Test
    void theOldScenesMeshesAreLetGo() throws Exception {
        Scene large = of(100);
        WeakReference<Mesh> mesh = new WeakReference<>(((SceneObject) large.children().get(0)).mesh());
        ViewState state = new ViewState(large, Camera.looking(new Vec3(0, 4, 8), Vec3.ZERO));
        large = null;
        state.viewSize(160, 100);
        RenderLoop loop = new RenderLoop(state, new TripleBuffer(), () -> { }, 1);
        Thread t = new Thread(loop, "test-render");
        t.start();
        try {
            awaitFrames(state, 1);
            long drawn = state.progress().frames();
            state.scene(of(1));
            awaitFrames(state, drawn + 1);
            // And the two frames that settle the frame slots, which a still view draws for it (bounded wait).
            for (int poll = 0; poll < 1500 && state.progress().frames() < drawn + 3; poll++) {
                Thread.sleep(2);
            }
        } finally {
            loop.stop();
            t.join(10_000);
        }
        for (int i = 0; i < 20 && mesh.get() != null; i++) {
            System.gc();
            Thread.sleep(20);
        }
        assertNull(mesh.get(), "the replaced scene's mesh is still held");
    }
}

