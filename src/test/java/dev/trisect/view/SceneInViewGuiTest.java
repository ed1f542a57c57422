package dev.trisect.view;

import static dev.trisect.GuiTests.edt;
import static dev.trisect.GuiTests.onEdt;
import static dev.trisect.GuiTests.waitFor;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.GuiTests;
import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.mesh.Primitives;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Pick;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.texture.ProceduralTextures;
import java.awt.Dimension;
import java.awt.Point;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.JFrame;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * A scene of objects in a view under an X server: objects added, moved, swapped and removed from
 * other threads while the view renders reach the frames whole and none is lost; a click on an
 * object tells the pick listeners which object, where and what texel.
 */
@Tag("gui")
class SceneInViewGuiTest {
    private static final Material CRATE = Material.of(ProceduralTextures.crate(64));
    private static Robot robot;
    private JFrame host;
    private TrisectView view;
    private Scene scene;
    private final List<FrameInfo> frames = new CopyOnWriteArrayList<>();
    private final GuiTests.Uncaught uncaught = new GuiTests.Uncaught();

    @BeforeAll
    static void robot() throws Exception {
        robot = GuiTests.robot("SceneInViewGuiTest");
    }

    @BeforeEach
    void open() throws Exception {
        GuiTests.requireDisplay();
        uncaught.start();
        scene = new Scene();
        edt(() -> {
            host = new JFrame("scene host");
            view = new TrisectView(scene, 2);
            view.setPreferredSize(new Dimension(320, 240));
            // Front on, the camera 5 units from the origin: the unit box at the origin fills the middle.
            view.setCamera(Camera.looking(new Vec3(0, 0, 5), Vec3.ZERO));
            view.setCameraControls(CameraControls.NONE);
            view.addFrameListener(frames::add);
            // These tests watch frames flow: keep them coming, as an animation does (a still view idles).
            view.addUpdateListener((step, frame) -> true);
            host.add(view);
            host.pack();
            host.setLocation(0, 0);
            host.setVisible(true);
        });
        waitFor("frames", () -> frames.size() >= 2);
    }

    @Test
    void aViewFrameWithoutAViewSaysWhatIsMissing() throws Exception {
        // Before, Swing failed inside its layout with a NullPointerException that named nothing.
        NullPointerException e = onEdt(() -> assertThrows(NullPointerException.class,
                () -> new ViewFrame("no view", null)));
        assertEquals("view is null", e.getMessage());
    }

    @AfterEach
    void close() throws Exception {
        if (host != null) {
            edt(() -> host.dispose());
        }
        uncaught.check();
    }

    /** The number of a frame started after now. */
    private long nextFrame() {
        return frames.isEmpty() ? 1 : frames.get(frames.size() - 1).number() + 2;
    }

    private FrameInfo frameAtLeast(long number) throws Exception {
        waitFor("frame " + number, () -> !frames.isEmpty() && frames.get(frames.size() - 1).number() >= number);
        return frames.get(frames.size() - 1);
    }

