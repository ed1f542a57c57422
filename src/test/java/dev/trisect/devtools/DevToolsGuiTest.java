package dev.trisect.devtools;

import static dev.trisect.GuiTests.edt;
import static dev.trisect.GuiTests.onEdt;
import static dev.trisect.GuiTests.waitFor;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.GuiTests;
import dev.trisect.content.AssetScenes;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.content.SceneLoader;
import dev.trisect.render.RenderMode;
import dev.trisect.view.TrisectView;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewState;
import java.awt.Component;
import java.awt.Dimension;
import java.awt.KeyboardFocusManager;
import java.awt.Point;
import java.awt.Robot;
import java.awt.Window;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import javax.swing.JFrame;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The developer tools window with real clicks and key presses under an X server. */
@Tag("gui")
class DevToolsGuiTest {
    private static Robot robot;
    private final GuiTests.Uncaught uncaught = new GuiTests.Uncaught();
    private final List<String> messages = new CopyOnWriteArrayList<>();
    private final AtomicInteger frames = new AtomicInteger();
    private JFrame host;
    private TrisectView view;

    @BeforeAll
    static void robot() throws Exception {
        robot = GuiTests.robot("DevToolsGuiTest");
    }

    @BeforeEach
    void open() throws Exception {
        GuiTests.requireDisplay();
        uncaught.start();
        edt(() -> {
            host = new JFrame("host");
            view = new TrisectView(AssetScenes.scene(DemoScenes.boxes()), 1);
            view.setPreferredSize(new Dimension(320, 240));
            view.addFrameListener(f -> frames.incrementAndGet());
            // These tests watch frames flow: keep them coming, as an animation does (a still view idles).
            view.addUpdateListener((step, frame) -> true);
            view.addMessageListener(messages::add);
            host.getContentPane().add(view);
            host.pack();
            host.setLocation(0, 0);
            host.setVisible(true);
        });
        waitFor("frames", () -> frames.get() >= 2);
        edt(() -> view.showDevTools(true));
        waitFor("the developer tools", () -> onEdt(() -> dialog() != null && dialog().isShowing()));
        click(view);
        waitFor("the view to have the keyboard", () -> onEdt(() -> view.isFocusOwner()));
    }

    @AfterEach
    void close() throws Exception {
        if (host != null) {
            edt(() -> host.dispose());
        }
        uncaught.check();
    }

    private static DevToolsDialog dialog() {
        for (Window w : Window.getWindows()) {
            if (w instanceof DevToolsDialog d && w.isDisplayable()) {
                return d;
            }
        }
        return null;
    }

    private ViewState state() {
        return ((ViewController) view.getClientProperty(ViewController.class)).state();
    }

