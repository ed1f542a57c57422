package dev.trisect.ui;

import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.GuiTests;
import dev.trisect.content.DemoScenes;
import dev.trisect.devtools.DevToolsDialog;
import dev.trisect.devtools.DevToolsPanel;
import dev.trisect.view.ViewAction;
import dev.trisect.view.internal.Command;
import dev.trisect.view.internal.FrameSlot;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewMouse;
import dev.trisect.view.internal.ViewSettings;
import dev.trisect.view.internal.ViewState;
import java.awt.GraphicsEnvironment;
import java.awt.Robot;
import java.awt.Window;
import java.awt.event.InputEvent;
import java.util.concurrent.Callable;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.swing.JDialog;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;

/**
 * The real demo window under an X server, opened once per test class and driven with real key presses
 * (java.awt.Robot), with the helpers its tests share. Skipped only where no display exists; CI starts
 * Xvfb and sets TRISECT_REQUIRE_DISPLAY, which turns the skip into a failure.
 */
abstract class DemoWindowFixture {
    static DemoWindow window;
    static Robot robot;

    @BeforeAll
    static void open() throws Exception {
        boolean headless = GraphicsEnvironment.isHeadless();
        if (headless) {
            // Each test then reports itself skipped (see requireDisplay), so the build shows them as skipped
            // rather than passed; say so in the output too.
            System.err.println("Demo window GUI tests SKIPPED: no display; the GUI tests need an X server "
                    + "(e.g. Xvfb :99 & export DISPLAY=:99)");
            return;
        }
        window = DemoApp.openForTest(DemoScenes.demo(), 2);
        // These tests watch frames flow: keep them coming, as an animation does (a still view idles).
        window.view().addUpdateListener((step, frame) -> true);
        robot = new Robot();
        robot.setAutoDelay(20);
        // Without a window manager the window has no keyboard until clicked.
        waitFor("the first frame", () -> onEdt(() -> front() != null));
        var at = onEdt(() -> window.view().getLocationOnScreen());
        robot.mouseMove(at.x + 300, at.y + 200);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        waitFor("keyboard focus", () -> onEdt(() -> window.frame().isFocused()));
    }

    @BeforeEach
    void requireDisplay() {
        boolean headless = GraphicsEnvironment.isHeadless();
        if (headless && System.getenv("TRISECT_REQUIRE_DISPLAY") != null) {
            throw new AssertionError("TRISECT_REQUIRE_DISPLAY is set but there is no display (DISPLAY="
                    + System.getenv("DISPLAY") + ")");
        }
        Assumptions.assumeFalse(headless, "no display: the GUI tests need an X server (set DISPLAY, e.g. Xvfb :99)");
    }

    @AfterAll
    static void close() throws Exception {
        if (window != null) {
            SwingUtilities.invokeAndWait(() -> window.frame().dispose());
        }
    }

    /** The view's engine room (not API: the test looks inside). */
    static ViewController c() {
        return (ViewController) window.view().getClientProperty(ViewController.class);
    }

    static ViewState state() {
        return c().state();
    }

    /** The frame on screen. Event thread. */
    static FrameSlot front() {
        return c().front();
    }

    static Command cmd(ViewAction a) {
        return (Command) window.view().action(a);
    }

    static ViewMouse mouse() {
        return (ViewMouse) window.view().getClientProperty(ViewMouse.class);
    }

    /** The developer tools in their window. Event thread. */
    static DevToolsPanel tools() {
        return ((DevToolsDialog) devToolsWindow()).panel();
    }

    /** {@link GuiTests#onEdt}, for the subclasses' unqualified calls. */
    static <T> T onEdt(Callable<T> task) throws Exception {
        return GuiTests.onEdt(task);
    }

    /** {@link GuiTests#waitFor}: bounded waiting, not timing. */
    static void waitFor(String what, GuiTests.Check check) throws Exception {
        GuiTests.waitFor(what, check);
    }

    static void press(int key) {
        robot.keyPress(key);
        robot.keyRelease(key);
    }

    /** Pixels of a frame drawn after now, with the settings in force now. */
    static int[] freshFrame() throws Exception {
        long after = onEdt(() -> front().serial) + 2;
        ViewSettings wanted = state().settings();
        waitFor("a new frame", () -> onEdt(() -> front().serial > after)
                && state().settings() == wanted);
        long serial = onEdt(() -> front().serial) + 1;
        waitFor("one more frame", () -> onEdt(() -> front().serial >= serial));
        return onEdt(() -> front().frame.colour().clone());
    }

    static int yellow(int[] pixels) {
        int n = 0;
        for (int p : pixels) {
            n += p == 0xFFFFFF00 ? 1 : 0;
        }
        return n;
    }

    /**
     * This window's developer tools. Window.getWindows() also lists the disposed tools of views that
     * other GUI test classes opened earlier in the same JVM (until they are collected), and lists them
     * first: only the dialog this window owns is ours.
     */
    static JDialog devToolsWindow() {
        for (Window w : Window.getWindows()) {
            if (w instanceof JDialog d && d.getOwner() == window.frame() && "Developer tools".equals(d.getTitle())) {
                return d;
            }
        }
        return null;
    }

    static double number(String json, String key) {
        Matcher m = Pattern.compile("\"" + key + "\":(-?[0-9.eE+-]+|null)").matcher(json);
        assertTrue(m.find(), key + " in " + json);
        return m.group(1).equals("null") ? Double.NaN : Double.parseDouble(m.group(1));
    }
}
