package dev.trisect.ui;

import static dev.trisect.GuiTests.onEdt;
import static dev.trisect.GuiTests.waitFor;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.GuiTests;
import dev.trisect.content.DemoScenes;
import java.awt.Component;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.event.MouseEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.MenuElement;
import javax.swing.MenuSelectionManager;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * No tooltip of the demo's menus covers another menu item: in the File menu Built-in scene's tip lay
 * over Floor, and Open recent's over Built-in scene, and took their clicks (found by a new user's trial).
 */
@Tag("gui")
class MenuTooltipGuiTest {
    private DemoWindow window;

    @AfterEach
    void close() throws Exception {
        MenuSelectionManager.defaultManager().clearSelectedPath();
        if (window != null) {
            SwingUtilities.invokeAndWait(() -> window.frame().dispose());
        }
    }

    @Test
    void noMenuTooltipCoversAnotherItem() throws Exception {
        GuiTests.requireDisplay();
        Path home = Files.createTempDirectory("trisect-recent");
        RecentFiles recent = new RecentFiles(home.resolve("demo.properties"));
        recent.opened(home.resolve("model.obj"));
        window = DemoApp.openForTest(DemoScenes.demo(), 1, recent);
        waitFor("the window", () -> onEdt(() -> window.frame().isShowing()));
        JMenuBar bar = onEdt(() -> window.frame().getJMenuBar());
        int checked = 0;
        for (int m = 0; m < onEdt(bar::getMenuCount); m++) {
            int index = m;
            JMenu menu = onEdt(() -> bar.getMenu(index));
            List<JMenu> subs = onEdt(() -> submenus(menu));
            // The menu alone, then with each of its submenus open beside it.
            List<JMenu> opened = new ArrayList<>();
            opened.add(null);
            opened.addAll(subs);
            for (JMenu sub : opened) {
                GuiTests.edt(() -> MenuSelectionManager.defaultManager().setSelectedPath(sub == null
                        ? new MenuElement[] {bar, menu, menu.getPopupMenu()}
                        : new MenuElement[] {bar, menu, menu.getPopupMenu(), sub, sub.getPopupMenu()}));
                waitFor("the menu open", () -> onEdt(() -> menu.getPopupMenu().isShowing()
                        && (sub == null || sub.getPopupMenu().isShowing())));
                checked += onEdt(() -> checkOpen(menu, sub));
            }
            GuiTests.edt(() -> MenuSelectionManager.defaultManager().clearSelectedPath());
        }
        assertTrue(checked > 20, "tooltips checked: " + checked);
    }

    /** The submenus of {@code menu} (Open recent, Built-in scene). */
    private static List<JMenu> submenus(JMenu menu) {
        List<JMenu> subs = new ArrayList<>();
        for (Component c : menu.getMenuComponents()) {
            if (c instanceof JMenu s) {
                subs.add(s);
            }
        }
        return subs;
    }

    /**
     * Checks the items of the innermost open popup ({@code sub}'s, or {@code menu}'s when null) — the
     * ones the mouse can rest on with these popups open — against every item showing; returns how many
     * had a tooltip.
     */
    private static int checkOpen(JMenu menu, JMenu sub) {
        List<JMenuItem> showing = new ArrayList<>();
        addItems(menu, showing);
        List<JMenuItem> hovered = new ArrayList<>();
        addItems(sub == null ? menu : sub, hovered);
        if (sub != null) {
            addItems(sub, showing);
        }
        int tips = 0;
        for (JMenuItem item : hovered) {
            if (item instanceof JMenu s) {
                assertNull(s.getToolTipText(), s.getText() + ": a submenu's tooltip would lie over its own items");
                continue;
            }
            if (item.getToolTipText() == null) {
                continue;
            }
            tips++;
            Rectangle tip = tipOnScreen(item);
            for (JMenuItem other : showing) {
                if (other != item) {
                    Rectangle r = new Rectangle(other.getLocationOnScreen(), other.getSize());
                    assertTrue(!tip.intersects(r), item.getText() + "'s tooltip " + tip + " covers " + other.getText()
                            + " " + r);
                }
            }
        }
        return tips;
    }

    private static void addItems(JMenu menu, List<JMenuItem> into) {
        for (Component c : menu.getMenuComponents()) {
            if (c instanceof JMenuItem i && i.isShowing()) {
                into.add(i);
            }
        }
    }

    /**
     * Where Swing shows {@code item}'s tooltip for a mouse at the item's middle: at the item's own
     * tooltip location, or, when it names none, 20 px below the mouse (ToolTipManager's default).
     */
    private static Rectangle tipOnScreen(JMenuItem item) {
        Point mouse = new Point(item.getWidth() / 2, item.getHeight() / 2);
        MouseEvent e = new MouseEvent(item, MouseEvent.MOUSE_MOVED, 0, 0, mouse.x, mouse.y, 0, false);
        Point at = item.getToolTipLocation(e);
        if (at == null) {
            at = new Point(mouse.x, mouse.y + 20);
        }
        Point screen = item.getLocationOnScreen();
        assertEquals(true, item.isShowing());
        return new Rectangle(new Point(screen.x + at.x, screen.y + at.y), MenuItems.tipSize(item));
    }
}
