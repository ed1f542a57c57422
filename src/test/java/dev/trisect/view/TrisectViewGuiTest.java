package dev.trisect.view;

import static dev.trisect.GuiTests.edt;
import static dev.trisect.GuiTests.onEdt;
import static dev.trisect.GuiTests.waitFor;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.GuiTests;
import dev.trisect.content.AssetScenes;
import dev.trisect.content.DemoScenes;
import dev.trisect.math.Vec3;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Scene;
import dev.trisect.view.internal.ViewController;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Robot;
import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import javax.swing.AbstractAction;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JPanel;
import javax.swing.KeyStroke;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/**
 * The view embedded in a host's own frame beside Swing controls, under an X server: it renders on
 * its own thread, takes settings and cameras from any thread at any time, tells its listeners, and
 * stops its thread when removed, closed or disposed, without an exception anywhere.
 */
@Tag("gui")
class TrisectViewGuiTest {
    private static Robot robot;
    private JFrame host;
    private TrisectView view;
    private final List<FrameInfo> frames = new CopyOnWriteArrayList<>();
    private final GuiTests.Uncaught uncaught = new GuiTests.Uncaught();

    @BeforeAll
    static void robot() throws Exception {
        robot = GuiTests.robot("TrisectViewGuiTest");
    }

    @BeforeEach
    void open() throws Exception {
        GuiTests.requireDisplay();
        uncaught.start();
        edt(() -> {
            host = new JFrame("host");
            view = new TrisectView(AssetScenes.scene(DemoScenes.boxes()), 2);
            view.setPreferredSize(new Dimension(400, 300));
            view.addFrameListener(frames::add);
            // These tests watch frames flow: keep them coming, as an animation does (a still view idles).
            view.addUpdateListener((step, frame) -> true);
            JPanel side = new JPanel();
            side.add(new JButton("a host control"));
            host.getContentPane().add(view, BorderLayout.CENTER);
            host.getContentPane().add(side, BorderLayout.EAST);
            host.pack();
            host.setLocation(0, 0);
            host.setVisible(true);
        });
        waitFor("frames", () -> frames.size() >= 3);
    }

    @AfterEach
    void close() throws Exception {
        if (host != null) {
            edt(() -> host.dispose());
        }
        uncaught.check();
    }

    private Thread renderThread() throws Exception {
        return onEdt(() -> ((ViewController) view.getClientProperty(ViewController.class)).renderThread());
    }

    private FrameInfo last() {
        return frames.get(frames.size() - 1);
    }

    /** Clicks into the view, so that it has the keyboard (Xvfb has no window manager to give it). */
    private void focusView() throws Exception {
        var at = onEdt(() -> view.getLocationOnScreen());
        robot.mouseMove(at.x + 200, at.y + 150);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        waitFor("the keyboard", () -> onEdt(() -> view.isFocusOwner()));
    }

    @Test
    void itRendersAtItsSizeOnItsOwnThreadAndReportsEachFrame() throws Exception {
        FrameInfo f = last();
        assertEquals(400, f.width(), "the frame is the view's size (device pixels, scale 1 here)");
        assertEquals(300, f.height());
        assertTrue(f.stats().trianglesIn() > 0);
        assertTrue(f.frameMillis() > 0);
        assertEquals("trisect-render", renderThread().getName());
        for (int i = 1; i < frames.size(); i++) {
            assertEquals(frames.get(i - 1).number() + 1, frames.get(i).number(), "every frame reported, in order");
        }
        BufferedImage image = onEdt(() -> view.frameImage());
        assertNotNull(image, "the frame on screen, as an image");
        assertEquals(400, image.getWidth());
    }

    @Test
    void theDifferenceViewsImageCarriesTheHeatMapsLegend() throws Exception {
        ViewController c = onEdt(() -> (ViewController) view.getClientProperty(ViewController.class));
        edt(() -> view.action(ViewAction.SHOW_DIFFERENCE).actionPerformed(null));
        waitFor("a heat map on screen", () -> onEdt(() -> c.front() != null
                && c.front().view == dev.trisect.view.internal.ViewKind.DIFFERENCE));
        int[] legendless = onEdt(() -> c.front().frame.colour().clone());
        BufferedImage saved = onEdt(() -> view.frameImage());
        BufferedImage same = onEdt(() -> {
            // The frame did not change between the two reads (the view holds the frame on screen).
            return c.front().frame.colour()[0] == legendless[0] ? view.frameImage() : null;
        });
        assertNotNull(same);
        int differ = 0;
        for (int y = 0; y < 40; y++) {
            for (int x = 0; x < 220; x++) {
                differ += saved.getRGB(x, y) != legendless[y * 400 + x] ? 1 : 0;
            }
        }
        assertTrue(differ > 1000, "the legend is drawn into the saved heat map (top left): " + differ + " pixels");
        assertEquals(legendless[299 * 400 + 399], saved.getRGB(399, 299), "and the rest is the heat map");
        edt(() -> view.showDevTools(false));
    }