    private static void click(Component c) throws Exception {
        Point p = onEdt(() -> {
            if (c instanceof javax.swing.JComponent j) {
                j.scrollRectToVisible(new java.awt.Rectangle(0, 0, c.getWidth(), c.getHeight()));
            }
            Point at = c.getLocationOnScreen();
            return new Point(at.x + c.getWidth() / 2, at.y + c.getHeight() / 2);
        });
        robot.mouseMove(p.x, p.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
    }

    private static void type(int... keys) {
        for (int k : keys) {
            robot.keyPress(k);
            robot.keyRelease(k);
        }
    }

    private static Component focusOwner() {
        return KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner();
    }

    /** Clicks a field and waits until it has the keyboard (it then selects its text). */
    private static void focus(NumberField field) throws Exception {
        // Its section may have been folded to fit the screen: open it.
        edt(() -> {
            for (Component p = field; p != null; p = p.getParent()) {
                ToolsForm f = ToolsForm.of(p);
                if (f != null && !f.open()) {
                    f.setOpen(true);
                }
            }
        });
        waitFor("the field to show", () -> onEdt(field::isShowing));
        click(field);
        waitFor("the field to have the keyboard", () -> onEdt(() -> focusOwner() == field));
    }

    @Test
    void numbersTypedIntoTheToolsApplyAndTheirDigitsStayOutOfTheViewsKeys() throws Exception {
        DevToolsPanel tools = onEdt(() -> dialog().panel());
        NumberField target = onEdt(() -> tools.section(BudgetSection.class).targetField());
        focus(target);
        type(KeyEvent.VK_4, KeyEvent.VK_0, KeyEvent.VK_ENTER);
        waitFor("the typed target", () -> state().budget().targetMs() == 40);
        // A target under 1 ms, as demo --target-ms and the view take: the field took only 1 to 1000.
        focus(target);
        type(KeyEvent.VK_0, KeyEvent.VK_PERIOD, KeyEvent.VK_5, KeyEvent.VK_ENTER);
        waitFor("the typed target under 1 ms", () -> state().budget().targetMs() == 0.5);
        assertEquals(RenderMode.TESSELLATED, state().settings().render().mode(), "the 4 typed is not key 4 (spans)");

        NumberField maxEdge = onEdt(() -> tools.section(SplitPolicySection.class).fields()[0]);
        focus(maxEdge);
        type(KeyEvent.VK_1, KeyEvent.VK_2, KeyEvent.VK_ENTER);
        waitFor("the typed max edge", () -> state().settings().render().tessellation().maxEdge() == 12);
        assertEquals(RenderMode.TESSELLATED, state().settings().render().mode(), "1 and 2 typed are not the paths' keys");
        assertEquals("12 px", onEdt(maxEdge::getText));

        // Still in the field, its text selected after Enter: the next typing replaces it.
        type(KeyEvent.VK_X, KeyEvent.VK_ENTER);
        waitFor("a message about the typing", () -> !messages.isEmpty());
        assertTrue(messages.get(0).startsWith("trisect: Max edge: \"x\" is not a number from 2 to 128 px"), messages.get(0));
        assertEquals(12, state().settings().render().tessellation().maxEdge(), "bad text changes nothing");
        assertEquals("12 px", onEdt(maxEdge::getText), "and the field shows the value in force again");

        // Then an accepted number: the refusal must not stay in the status bar (it did for its 8 s).
        type(KeyEvent.VK_1, KeyEvent.VK_6, KeyEvent.VK_ENTER);
        waitFor("the typed max edge", () -> state().settings().render().tessellation().maxEdge() == 16);
        waitFor("a message after the refusal", () -> messages.size() >= 2);
        assertEquals("Max edge: 16 px", messages.get(messages.size() - 1), "the accepted value replaces the refusal");
    }

    @Test
    void theViewsKeysWorkWhileAControlOfTheToolsHasTheKeyboard() throws Exception {
        DevToolsPanel tools = onEdt(() -> dialog().panel());
        NumberField maxDepth = onEdt(() -> tools.section(SplitPolicySection.class).fields()[2]);
        focus(maxDepth);
        type(KeyEvent.VK_F7);
        waitFor("the split view from F7 in a field", () -> state().settings().view()
                == dev.trisect.view.internal.ViewKind.SPLIT);
        type(KeyEvent.VK_TAB);
        waitFor("the keyboard to leave the field", () -> onEdt(() -> !(focusOwner() instanceof NumberField)));
        boolean borders = state().settings().render().borders();
        type(KeyEvent.VK_B);
        waitFor("B to toggle the borders from the tools", () -> state().settings().render().borders() != borders);
    }

    @Test
    void theToolsFitTheScreenWithStatisticsWholeAndFoldedSectionsOpenOnAClick() throws Exception {
        DevToolsPanel tools = onEdt(() -> dialog().panel());
        javax.swing.JComponent stats = onEdt(() -> tools.section(StatisticsSection.class).component());
        waitFor("the window to settle", () -> onEdt(() -> tools.scrollPane().getViewport().getExtentSize().height
                >= tools.scrollPane().getViewport().getView().getPreferredSize().height));
        java.awt.Rectangle shown = onEdt(() -> tools.scrollPane().getViewport().getViewRect());
        java.awt.Rectangle at = onEdt(stats::getBounds);
        assertTrue(shown.contains(at), "Statistics " + at + " whole in the window's view " + shown);
        ToolsForm folded = onEdt(() -> ToolsForm.of(tools.section(RenderSection.class).component()));
        if (!onEdt(folded::open)) {
            click(onEdt(folded::header));
            waitFor("the section to open", () -> onEdt(folded::open));
        }
        click(onEdt(folded::header));
        waitFor("the section to fold", () -> onEdt(() -> !folded.open()));
    }

    @Test
    void aModelWithoutTextureCoordinatesReadsDashesWhereNothingWasMeasured(@TempDir Path dir) throws Exception {
        // An OBJ without vt: every pixel's texture coordinates span no area, so no displacement exists;
        // compare prints null for it, and the tools read "NaN px" (found by the demo trial).
        Path obj = dir.resolve("flat.obj");
        Files.writeString(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        SceneAsset flat = SceneLoader.load(obj, null, note -> { }, true);
        edt(() -> {
            view.setScene(AssetScenes.scene(flat));
            view.setCamera(flat.camera());
        });
        DevToolsPanel tools = onEdt(() -> dialog().panel());
        waitFor("the flat model measured", () -> onEdt(() -> tools.readout("Mean displacement")).contains("no UV area"));
        for (String k : CompareSection.MEASURES) {
            String text = onEdt(() -> tools.readout(k));
            assertTrue(!text.contains("NaN"), k + ": " + text);
        }
        assertEquals("\u2014", onEdt(() -> tools.readout("Max displacement")));
        assertTrue(onEdt(() -> tools.readout("Mean displacement")).startsWith("\u2014 ("),
                onEdt(() -> tools.readout("Mean displacement")));
        assertEquals("\u2014", CompareSection.measure("%.2f %%", Double.NaN), "no pixel compared: no share");
        assertEquals("0.50 %", CompareSection.measure("%.2f %%", 0.5));
    }
}