    @Test
    void objectsChangedFromOtherThreadsReachTheFramesWholeAndNoneIsLost() throws Exception {
        Mesh box = Primitives.box(1, 1, 1);
        // A swapped pair, one triangle or two (a quad): each frame has one of them, never both nor
        // neither. Against the boxes' 12 triangles each case leaves its own remainder: 1, 2; 3 or 0.
        MeshBuilder b = new MeshBuilder();
        b.triangle(b.position(0, 0, 0), b.position(1, 0, 0), b.position(0, 1, 0), b.uv(0, 0), b.uv(1, 0), b.uv(0, 1));
        Mesh one = b.build();
        Mesh two = Primitives.plane(1, 1, 1, 1);
        assertEquals(1, one.triangleCount());
        assertEquals(2, two.triangleCount());
        SceneObject swapA = new SceneObject(one, CRATE, Transform.translation(-1.5, 0, 0));
        SceneObject swapB = new SceneObject(two, CRATE, Transform.translation(-1.5, 0, 0));
        scene.add(swapA);
        List<Thread> workers = new ArrayList<>();
        List<SceneObject> added = new CopyOnWriteArrayList<>();
        int perWorker = 40;
        for (int w = 0; w < 3; w++) {
            int id = w;
            workers.add(new Thread(() -> {
                for (int i = 0; i < perWorker; i++) {
                    SceneObject o = new SceneObject(box, CRATE, Transform.translation(1 + 0.01 * i, 0.3 * id, -3));
                    scene.add(o);
                    added.add(o);
                    o.setTransform(o.transform().movedBy(0, 0.001, 0));
                    if (i % 4 == 0) {
                        // Spread the adds over several frames.
                        try {
                            Thread.sleep(2);
                        } catch (InterruptedException e) {
                            return;
                        }
                    }
                }
            }, "adder-" + w));
        }
        AtomicReference<Boolean> swapping = new AtomicReference<>(true);
        Thread swapper = new Thread(() -> {
            boolean a = true;
            while (swapping.get()) {
                boolean showA = a;
                scene.update(() -> {
                    scene.remove(showA ? swapA : swapB);
                    scene.add(showA ? swapB : swapA);
                });
                a = !a;
                Thread.yield();
            }
        }, "swapper");
        // Only frames started after swapA was added: one already drawing the empty scene may still arrive.
        frameAtLeast(nextFrame());
        int before = frames.size();
        swapper.start();
        workers.forEach(Thread::start);
        for (Thread t : workers) {
            t.join(20_000);
        }
        waitFor("frames while the scene changes", () -> frames.size() > before + 10);
        swapping.set(false);
        swapper.join(10_000);
        // Every frame during the churn: the swapped pair counted once, plus whichever adds it saw.
        int checked = 0;
        // A copy: frames keep arriving, and a sub-list of the live list fails on the next one.
        List<FrameInfo> seen = List.copyOf(frames);
        for (FrameInfo f : seen.subList(before, seen.size())) {
            long rest = f.stats().trianglesIn() % box.triangleCount();
            assertTrue(rest == 1 || rest == 2, "frame " + f.number() + ": " + f.stats().trianglesIn()
                    + " triangles: the pair half-swapped");
            checked++;
        }
        assertTrue(checked > 10);
        FrameInfo last = frameAtLeast(nextFrame());
        int pair = scene.objects().contains(swapA) ? 1 : 2;
        long expected = 3L * perWorker * box.triangleCount() + pair;
        assertEquals(3 * perWorker, added.size());
        assertEquals(expected, last.stats().trianglesIn(), "every object added is drawn");
        // Removing from another thread: gone from the next frames.
        Thread remover = new Thread(() -> added.forEach(scene::remove), "remover");
        remover.start();
        remover.join(10_000);
        long after = nextFrame();
        FrameInfo cleared = frameAtLeast(after);
        assertEquals(pair, cleared.stats().trianglesIn(), "removed objects are not drawn");
    }

    @Test
    void aClickOnAnObjectTellsThePickListenersWhichObjectWhereAndWhatTexel() throws Exception {
        SceneObject box = new SceneObject(Primitives.box(1, 1, 1), CRATE);
        box.setName("the box");
        SceneObject side = new SceneObject(Primitives.box(1, 1, 1), CRATE, Transform.translation(2.2, 0, 0));
        side.setName("the side box");
        scene.add(box, side);
        List<Pick> picks = new CopyOnWriteArrayList<>();
        List<Boolean> onEdt = new CopyOnWriteArrayList<>();
        view.addPickListener((pick, click) -> {
            picks.add(pick);
            onEdt.add(javax.swing.SwingUtilities.isEventDispatchThread());
        });
        frameAtLeast(nextFrame());
        Point at = onEdt(() -> view.getLocationOnScreen());
        // The view's centre shows the middle of the box's front face (z = 0.5).
        robot.mouseMove(at.x + 160, at.y + 120);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        waitFor("a pick", () -> picks.size() == 1);
        Pick p = picks.get(0);
        assertSame(box, p.object());
        assertEquals(160, p.x());
        assertEquals(120, p.y());
        assertEquals(0.5, p.point().z(), 1e-9, "on the front face: " + p.point());
        // The pixel centre (160.5, 120.5) seen from 5 units away at 60 degrees: a hair right of and below the middle.
        double unitsPerPixel = 2 * 4.5 * Math.tan(Math.toRadians(30)) / 240;
        assertEquals(0.5 * unitsPerPixel, p.point().x(), 1e-9);
        assertEquals(-0.5 * unitsPerPixel, p.point().y(), 1e-9);
        assertTrue(p.texelX() >= 0 && p.texelX() < 64 && p.texelY() >= 0 && p.texelY() < 64);
        assertEquals(List.of(true), onEdt, "on the event thread");
        // The box moved away: a click at the same place now hits the background (nothing reported),
        // and one on the side box names it.
        box.setVisible(false);
        frameAtLeast(nextFrame());
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        Thread.sleep(300);
        assertEquals(1, picks.size(), "a click on the background is no pick");
        // The side box's centre, 2.2 units right: 2.2 / unitsPerPixel pixels right of the middle.
        int sideX = 160 + (int) Math.round(2.2 / unitsPerPixel);
        robot.mouseMove(at.x + sideX, at.y + 120);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        waitFor("a second pick", () -> picks.size() == 2);
        assertSame(side, picks.get(1).object());
    }
}