    @Test
    void settingsAndCamerasSetFromAnotherThreadReachTheNextFrames() throws Exception {
        Camera aside = Camera.looking(new Vec3(6, 3, 6), new Vec3(0, 0.5, 0));
        Thread other = new Thread(() -> {
            for (int i = 0; i < 20; i++) {
                view.setRenderSettings(view.getRenderSettings().withMode(i % 2 == 0 ? RenderMode.PERSPECTIVE
                        : RenderMode.AFFINE));
                view.setRenderScale(i % 2 == 0 ? 0.5 : 1);
                Thread.yield();
            }
            view.setRenderSettings(view.getRenderSettings().withMode(RenderMode.AFFINE).withBorders(true));
            view.setCamera(aside);
        }, "host-worker");
        other.start();
        other.join(10_000);
        waitFor("a frame with the last settings and camera", () -> {
            FrameInfo f = last();
            return f.settings().mode() == RenderMode.AFFINE && f.settings().borders() && f.camera().equals(aside)
                    && f.width() == 400;
        });
        assertEquals(aside, view.getCamera(), "the camera as set, until the user moves it");
        waitFor("the menu's state to follow", () -> onEdt(() -> Boolean.TRUE.equals(view.action(ViewAction.BORDERS)
                .getValue(javax.swing.Action.SELECTED_KEY))
                && Boolean.TRUE.equals(view.action(ViewAction.AFFINE).getValue(javax.swing.Action.SELECTED_KEY))));
    }

    @Test
    void removingTheViewStopsItsThreadAndAddingItBackStartsAnother() throws Exception {
        Thread first = renderThread();
        edt(() -> {
            host.getContentPane().remove(view);
            host.revalidate();
        });
        first.join(10_000);
        assertFalse(first.isAlive(), "the render thread ended when the view left its window");
        int before = frames.size();
        edt(() -> {
            host.getContentPane().add(view, BorderLayout.CENTER);
            host.revalidate();
        });
        waitFor("frames again", () -> frames.size() > before + 2);
        assertNotEquals(first, renderThread());
    }

    @Test
    void closingStopsForGoodAndDisposingTheWindowStopsToo() throws Exception {
        Thread t = renderThread();
        view.close();
        t.join(10_000);
        assertFalse(t.isAlive(), "closed: the render thread ended");
        assertTrue(view.isClosed());
        List<Executable> refused = List.of(() -> view.setCamera(Camera.looking(new Vec3(0, 1, 3), Vec3.ZERO)),
                () -> view.setScene(new Scene()), () -> view.setRenderSettings(RenderSettings.defaults()),
                () -> view.setRenderScale(1), () -> view.setFrameTimeTarget(0),
                () -> view.setCameraControls(CameraControls.ORBIT),
                () -> view.addFrameListener(frame -> { }), () -> view.addPickListener((pick, click) -> { }),
                () -> view.addUpdateListener((seconds, frame) -> false),
                () -> view.addMessageListener(message -> { }), () -> view.action(ViewAction.BORDERS));
        for (Executable call : refused) {
            assertEquals("this TrisectView is closed: make a new one",
                    assertThrows(IllegalStateException.class, call).getMessage());
        }
        edt(() -> assertEquals("this TrisectView is closed: make a new one",
                assertThrows(IllegalStateException.class, view::createDevToolsPanel).getMessage()));
        FrameListener unwanted = frame -> { };
        view.removeFrameListener(unwanted); // taking one away stays allowed
        edt(() -> {
            host.getContentPane().remove(view);
            host.getContentPane().add(view, BorderLayout.CENTER);
            host.revalidate();
        });
        int before = frames.size();
        Thread.sleep(300);
        assertEquals(before, frames.size(), "a closed view draws no more, even when added again");

        TrisectView second = onEdt(() -> {
            TrisectView v = new TrisectView(AssetScenes.scene(DemoScenes.floor()), 1);
            host.getContentPane().add(v, BorderLayout.NORTH);
            v.setPreferredSize(new Dimension(100, 80));
            host.pack();
            return v;
        });
        waitFor("the second view's thread", () -> onEdt(() -> ((ViewController) second
                .getClientProperty(ViewController.class)).renderThread()) != null);
        Thread secondThread = onEdt(() -> ((ViewController) second.getClientProperty(ViewController.class))
                .renderThread());
        edt(() -> host.dispose());
        secondThread.join(10_000);
        assertFalse(secondThread.isAlive(), "disposing the window ends the thread of a view in it");
    }

