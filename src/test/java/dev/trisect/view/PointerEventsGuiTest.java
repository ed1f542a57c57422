package dev.trisect.view;

import static dev.trisect.GuiTests.edt;
import static dev.trisect.GuiTests.onEdt;
import static dev.trisect.GuiTests.waitFor;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.GuiTests;
import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Framebuffer;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Group;
import dev.trisect.scene.Highlight;
import dev.trisect.scene.Material;
import dev.trisect.scene.Pick;
import dev.trisect.scene.PointerEvent;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.SceneRenderer;
import dev.trisect.texture.ProceduralTextures;
import java.awt.Dimension;
import java.awt.Point;
import java.awt.Robot;
import java.awt.event.InputEvent;
import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.util.List;
import java.util.Optional;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;
import javax.swing.JFrame;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Per-object mouse events, the hover highlight, picking and the keyboard focus, through real mouse
 * and key events (a robot) on a view under an X server: a crate on the left, a ball in a group on the
 * right, seen front on.
 */
@Tag("gui")
class PointerEventsGuiTest {
    private static Robot robot;
    private JFrame host;
    private TrisectView view;
    private Scene scene;
    private SceneObject crate;
    private SceneObject ball;
    private Group group;
    private final List<FrameInfo> frames = new CopyOnWriteArrayList<>();
    private final List<String> heard = new CopyOnWriteArrayList<>();
    private final GuiTests.Uncaught uncaught = new GuiTests.Uncaught();

    @BeforeAll
    static void robot() throws Exception {
        robot = GuiTests.robot("PointerEventsGuiTest");
    }

