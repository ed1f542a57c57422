package dev.trisect.ui;

import static dev.trisect.GuiTests.onEdt;
import static dev.trisect.GuiTests.waitFor;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import dev.trisect.GuiTests;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.SwingUtilities;
import javax.swing.SwingWorker;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The File menu's scenes and loads in the real demo window, under an X server. */
@Tag("gui")
class FileMenuGuiTest {
    private DemoWindow window;

    @AfterEach
    void close() throws Exception {
        if (window != null) {
            SwingUtilities.invokeAndWait(() -> window.frame().dispose());
        }
    }

    private String title() throws Exception {
        return onEdt(() -> window.frame().getTitle());
    }

    @Test
    void aSceneChosenWhileAModelLoadsStaysOnScreen() throws Exception {
        GuiTests.requireDisplay();
        window = DemoApp.openForTest(DemoScenes.demo(), 1);
        // The trial's steps: open a large OBJ (a million triangles take seconds to read), then choose
        // Built-in scene > Floor while it loads. The model replaced the floor when it came.
        CountDownLatch reading = new CountDownLatch(1);
        SwingWorker<SceneAsset, Void> load = onEdt(() -> window.fileMenu.load(Path.of("globe.obj"), notes -> {
            try {
                reading.await();
            } catch (InterruptedException e) {
                throw new IllegalStateException(e);
            }
            return DemoScenes.boxes();
        }));
        JMenu scenes = onEdt(() -> window.fileMenu.scenesMenu());
        JMenuItem floor = onEdt(() -> scenes.getItem(DemoScenes.names().indexOf("floor")));
        assertNotNull(floor);
        SwingUtilities.invokeAndWait(floor::doClick);
        waitFor("the floor", () -> title().equals("Trisect \u2014 floor"));
        reading.countDown();
        waitFor("the load to end", load::isDone);
        // SwingWorker hands done() to the event thread on a timer (a thirtieth of a second): give it ample time.
        Thread.sleep(1000);
        SwingUtilities.invokeAndWait(() -> { });
        assertEquals("Trisect \u2014 floor", title(), "the scene chosen last stays, not the model that came after");

        // A load asked for last is shown, as ever.
        SwingWorker<SceneAsset, Void> last = onEdt(() -> window.fileMenu.load(Path.of("boxes.obj"),
                notes -> DemoScenes.boxes()));
        waitFor("the load to end", last::isDone);
        waitFor("the model", () -> title().equals("Trisect \u2014 boxes"));
    }

    @Test
    void aBuiltInSceneIsMadeOffTheEventThread() throws Exception {
        GuiTests.requireDisplay();
        window = DemoApp.openForTest(DemoScenes.demo(), 1);
        // Built-in scene > Sphere1m built its million triangles on the event thread: the window froze
        // for up to 1.4 s (found by the demo trial). The making now runs in the background.
        java.util.concurrent.atomic.AtomicBoolean onEventThread = new java.util.concurrent.atomic.AtomicBoolean(true);
        CountDownLatch making = new CountDownLatch(1);
        SwingWorker<SceneAsset, Void> build = onEdt(() -> window.fileMenu.builtIn("Boxes", () -> {
            onEventThread.set(SwingUtilities.isEventDispatchThread());
            try {
                making.await();
            } catch (InterruptedException e) {
                throw new IllegalStateException(e);
            }
            return DemoScenes.boxes();
        }));
        // The event thread is free while the scene is being made.
        SwingUtilities.invokeAndWait(() -> { });
        assertEquals("Trisect \u2014 demo", title(), "the old scene stays until the new one is made");
        making.countDown();
        waitFor("the making to end", build::isDone);
        assertFalse(onEventThread.get(), "made off the event thread");
        waitFor("the boxes", () -> title().equals("Trisect \u2014 boxes"));
    }
}
