package dev.trisect.ui;

import static dev.trisect.GuiTests.edt;
import static dev.trisect.GuiTests.onEdt;
import static dev.trisect.GuiTests.waitFor;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.GuiTests;
import dev.trisect.content.DemoScenes;
import dev.trisect.devtools.DevToolsDialog;
import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.Container;
import java.awt.GraphicsEnvironment;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Window;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** The developer tools window docks to the demo's window, follows it, and never covers its status bar. */
@Tag("gui")
class DevToolsDockGuiTest {
    private DemoWindow window;

    @AfterEach
    void close() throws Exception {
        if (window != null) {
            SwingUtilities.invokeAndWait(() -> window.frame().dispose());
        }
    }

    private Window tools() {
        for (Window w : window.frame().getOwnedWindows()) {
            if (w instanceof DevToolsDialog && w.isShowing()) {
                return w;
            }
        }
        return null;
    }

    /** The status bar's bounds on screen. */
    private Rectangle statusBar() throws Exception {
        return onEdt(() -> {
            Container content = window.frame().getContentPane();
            Component bottom = ((BorderLayout) content.getLayout()).getLayoutComponent(BorderLayout.SOUTH);
            Point at = bottom.getLocationOnScreen();
            return new Rectangle(at.x, at.y, bottom.getWidth(), bottom.getHeight());
        });
    }

    @Test
    void theToolsDockBesideTheWindowFollowItAndLeaveTheStatusBarClear() throws Exception {
        GuiTests.requireDisplay();
        Rectangle usable = GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds();
        window = DemoApp.openForTest(DemoScenes.demo(), 1);
        edt(() -> {
            window.frame().setBounds(usable.x, usable.y, 1000, 700);
            window.view().showDevTools(true);
        });
        waitFor("the tools, docked on the right", () -> onEdt(() -> tools() != null
                && tools().getX() == window.frame().getX() + window.frame().getWidth()
                && tools().getY() == window.frame().getY()));
        // It stayed where it was opened when the window moved (and covered the view when it grew).
        edt(() -> window.frame().setLocation(usable.x + 150, usable.y + 60));
        waitFor("the tools following the window", () -> onEdt(() -> tools().getX() == window.frame().getX()
                + window.frame().getWidth() && tools().getY() == window.frame().getY()));
        edt(() -> window.frame().setBounds(usable));
        waitFor("the tools over the view, clear of the status bar", () -> {
            Rectangle t = onEdt(() -> tools().getBounds());
            Rectangle bar = statusBar();
            return usable.contains(t) && !t.intersects(bar) && t.height >= 200;
        });
        assertTrue(onEdt(() -> tools().isShowing()));
    }
}
