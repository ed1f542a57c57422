package dev.trisect.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.AssetScenes;
import dev.trisect.cli.Cli;
import dev.trisect.content.DemoScenes;
import dev.trisect.devtools.CliArgs;
import dev.trisect.devtools.CompareSection;
import dev.trisect.devtools.DevToolsDialog;
import dev.trisect.devtools.DevToolsPanel;
import dev.trisect.metrics.Comparison;
import dev.trisect.render.RenderMode;
import dev.trisect.render.SplitPolicy;
import dev.trisect.texture.TextureFilter;
import dev.trisect.view.ViewAction;
import dev.trisect.view.internal.Command;
import dev.trisect.view.internal.FrameSlot;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewKind;
import dev.trisect.view.internal.ViewMouse;
import dev.trisect.view.internal.ViewSettings;
import dev.trisect.view.internal.ViewState;
import java.awt.GraphicsEnvironment;
import java.awt.Robot;
import java.awt.Window;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.swing.Action;
import javax.swing.JDialog;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;

/**
 * The real demo window under an X server, driven with real key presses (java.awt.Robot). Skipped
 * only where no display exists; CI starts Xvfb and sets TRISECT_REQUIRE_DISPLAY, which turns the
 * skip into a failure.
 */
@Tag("gui")
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class DemoWindowGuiTest {
    private static DemoWindow window;
    private static Robot robot;

    @BeforeAll
    static void open() throws Exception {
        boolean headless = GraphicsEnvironment.isHeadless();
        if (headless) {
            // Each test then reports itself skipped (see requireDisplay), so the build shows 14 skipped
            // tests rather than none; say so in the output too.
            System.err.println("DemoWindowGuiTest SKIPPED: no display; the GUI tests need an X server "
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
    private static ViewController c() {
        return (ViewController) window.view().getClientProperty(ViewController.class);
    }

    private static ViewState state() {
        return c().state();
    }

    /** The frame on screen. Event thread. */
    private static FrameSlot front() {
        return c().front();
    }

    private static Command cmd(ViewAction a) {
        return (Command) window.view().action(a);
    }

    private static ViewMouse mouse() {
        return (ViewMouse) window.view().getClientProperty(ViewMouse.class);
    }

    /** The developer tools in their window. Event thread. */
    private static DevToolsPanel tools() {
        return ((DevToolsDialog) devToolsWindow()).panel();
    }

    private static <T> T onEdt(Callable<T> task) throws Exception {
        AtomicReference<T> result = new AtomicReference<>();
        AtomicReference<Exception> failure = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            try {
                result.set(task.call());
            } catch (Exception e) {
                failure.set(e);
            }
        });
        if (failure.get() != null) {
            throw failure.get();
        }
        return result.get();
    }

    private interface Check {
        boolean ok() throws Exception;
    }

    private static void waitFor(String what, Check check) throws Exception {
        // Bounded waiting (up to about 20 s), not timing: 400 polls 50 ms apart.
        for (int poll = 0; poll < 400; poll++) {
            if (check.ok()) {
                return;
            }
            Thread.sleep(50);
        }
        throw new AssertionError("timed out waiting for " + what);
    }

    private static void press(int key) {
        robot.keyPress(key);
        robot.keyRelease(key);
    }

    /** Pixels of a frame drawn after now, with the settings in force now. */
    private static int[] freshFrame() throws Exception {
        long after = onEdt(() -> front().serial) + 2;
        ViewSettings wanted = state().settings();
        waitFor("a new frame", () -> onEdt(() -> front().serial > after)
                && state().settings() == wanted);
        long serial = onEdt(() -> front().serial) + 1;
        waitFor("one more frame", () -> onEdt(() -> front().serial >= serial));
        return onEdt(() -> front().frame.colour().clone());
    }

    private static int yellow(int[] pixels) {
        int n = 0;
        for (int p : pixels) {
            n += p == 0xFFFFFF00 ? 1 : 0;
        }
        return n;
    }

    @Test
    @Order(1)
    void theWindowOpensWithTrisectInItsTitle() throws Exception {
        assertTrue(onEdt(() -> window.frame().getTitle()).startsWith("Trisect"));
        assertTrue(onEdt(() -> window.frame().isShowing()));
        int[] px = freshFrame();
        assertTrue(Arrays.stream(px).distinct().count() > 100, "the scene is drawn, not a blank frame");
    }

    @Test
    @Order(2)
    void f12ShowsTheDeveloperToolsAndTheViewKeepsTheKeyboard() throws Exception {
        press(KeyEvent.VK_F12);
        waitFor("the developer tools", () -> onEdt(() -> devToolsWindow() != null && devToolsWindow().isShowing()));
        assertTrue(onEdt(() -> window.frame().isFocused()), "the view keeps the keyboard");
        press(KeyEvent.VK_F12);
        waitFor("the developer tools to close", () -> onEdt(() -> !devToolsWindow().isShowing()));
        press(KeyEvent.VK_F12);
        waitFor("the developer tools again", () -> onEdt(() -> devToolsWindow().isShowing()));
    }

    /**
     * This window's developer tools. Window.getWindows() also lists the disposed tools of views that
     * other GUI test classes opened earlier in the same JVM (until they are collected), and lists them
     * first: only the dialog this window owns is ours.
     */
    private static JDialog devToolsWindow() {
        for (Window w : Window.getWindows()) {
            if (w instanceof JDialog d && d.getOwner() == window.frame() && "Developer tools".equals(d.getTitle())) {
                return d;
            }
        }
        return null;
    }

    @Test
    @Order(3)
    void bAddsTheYellowOverlayAndTakesItAway() throws Exception {
        int before = yellow(freshFrame());
        press(KeyEvent.VK_B);
        waitFor("borders on", () -> state().settings().render().borders());
        int with = yellow(freshFrame());
        press(KeyEvent.VK_B);
        waitFor("borders off", () -> !state().settings().render().borders());
        int after = yellow(freshFrame());
        assertEquals(0, before);
        assertTrue(with > 2000, "yellow piece outlines: " + with);
        assertEquals(0, after);
        assertTrue(onEdt(() -> !cmd(ViewAction.BORDERS).selected()), "the menu and the dev tools show it off");
    }

    @Test
    @Order(4)
    void oneToFourSwitchThePathAndChangeTheFrame() throws Exception {
        int[][] frames = new int[4][];
        int[] keys = {KeyEvent.VK_1, KeyEvent.VK_2, KeyEvent.VK_3, KeyEvent.VK_4};
        for (RenderMode m : RenderMode.values()) {
            press(keys[m.ordinal()]);
            waitFor(m.id(), () -> state().settings().render().mode() == m);
            frames[m.ordinal()] = freshFrame();
            assertTrue(onEdt(() -> c().commands().modes.get(m.ordinal()).selected()), "the Render menu follows");
        }
        assertFalse(Arrays.equals(frames[0], frames[1]), "affine differs from perspective");
        assertFalse(Arrays.equals(frames[1], frames[2]), "tessellated differs from affine");
        assertFalse(Arrays.equals(frames[0], frames[2]), "tessellated differs from perspective, slightly");
        long differ = 0;
        for (int i = 0; i < frames[0].length; i++) {
            differ += frames[0][i] != frames[2][i] ? 1 : 0;
        }
        long affineDiffer = 0;
        for (int i = 0; i < frames[0].length; i++) {
            affineDiffer += frames[0][i] != frames[1][i] ? 1 : 0;
        }
        assertTrue(differ < affineDiffer, "tessellated is closer to perspective than affine is");
        long spansDiffer = 0;
        for (int i = 0; i < frames[0].length; i++) {
            spansDiffer += frames[0][i] != frames[3][i] ? 1 : 0;
        }
        assertTrue(spansDiffer > 0 && spansDiffer < affineDiffer, "spans differ from perspective, less than affine: "
                + spansDiffer + " pixels against " + affineDiffer);
    }

    @Test
    @Order(4)
    void fStepsTheTextureFilterFromTrilinear() throws Exception {
        assertEquals(TextureFilter.TRILINEAR, state().settings().render().filter(), "the demo opens trilinear");
        TextureFilter[] order = {TextureFilter.NEAREST, TextureFilter.BILINEAR, TextureFilter.TRILINEAR};
        int[][] frames = new int[3][];
        for (int i = 0; i < 3; i++) {
            TextureFilter f = order[i];
            press(KeyEvent.VK_F);
            waitFor(f.id(), () -> state().settings().render().filter() == f);
            frames[i] = freshFrame();
            assertEquals("Texture filter: " + f.id(), onEdt(() -> cmd(ViewAction.TEXTURE_FILTER).getValue(Action.NAME)),
                    "the View menu entry names the filter");
        }
        assertFalse(Arrays.equals(frames[0], frames[1]), "bilinear differs from nearest");
        assertFalse(Arrays.equals(frames[1], frames[2]), "trilinear differs from bilinear");
    }

    private static double number(String json, String key) {
        Matcher m = Pattern.compile("\"" + key + "\":(-?[0-9.eE+-]+|null)").matcher(json);
        assertTrue(m.find(), key + " in " + json);
        return m.group(1).equals("null") ? Double.NaN : Double.parseDouble(m.group(1));
    }

    @Test
    @Order(5)
    void comparisonNumbersAppearAndAgreeWithTheCommandLine() throws Exception {
        press(KeyEvent.VK_3);
        // The key reaches the event thread some time after the robot returns (longer under load): read
        // the settings only once it has, or they are the spans path's, whose numbers the tools replace.
        waitFor("the tessellated path", () -> state().settings().render().mode() == RenderMode.TESSELLATED);
        ViewSettings now = state().settings();
        waitFor("a measurement of the current settings", () -> {
            ViewState.Measurement m = state().measurement();
            return m != null && m.settings().equals(now);
        });
        ViewState.Measurement m = state().measurement();
        Comparison c = m.comparison();
        waitFor("the readouts", () -> onEdt(() -> String.format(Locale.ROOT, "%.3f px", c.maxDisplacement())
                .equals(tools().readout("Max displacement"))));
        String p99 = onEdt(() -> tools().readout("p99 displacement"));
        assertEquals(String.format(Locale.ROOT, "%.3f px", c.p99Displacement()), p99);
        assertEquals(String.format(Locale.ROOT, "%.3f px", c.meanDisplacement()),
                onEdt(() -> tools().readout("Mean displacement")));
        assertNotNull(onEdt(() -> tools().readout("PSNR")));
        List<String> args = CliArgs.compare(AssetScenes.assetOf(state().scene()).orElseThrow(), m);
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        assertEquals(0, Cli.run(new PrintWriter(out, true), new PrintWriter(err, true), args.toArray(String[]::new)),
                err.toString());
        String json = out.toString();
        assertEquals(c.maxDisplacement(), number(json, "max_displacement"), 0.0, "same frame, same numbers");
        assertEquals(c.p99Displacement(), number(json, "p99_displacement"), 0.0);
        assertEquals(c.meanDisplacement(), number(json, "mean_displacement"), 0.0);
        assertEquals(c.texelDifferShare(), number(json, "texel_differ_share"), 0.0);
        assertEquals(c.psnrDb(), number(json, "psnr_db"), 0.0);
    }

    @Test
    @Order(6)
    void resizingTinyAndHugeAndMinimizingNeverThrows() throws Exception {
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread.UncaughtExceptionHandler previous = Thread.getDefaultUncaughtExceptionHandler();
        Thread.setDefaultUncaughtExceptionHandler((t, e) -> failure.set(e));
        try {
            for (int[] size : new int[][] {{20, 20}, {1, 1}, {2600, 1800}, {700, 500}}) {
                SwingUtilities.invokeAndWait(() -> window.frame().setSize(size[0], size[1]));
                Thread.sleep(300);
            }
            SwingUtilities.invokeAndWait(() -> window.frame().setExtendedState(java.awt.Frame.ICONIFIED));
            Thread.sleep(300);
            SwingUtilities.invokeAndWait(() -> window.frame().setExtendedState(java.awt.Frame.NORMAL));
            long before = state().progress().frames();
            waitFor("frames after restoring", () -> state().progress().frames() > before + 3);
            SwingUtilities.invokeAndWait(() -> {
                JDialog d = devToolsWindow();
                if (d != null) {
                    d.dispatchEvent(new java.awt.event.WindowEvent(d, java.awt.event.WindowEvent.WINDOW_CLOSING));
                }
            });
            waitFor("frames after closing the tools", () -> state().progress().frames() > before + 6);
            assertFalse(onEdt(() -> cmd(ViewAction.DEV_TOOLS).selected()), "F12's state follows the closed window");
        } finally {
            Thread.setDefaultUncaughtExceptionHandler(previous);
        }
        assertEquals(null, failure.get());
    }

    @Test
    @Order(7)
    void f6ShowsTheDifferenceWithTheToolsAndClosingThemGoesBackToTheImage() throws Exception {
        press(KeyEvent.VK_F6);
        waitFor("the difference view", () -> state().settings().view() == ViewKind.DIFFERENCE);
        waitFor("the developer tools", () -> onEdt(() -> devToolsWindow() != null && devToolsWindow().isShowing()));
        freshFrame();
        assertEquals(ViewKind.DIFFERENCE, onEdt(() -> front().view));
        press(KeyEvent.VK_F12);
        waitFor("the tools to close", () -> onEdt(() -> !devToolsWindow().isShowing()));
        assertEquals(ViewKind.IMAGE, state().settings().view(), "no heat map left behind");
        freshFrame();
        assertEquals(ViewKind.IMAGE, onEdt(() -> front().view));
        assertTrue(onEdt(() -> c().commands().views.get(ViewKind.IMAGE.ordinal()).selected()), "the View menu follows");
        press(KeyEvent.VK_F7);
        waitFor("the split view", () -> state().settings().view() == ViewKind.SPLIT);
        press(KeyEvent.VK_F5);
        waitFor("the image", () -> state().settings().view() == ViewKind.IMAGE);
    }

    @Test
    @Order(8)
    void untickingTheMeasurementGreysTheNumbersAndStopsTheHeatMap() throws Exception {
        press(KeyEvent.VK_F6);
        waitFor("the difference view with the tools", () -> state().settings().view() == ViewKind.DIFFERENCE
                && onEdt(() -> devToolsWindow() != null && devToolsWindow().isShowing()));
        CompareSection compare = onEdt(() -> tools().section(CompareSection.class));
        waitFor("live numbers", () -> onEdt(() -> compare.live("PSNR")));
        SwingUtilities.invokeAndWait(() -> compare.measureBox().doClick());
        assertFalse(state().settings().compare());
        assertEquals(ViewKind.IMAGE, state().settings().view(), "the heat map stops with the measurement");
        waitFor("greyed numbers", () -> onEdt(() -> !compare.live("PSNR") && !compare.live("Max displacement")));
        assertTrue(onEdt(() -> tools().readout("PSNR")).matches("[0-9.]+ dB|identical"),
                "greyed, not hidden (docs/demo.md): " + onEdt(() -> tools().readout("PSNR")));
        assertTrue(onEdt(() -> tools().readout("Max displacement")).endsWith(" px"));
        SwingUtilities.invokeAndWait(() -> compare.measureBox().doClick());
        waitFor("live numbers again", () -> onEdt(() -> compare.live("PSNR")));
    }

    @Test
    @Order(9)
    void theToolsWindowShowsEverySectionOrScrollsByRows() throws Exception {
        JDialog d = onEdt(DemoWindowGuiTest::devToolsWindow);
        int content = onEdt(() -> tools().scrollPane().getViewport().getView().getPreferredSize().height);
        int viewport = onEdt(() -> tools().scrollPane().getViewport().getExtentSize().height);
        java.awt.Rectangle usable = java.awt.GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        int room = usable.y + usable.height - onEdt(d::getY);
        assertTrue(viewport >= content || onEdt(d::getHeight) >= room - 1,
                "all " + content + " px of sections fit, or the window reaches the screen's edge: viewport "
                        + viewport + ", room " + room);
        assertTrue(onEdt(() -> tools().scrollPane().getVerticalScrollBar().getUnitIncrement()) >= 16);
    }

    @Test
    @Order(10)
    void ctrlSSavesIntoPicturesAndSaysWhere() throws Exception {
        Path home = Files.createTempDirectory("trisect-home");
        Files.createDirectory(home.resolve("Pictures"));
        String before = System.getProperty("user.home");
        System.setProperty("user.home", home.toString());
        try {
            robot.keyPress(KeyEvent.VK_CONTROL);
            press(KeyEvent.VK_S);
            robot.keyRelease(KeyEvent.VK_CONTROL);
            waitFor("the screenshot", () -> onEdt(() -> window.statusText().startsWith("Saved screenshot to")));
            String status = onEdt(() -> window.statusText());
            assertTrue(status.contains(home.resolve("Pictures").toString()), status);
            try (var files = Files.list(home.resolve("Pictures"))) {
                assertEquals(1, files.filter(f -> f.getFileName().toString().endsWith(".png")).count());
            }
        } finally {
            System.setProperty("user.home", before);
        }
    }

    @Test
    @Order(11)
    void spaceFreezesPeriodStepsOneFrameAndTheCameraReadoutFollows() throws Exception {
        press(KeyEvent.VK_SPACE);
        waitFor("frozen", () -> state().freeze.frozen());
        assertTrue(onEdt(() -> cmd(ViewAction.FREEZE).selected()), "the View menu shows it");
        // A frame already being drawn when Space was pressed still arrives; wait until the loop holds
        // (that frame handed over) and it is on screen. A quiet spell of 300 ms was no proof: under load
        // a frame of four paths and a comparison can take longer, and then arrived after "held".
        waitFor("the last frame on screen", () -> state().freeze.holding()
                && onEdt(() -> front().serial) == state().progress().frames());
        long held = onEdt(() -> front().serial);
        Thread.sleep(400);
        assertEquals(held, (long) onEdt(() -> front().serial), "no new frames while frozen");
        press(KeyEvent.VK_PERIOD);
        waitFor("one step", () -> onEdt(() -> front().serial) == held + 1);
        Thread.sleep(300);
        assertEquals(held + 1, (long) onEdt(() -> front().serial), "one frame per step");
        waitFor("the camera readout", () -> onEdt(() -> {
            var eye = front().camera.eye();
            return String.format(Locale.ROOT, "%.3f, %.3f, %.3f", eye.x(), eye.y(), eye.z()).replace("-0.000", "0.000")
                    .equals(tools().readout("Eye"));
        }));
        press(KeyEvent.VK_SPACE);
        waitFor("running again", () -> onEdt(() -> front().serial) > held + 3);
        assertFalse(state().freeze.frozen());
    }

    @Test
    @Order(12)
    void cCyclesTheBorderColouringAndTurnsTheBordersOn() throws Exception {
        var start = state().settings().render().borderStyle().colouring();
        press(KeyEvent.VK_C);
        waitFor("the next colouring", () -> state().settings().render().borderStyle().colouring() != start);
        assertTrue(state().settings().render().borders(), "C shows the borders it colours");
        press(KeyEvent.VK_C);
        press(KeyEvent.VK_C);
        waitFor("back round", () -> state().settings().render().borderStyle().colouring() == start);
        press(KeyEvent.VK_B);
        waitFor("borders off", () -> !state().settings().render().borders());
    }

    @Test
    @Order(13)
    void iInspectsThePixelUnderTheMouseAndAClickPinsIt() throws Exception {
        var at = onEdt(() -> window.view().getLocationOnScreen());
        int vw = onEdt(() -> window.view().getWidth());
        int vh = onEdt(() -> window.view().getHeight());
        robot.mouseMove(at.x + vw / 3, at.y + vh / 3);
        press(KeyEvent.VK_I);
        waitFor("the inspector", () -> onEdt(() -> cmd(ViewAction.PIXEL_INSPECTOR).selected()) && state().inspected() >= 0);
        waitFor("an inspected frame", () -> onEdt(() -> front().inspection != null));
        robot.mouseMove(at.x + vw / 2, at.y + vh / 2);
        waitFor("the inspector to follow", () -> onEdt(() -> front().inspection != null
                && front().inspection.x() == (int) ((long) (vw / 2) * front().width()
                        / vw)));
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        waitFor("pinned", () -> onEdt(() -> mouse().pinned()));
        long pinnedAt = state().inspected();
        robot.mouseMove(at.x + 200, at.y + 200);
        Thread.sleep(300);
        assertEquals(pinnedAt, state().inspected(), "a pinned inspector stays put");
        // Ctrl+C copies the readout as text (the View menu's "Copy inspector readout").
        robot.keyPress(KeyEvent.VK_CONTROL);
        press(KeyEvent.VK_C);
        robot.keyRelease(KeyEvent.VK_CONTROL);
        waitFor("the readout on the clipboard", () -> onEdt(() -> {
            var clip = java.awt.Toolkit.getDefaultToolkit().getSystemClipboard();
            Object text = clip.isDataFlavorAvailable(java.awt.datatransfer.DataFlavor.stringFlavor)
                    ? clip.getData(java.awt.datatransfer.DataFlavor.stringFlavor) : "";
            return text.toString().startsWith("pixel " + front().inspection.x() + "," + front().inspection.y());
        }));
        press(KeyEvent.VK_I);
        waitFor("the inspector off", () -> state().inspected() < 0);
    }

    @Test
    @Order(14)
    void pSwitchesTheSplitPolicyAndTheMenuNamesIt() throws Exception {
        var start = state().settings().render().tessellation().policy();
        press(KeyEvent.VK_P);
        waitFor("the other policy", () -> state().settings().render().tessellation().policy() != start);
        String name = onEdt(() -> (String) cmd(ViewAction.SPLIT_POLICY).getValue(javax.swing.Action.NAME));
        assertTrue(name.endsWith(state().settings().render().tessellation().policy().name()
                .toLowerCase(Locale.ROOT)), name);
        // Feedback without the tools: the status bar says which policy is in force, and its right side names it.
        waitFor("the status bar's word on P", () -> onEdt(() -> window.statusText().startsWith("Split policy: ")));
        String said = onEdt(() -> window.statusText());
        String policy = state().settings().render().tessellation().policy() == SplitPolicy.EDGE ? "Edge" : "Error";
        assertTrue(said.startsWith("Split policy: " + policy), said);
        waitFor("the policy beside path and filter", () -> onEdt(() -> window.paceText())
                .contains(policy.toLowerCase(Locale.ROOT) + " "));
        press(KeyEvent.VK_P);
        waitFor("back", () -> state().settings().render().tessellation().policy() == start);
    }

    @Test
    @Order(15)
    void theFileMenuGoesBackToTheBuiltInScenes() throws Exception {
        javax.swing.JMenu scenes = onEdt(() -> window.fileMenu.scenesMenu());
        assertEquals(DemoScenes.names().size(), (int) onEdt(scenes::getItemCount));
        javax.swing.JMenuItem floor = onEdt(() -> {
            for (int i = 0; i < scenes.getItemCount(); i++) {
                if (scenes.getItem(i).getText().equals("Floor")) {
                    return scenes.getItem(i);
                }
            }
            return null;
        });
        assertNotNull(floor);
        SwingUtilities.invokeAndWait(floor::doClick);
        waitFor("the floor scene", () -> onEdt(() -> window.frame().getTitle()).equals("Trisect \u2014 floor"));
        javax.swing.JMenuItem demo = onEdt(() -> scenes.getItem(DemoScenes.names().indexOf("demo")));
        SwingUtilities.invokeAndWait(demo::doClick);
        waitFor("the demo scene again", () -> onEdt(() -> window.frame().getTitle()).equals("Trisect \u2014 demo"));
    }
}
