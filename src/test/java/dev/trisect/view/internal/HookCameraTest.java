package dev.trisect.view.internal;

import static dev.trisect.GuiTests.waitFor;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/**
 * An update hook sees the camera its frame is drawn with ({@code TrisectView.getCamera()} reads
 * {@link ViewState#currentCamera()}): while the user turns the camera, a light that follows it (a
 * headlight) is lit from where that frame looks, not from where the frame before looked; and a camera
 * a hook sets is the one its frame draws.
 */
class HookCameraTest {
    @Test
    void aHookSeesTheCameraOfTheFrameItRunsBefore() throws Exception {
        Scene scene = new Scene();
        scene.add(new SceneObject(Primitives.box(1, 1, 1), Material.colour(0x808080)));
        Camera home = Camera.looking(new Vec3(0, 2, 4), Vec3.ZERO);
        ViewState state = new ViewState(scene, home);
        state.viewSize(32, 24);
        Map<Long, Camera> seen = new ConcurrentHashMap<>();
        Map<Long, Camera> drawn = new ConcurrentHashMap<>();
        Camera set = Camera.looking(new Vec3(3, 1, 3), Vec3.ZERO);
        AtomicLong setBefore = new AtomicLong(-1);
        RenderLoop loop = new RenderLoop(state, new TripleBuffer(), () -> { }, 1);
        loop.listener(new RenderLoop.LoopListener() {
            @Override
            public void frameDone(FrameReport report) {
                drawn.put(report.frame(), report.camera());
            }

            @Override
            public void problem(String message) {
                throw new AssertionError(message);
            }

            @Override
            public boolean update(double seconds, long frame) {
                seen.put(frame, state.currentCamera());
                if (frame == setBefore.get()) {
                    state.camera(set);
                }
                return false;
            }
        });
        Thread t = new Thread(loop, "test-render");
        t.start();
        try {
            waitFor("the first frame", () -> drawn.containsKey(1L));
            for (int i = 0; i < 3; i++) {
                // Drag to look round (fly controls): each drag moves the camera of the frame it wakes.
                long before = drawn.size();
                state.input.drag(40, 0);
                waitFor("a frame for the drag", () -> drawn.size() > before && !state.input.pendingDrag());
            }
            long last = drawn.size();
            setBefore.set(last + 1);
            state.demand.request();
            waitFor("the frame whose hook sets a camera", () -> drawn.containsKey(last + 1));
        } finally {
            loop.stop();
            t.join(5000);
        }
        assertNotEquals(drawn.get(1L), drawn.get(2L), "the drag turned the camera");
        for (long f : drawn.keySet()) {
            if (f != setBefore.get()) {
                assertEquals(drawn.get(f), seen.get(f), "the camera a hook sees before frame " + f);
            }
        }
        assertEquals(set, drawn.get(setBefore.get()), "a camera set in a hook is its frame's");
    }
}
