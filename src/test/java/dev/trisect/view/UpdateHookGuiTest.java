package dev.trisect.view;

import static dev.trisect.GuiTests.edt;
import static dev.trisect.GuiTests.waitFor;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.GuiTests;
import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.texture.ProceduralTextures;
import java.awt.Dimension;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import javax.swing.JFrame;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The update hook and frames only when needed, in a real view under an X server: the hook is called
 * once a frame with its step, what it changes is in the frame it runs before, and a still view stops
 * drawing until something changes.
 */
@Tag("gui")
class UpdateHookGuiTest {
    private JFrame host;
    private TrisectView view;
    private Scene scene;
    private SceneObject box;
    private final List<FrameInfo> frames = new CopyOnWriteArrayList<>();
    private final GuiTests.Uncaught uncaught = new GuiTests.Uncaught();

    @BeforeEach
    void open() throws Exception {
        GuiTests.requireDisplay();
        uncaught.start();
        scene = new Scene();
        box = new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.crate(64)));
        scene.add(box);
        edt(() -> {
            host = new JFrame("update hook");
            view = new TrisectView(scene, 1);
            view.setPreferredSize(new Dimension(160, 120));
            view.addFrameListener(frames::add);
            host.add(view);
            host.pack();
            host.setVisible(true);
        });
        waitFor("the first frame", () -> !frames.isEmpty());
    }

    @AfterEach
    void close() throws Exception {
        if (host != null) {
            edt(() -> host.dispose());
        }
        uncaught.check();
    }

    /**
     * The public hook is called once a frame, numbered in order, with a step within the loop's bounds.
     * That the steps add up to the time between frames is checked on a stepped clock, without timing
     * anything (FrameDemandTest.animatedFramesKeepToTheCapAndTheStepsAddUpToTheClock).
     */
    @Test
    void theHookGetsOneStepAFrameNumberedInOrder() throws Exception {
        List<double[]> calls = new CopyOnWriteArrayList<>();
        view.addUpdateListener((seconds, frame) -> {
            calls.add(new double[] {seconds, frame});
            return calls.size() < 20;
        });
        waitFor("twenty calls", () -> calls.size() >= 20);
        List<double[]> c = List.copyOf(calls);
        for (int i = 1; i < c.size(); i++) {
            double step = c.get(i)[0];
            assertTrue(step >= 0 && step <= TrisectView.MAX_STEP_SECONDS, "step " + step);
            assertEquals(c.get(i - 1)[1] + 1, c.get(i)[1], "one call per frame, numbered in order");
        }
    }

    @Test
    void whatTheHookChangesIsInTheFrameItRunsBefore() throws Exception {
        Map<Long, Camera> set = new ConcurrentHashMap<>();
        view.addUpdateListener((seconds, frame) -> {
            Camera c = Camera.looking(new Vec3(frame * 0.01, 2, 4), Vec3.ZERO);
            set.put(frame, c);
            view.setCamera(c);
            box.setTransform(Transform.translation(frame * 0.001, 0, 0));
            return frame < 30;
        });
        waitFor("thirty frames", () -> frames.get(frames.size() - 1).number() >= 30);
        for (FrameInfo f : frames) {
            if (set.containsKey(f.number())) {
                assertEquals(set.get(f.number()), f.camera(), "frame " + f.number() + " is drawn from its hook's camera");
            }
        }
    }

    @Test
    void aStillViewIdlesAndWakesForAChange() throws Exception {
        Thread.sleep(300);
        int still = frames.size();
        Thread.sleep(700);
        assertEquals(still, frames.size(), "no frames while nothing changes");
        box.setTransform(Transform.translation(0.3, 0, 0));
        waitFor("a frame for the change", () -> frames.size() > still);
        Thread.sleep(500);
        assertEquals(still + 1, frames.size(), "one frame for one change, then idle again");
        view.requestFrame();
        waitFor("a requested frame", () -> frames.size() == still + 2);
    }
}
