package dev.trisect.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.render.SplitPolicy;
import dev.trisect.view.ViewAction;
import java.awt.GraphicsEnvironment;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import javax.swing.Action;
import javax.swing.JDialog;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;

/** The demo window's tools window, saving, freezing and stepping, border colouring, inspector, split policy and File menu. */
@Tag("gui")
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class DemoToolsGuiTest extends DemoWindowFixture {
    /** These tests start with the developer tools open, as F12 leaves them. */
    @BeforeAll
    static void openTheTools() throws Exception {
        if (window == null) {
            return; // no display: each test reports itself skipped
        }
        press(KeyEvent.VK_F12);
        waitFor("the developer tools", () -> onEdt(() -> devToolsWindow() != null && devToolsWindow().isShowing()));
    }
    @Test
    @Order(9)
    void theToolsWindowShowsEverySectionOrScrollsByRows() throws Exception {
        JDialog d = onEdt(DemoWindowFixture::devToolsWindow);
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