    @Test
    void withoutCameraControlsTheMovementKeysAreTheHosts() throws Exception {
        AtomicInteger hostW = new AtomicInteger();
        edt(() -> {
            JComponent root = host.getRootPane();
            root.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW).put(KeyStroke.getKeyStroke(KeyEvent.VK_W, 0), "host-w");
            root.getActionMap().put("host-w", new AbstractAction() {
                private static final long serialVersionUID = 1L;

                @Override
                public void actionPerformed(ActionEvent e) {
                    hostW.incrementAndGet();
                }
            });
        });
        focusView();
        Camera start = view.getCamera();
        view.setCameraControls(CameraControls.NONE);
        Thread.sleep(200);
        robot.keyPress(KeyEvent.VK_W);
        Thread.sleep(300);
        robot.keyRelease(KeyEvent.VK_W);
        waitFor("the host's binding", () -> hostW.get() > 0);
        Thread.sleep(200);
        assertEquals(start, view.getCamera(), "no controls: the camera stays");

        view.setCameraControls(CameraControls.FLY);
        int before = hostW.get();
        Thread.sleep(200);
        robot.keyPress(KeyEvent.VK_W);
        Thread.sleep(300);
        robot.keyRelease(KeyEvent.VK_W);
        waitFor("the camera to fly forward", () -> {
            Camera c = view.getCamera();
            Vec3 forward = start.target().sub(start.eye()).normalize();
            return c.eye().sub(start.eye()).dot(forward) > 0.1;
        });
        assertEquals(before, hostW.get(), "with controls the view takes W");
    }

    @Test
    void orbitControlsTurnRoundTheTargetAtTheSameDistance() throws Exception {
        Camera start = Camera.looking(new Vec3(0, 2, 8), new Vec3(0, 0.5, 0));
        view.setCamera(start);
        view.setCameraControls(CameraControls.ORBIT);
        waitFor("the camera set", () -> last().camera().equals(start));
        var at = onEdt(() -> view.getLocationOnScreen());
        robot.mouseMove(at.x + 150, at.y + 150);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        for (int i = 1; i <= 10; i++) {
            robot.mouseMove(at.x + 150 + 10 * i, at.y + 150);
        }
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        waitFor("the camera to turn", () -> !view.getCamera().eye().equals(start.eye()));
        Thread.sleep(200);
        Camera c = view.getCamera();
        assertEquals(start.target(), c.target(), "it looks at the same point");
        assertEquals(start.eye().sub(start.target()).length(), c.eye().sub(c.target()).length(), 1e-9,
                "from the same distance");
        assertEquals(start.eye().y(), c.eye().y(), 1e-9, "a horizontal drag keeps the height");
    }

    @Test
    void aFailingFrameListenerIsReportedAndRenderingGoesOn() throws Exception {
        List<String> messages = new CopyOnWriteArrayList<>();
        view.addMessageListener(messages::add);
        FrameListener bad = f -> {
            throw new IllegalStateException("listener bug");
        };
        view.addFrameListener(bad);
        waitFor("the message", () -> !messages.isEmpty());
        assertTrue(messages.get(0).contains("listener bug"), messages.get(0));
        view.removeFrameListener(bad);
        int before = frames.size();
        waitFor("more frames", () -> frames.size() > before + 2);
    }

    @Test
    void aDevToolsPanelPlacedByTheHostMeasuresWhileItShows() throws Exception {
        JComponent tools = onEdt(() -> {
            JComponent t = view.createDevToolsPanel();
            t.setPreferredSize(new Dimension(420, 300));
            host.getContentPane().add(t, BorderLayout.WEST);
            host.pack();
            return t;
        });
        ViewController c = onEdt(() -> (ViewController) view.getClientProperty(ViewController.class));
        waitFor("a measurement for the placed tools", () -> c.state().measurement() != null);
        assertTrue(c.state().toolsOpen());
        edt(() -> {
            host.getContentPane().remove(tools);
            host.revalidate();
        });
        assertFalse(c.state().toolsOpen(), "tools taken away: nothing more to measure for");
        edt(() -> view.showDevTools(true));
        assertTrue(onEdt(() -> view.isDevToolsShowing()));
        assertTrue(c.state().toolsOpen());
        edt(() -> view.showDevTools(false));
        assertFalse(c.state().toolsOpen());
    }
}