    @BeforeEach
    void open() throws Exception {
        GuiTests.requireDisplay();
        uncaught.start();
        scene = new Scene();
        crate = new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.crate(64)),
                Transform.translation(-1, 0, 0));
        crate.setName("crate");
        ball = new SceneObject(Primitives.sphere(0.5, 16, 8), Material.of(ProceduralTextures.uvGrid(64)));
        ball.setName("ball");
        group = new Group("group");
        group.setTransform(Transform.translation(1, 0, 0));
        group.add(ball);
        scene.add(crate, group);
        crate.addPointerListener(e -> heard.add("crate: " + e.kind() + " " + e.target().name()));
        ball.addPointerListener(e -> heard.add("ball: " + e.kind() + " " + e.target().name()));
        group.addPointerListener(e -> heard.add("group: " + e.kind() + " " + e.target().name()));
        edt(() -> {
            host = new JFrame("pointer");
            view = new TrisectView(scene, 1);
            view.setPreferredSize(new Dimension(320, 240));
            view.setCamera(Camera.looking(new Vec3(0, 0, 3), Vec3.ZERO));
            view.setCameraControls(CameraControls.NONE);
            view.addFrameListener(frames::add);
            host.add(view);
            host.pack();
            host.setLocation(0, 0);
            host.setVisible(true);
        });
        waitFor("a frame with its triangle ids", () -> onEdt(() -> view.pick(0, 0)) != null && !frames.isEmpty());
    }

    @AfterEach
    void close() throws Exception {
        if (host != null) {
            edt(() -> host.dispose());
        }
        uncaught.check();
    }

    /** The view point (logical pixels) where {@code world} is drawn. */
    private Point at(Vec3 world) {
        Camera c = view.getCamera();
        double[] p = new double[4];
        c.viewProjection(new dev.trisect.math.Viewport(view.getWidth(), view.getHeight()))
                .transformPoint(world.x(), world.y(), world.z(), p, 0);
        return new Point((int) ((p[0] / p[3] + 1) / 2 * view.getWidth()),
                (int) ((1 - p[1] / p[3]) / 2 * view.getHeight()));
    }

    /** Moves the mouse to view point (x, y) in small steps from where it is, waiting for the events. */
    private void glide(Point from, Point to) throws Exception {
        Point origin = onEdt(() -> view.getLocationOnScreen());
        for (int i = 0; i <= 20; i++) {
            robot.mouseMove(origin.x + from.x + (to.x - from.x) * i / 20, origin.y + from.y + (to.y - from.y) * i / 20);
        }
        robot.waitForIdle();
    }

    private List<String> heardFrom(String who) {
        return heard.stream().filter(s -> s.startsWith(who + ":")).toList();
    }

    @Test
    void enterAndExitFireOncePerCrossingAndTheGroupHearsItsOwn() throws Exception {
        Point empty = new Point(160, 20);
        Point onCrate = onEdt(() -> at(new Vec3(-1, 0, 0.5)));
        Point onBall = onEdt(() -> at(new Vec3(1, 0, 0.5)));
        glide(empty, empty);
        for (int crossing = 0; crossing < 2; crossing++) {
            glide(empty, onCrate);
            glide(onCrate, empty);
        }
        waitFor("two crossings of the crate", () -> heardFrom("crate").size() >= 4);
        assertEquals(List.of("crate: ENTERED crate", "crate: EXITED crate", "crate: ENTERED crate",
                "crate: EXITED crate"), heardFrom("crate"), "once per crossing, however many moves inside");
        heard.clear();
        glide(empty, onBall);
        glide(onBall, empty);
        waitFor("a crossing of the ball", () -> heardFrom("ball").size() >= 2 && heardFrom("group").size() >= 2);
        assertEquals(List.of("ball: ENTERED ball", "ball: EXITED ball"), heardFrom("ball"));
        assertEquals(List.of("group: ENTERED ball", "group: EXITED ball"), heardFrom("group"),
                "the group is entered and left as a whole, once");
        assertEquals(List.of(), heardFrom("crate"));
    }

    @Test
    void aClickNamesTheObjectAndBubblesToItsGroupUnlessConsumed() throws Exception {
        Point onBall = onEdt(() -> at(new Vec3(1, 0, 0.5)));
        glide(new Point(160, 20), onBall);
        heard.clear();
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        waitFor("the click", () -> heardFrom("group").contains("group: CLICKED ball"));
        assertEquals(List.of("ball: PRESSED ball", "ball: RELEASED ball", "ball: CLICKED ball"), heardFrom("ball"));
        assertEquals(List.of("group: PRESSED ball", "group: RELEASED ball", "group: CLICKED ball"), heardFrom("group"),
                "passed on to the group, naming the object");
        ball.addPointerListener(PointerEvent::consume);
        heard.clear();
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        waitFor("the second click", () -> heardFrom("ball").contains("ball: CLICKED ball"));
        robot.waitForIdle();
        assertEquals(List.of(), heardFrom("group"), "a consumed event stops at the object");
    }

    @Test
    void theHoverHighlightTintsTheObjectsPixelsAndNothingElse() throws Exception {
        crate.setHoverHighlight(Highlight.tint(0xFF0000));
        Point onCrate = onEdt(() -> at(new Vec3(-1, 0, 0.5)));
        Point onBall = onEdt(() -> at(new Vec3(1, 0, 0.5)));
        glide(new Point(160, 20), new Point(160, 20));
        // Setting a highlight is a change: its frame (the same pixels, nothing under the pointer) comes and goes.
        Thread.sleep(500);
        int[] plain = onEdt(() -> view.frameImage().getRGB(0, 0, 320, 240, null, 0, 320));
        glide(new Point(160, 20), onCrate);
        waitFor("the crate highlighted", () -> onEdt(() -> view.frameImage().getRGB(onCrate.x, onCrate.y))
                != plain[onCrate.y * 320 + onCrate.x]);
        int[] lit = onEdt(() -> view.frameImage().getRGB(0, 0, 320, 240, null, 0, 320));
        boolean[] crates = onEdt(() -> {
            boolean[] c = new boolean[320 * 240];
            for (int i = 0; i < c.length; i++) {
                Optional<Pick> p = view.pick(i % 320, i / 320);
                c[i] = p.isPresent() && p.get().object() == crate;
            }
            return c;
        });
        int tinted = 0;
        for (int y = 0; y < 240; y++) {
            for (int x = 0; x < 320; x++) {
                int i = y * 320 + x;
                boolean onIt = crates[i];
                int want = onIt ? 0xFF000000 | (((plain[i] & 0xFEFEFE) >> 1) + ((0xFF0000 & 0xFEFEFE) >> 1)) : plain[i];
                assertEquals(Integer.toHexString(want), Integer.toHexString(lit[i]), "pixel " + x + "," + y);
                tinted += onIt ? 1 : 0;
            }
        }
        assertTrue(tinted > 1000, tinted + " pixels of the crate tinted");
        glide(onCrate, onBall);
        waitFor("the highlight gone", () -> onEdt(() -> view.frameImage().getRGB(onCrate.x, onCrate.y))
                == plain[onCrate.y * 320 + onCrate.x]);
    }

    @Test
    void theViewsPickIsTheRenderersOnTheSameFrameAtAThousandPoints() throws Exception {
        Thread.sleep(300);
        FrameInfo f = frames.get(frames.size() - 1);
        Framebuffer fb = new Framebuffer(f.width(), f.height());
        Random random = new Random(29);
        int objects = 0;
        try (SceneRenderer r = new SceneRenderer(1)) {
            r.render(scene, f.camera(), f.settings(), fb);
            for (int i = 0; i < 1000; i++) {
                int x = random.nextInt(f.width());
                int y = random.nextInt(f.height());
                Optional<Pick> mine = onEdt(() -> view.pick(x, y));
                assertEquals(r.pick(x, y), mine, "pixel " + x + "," + y);
                objects += mine.isPresent() ? 1 : 0;
            }
        }
        assertEquals(f.number(), frames.get(frames.size() - 1).number(), "the same frame throughout");
        assertTrue(objects > 100, objects + " of the points on an object");
    }

    @Test
    void anObjectWithTheKeyboardHearsKeysFirstAndEscapeGivesThemBack() throws Exception {
        List<Integer> keys = new CopyOnWriteArrayList<>();
        crate.addKeyListener(new KeyAdapter() {
            @Override
            public void keyPressed(KeyEvent e) {
                keys.add(e.getKeyCode());
                e.consume();
            }
        });
        edt(() -> view.setCameraControls(CameraControls.FLY));
        Point origin = onEdt(() -> view.getLocationOnScreen());
        robot.mouseMove(origin.x + 160, origin.y + 20);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        waitFor("the keyboard", () -> onEdt(() -> view.isFocusOwner()));
        edt(() -> view.giveKeyboard(crate));
        Camera before = view.getCamera();
        robot.keyPress(KeyEvent.VK_W);
        Thread.sleep(300);
        robot.keyRelease(KeyEvent.VK_W);
        waitFor("the key at the crate", () -> keys.contains(KeyEvent.VK_W));
        Thread.sleep(200);
        assertEquals(before, view.getCamera(), "a key the crate consumed never moves the camera");
        robot.keyPress(KeyEvent.VK_ESCAPE);
        robot.keyRelease(KeyEvent.VK_ESCAPE);
        waitFor("the keyboard given back", () -> onEdt(() -> view.keyboardOwner().isEmpty()));
        robot.keyPress(KeyEvent.VK_W);
        Thread.sleep(300);
        robot.keyRelease(KeyEvent.VK_W);
        waitFor("the camera flying", () -> !view.getCamera().equals(before));
        assertEquals(1, keys.size(), "the crate heard no more keys");
    }
}
