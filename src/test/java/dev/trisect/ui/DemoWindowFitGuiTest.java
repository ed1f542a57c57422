package dev.trisect.ui;

import static dev.trisect.GuiTests.edt;
import static dev.trisect.GuiTests.onEdt;
import static dev.trisect.GuiTests.waitFor;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.GuiTests;
import dev.trisect.content.DemoScenes;
import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.Container;
import java.awt.GraphicsEnvironment;
import java.awt.Rectangle;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The demo window on the screen it gets, under an X server. */
@Tag("gui")
class DemoWindowFitGuiTest {
    private DemoWindow window;

    @AfterEach
    void close() throws Exception {
        if (window != null) {
            SwingUtilities.invokeAndWait(() -> window.frame().dispose());
        }
    }

    /** The status bar's bounds in the window's own coordinates. */
    private Rectangle statusBar() throws Exception {
        return onEdt(() -> {
            Container content = window.frame().getContentPane();
            Component bottom = ((BorderLayout) content.getLayout()).getLayoutComponent(BorderLayout.SOUTH);
            return SwingUtilities.convertRectangle(content, bottom.getBounds(), window.frame());
        });
    }

    @Test
    void theWindowAndItsStatusBarFitTheScreen() throws Exception {
        GuiTests.requireDisplay();
        window = DemoApp.openForTest(DemoScenes.demo(), 1);
        Rectangle usable = GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        Rectangle bounds = onEdt(() -> window.frame().getBounds());
        assertTrue(usable.contains(bounds), bounds + " within the screen " + usable);
        // The rule on a 1024x600 screen (this display is larger): on a 1280x720 one the 1280x767 window
        // reached past the bottom and its status bar was off screen (found by the demo trial).
        edt(() -> {
            DemoWindow.fitTo(window.frame(), new Rectangle(0, 0, 1024, 600));
            window.frame().validate();
        });
        assertEquals(new Rectangle(0, 0, 1024, 600), onEdt(() -> window.frame().getBounds()));
        Rectangle bar = statusBar();
        assertTrue(bar.height > 0 && bar.y + bar.height <= 600, "the status bar " + bar + " inside the window");
        waitFor("frames at the view's new size", () -> {
            var f = onEdt(() -> window.latest());
            return f != null && f.height() < 600 && f.width() <= 1024;
        });
    }

    /**
     * In a narrow window the right side of the status bar shows from its start, the rate and the size
     * whole: it was laid out from left of the window's edge, and read "ed, edge 32 px, trilinear idle...".
     */
    @Test
    void aNarrowWindowsStatusBarShowsTheRateAndSize() throws Exception {
        GuiTests.requireDisplay();
        window = DemoApp.openForTest(DemoScenes.demo(), 1);
        edt(() -> {
            window.frame().setSize(400, 300);
            window.frame().validate();
        });
        waitFor("a frame of the narrow view, and the bar saying so", () -> onEdt(() -> window.latest() != null
                && window.latest().width() <= 400 && window.paceText().endsWith(window.latest().width() + "x"
                + window.latest().height()) && !window.paceText().startsWith("tessellated")));
        Rectangle bar = statusBar();
        javax.swing.JLabel pace = onEdt(() -> (javax.swing.JLabel) ((BorderLayout) ((Container) ((BorderLayout)
                window.frame().getContentPane().getLayout()).getLayoutComponent(BorderLayout.SOUTH)).getLayout())
                .getLayoutComponent(BorderLayout.EAST));
        Rectangle at = onEdt(pace::getBounds);
        assertTrue(at.x >= 0 && at.x + at.width <= bar.width, "the pace " + at + " inside the bar " + bar);
        int needed = onEdt(() -> pace.getFontMetrics(pace.getFont()).stringWidth(pace.getText()));
        assertTrue(needed <= at.width, "its text whole: " + needed + " px in " + at.width);
    }

    /** A still scene draws once and idles: the status bar says so; M draws flat out and shows the rate. */
    @Test
    void aStillViewSaysIdleAndMMeasuresTheUncappedRate() throws Exception {
        GuiTests.requireDisplay();
        window = DemoApp.openForTest(DemoScenes.demo(), 1);
        waitFor("idle in the status bar", () -> onEdt(() -> window.paceText()).contains("idle, last frame "));
        javax.swing.Action uncapped = onEdt(() -> window.commands.stream().map(DemoCommands.Entry::action)
                .filter(a -> "Uncapped frame rate".equals(a.getValue(javax.swing.Action.NAME))).findFirst()
                .orElseThrow());
        double cap = onEdt(() -> window.view().getMaxFrameRate());
        long before = onEdt(() -> window.latest().number());
        edt(() -> uncapped.actionPerformed(null));
        assertEquals(0, onEdt(() -> window.view().getMaxFrameRate()), 0.0, "no cap");
        waitFor("frames flat out, and their rate", () -> onEdt(() -> window.latest().number() > before + 5
                && window.paceText().matches(".* [0-9.]+ fps .*")));
        edt(() -> uncapped.actionPerformed(null));
        assertEquals(cap, onEdt(() -> window.view().getMaxFrameRate()), 0.0, "the cap back");
        waitFor("idle again", () -> onEdt(() -> window.paceText()).contains("idle, last frame "));
    }
}
