package dev.trisect.ui;

import static dev.trisect.GuiTests.onEdt;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.GuiTests;
import java.awt.Component;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import javax.swing.Action;
import javax.swing.InputMap;
import javax.swing.JComponent;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The demo's table of commands (DemoCommands.table) as the window builds it: each key taken once and
 * not one of the view's, each in the F1 table, each item in its menu.
 */
@Tag("gui")
class DemoCommandsGuiTest {
    private DemoWindow window;

    @AfterEach
    void close() throws Exception {
        if (window != null) {
            SwingUtilities.invokeAndWait(() -> window.frame().dispose());
        }
    }

    @Test
    void eachCommandHasOneFreeKeyAHelpRowAndOneItem() throws Exception {
        GuiTests.requireDisplay();
        window = onEdt(DemoWindows::demo);
        List<DemoCommands.Entry> table = window.commands;
        Map<KeyStroke, Object> taken = new HashMap<>();
        InputMap viewKeys = onEdt(() -> window.view().getInputMap(JComponent.WHEN_FOCUSED));
        for (KeyStroke k : viewKeys.allKeys()) {
            taken.put(k, "the view's " + viewKeys.get(k));
        }
        List<Action> items = onEdt(() -> items(window.frame().getJMenuBar()));
        for (DemoCommands.Entry e : table) {
            String name = (String) e.action().getValue(Action.NAME);
            KeyStroke key = e.key();
            if (key != null) {
                assertNull(taken.put(key, name), name + "'s key " + key + " is taken by " + taken.get(key));
                String text = DemoCommands.keyText(key);
                assertTrue(java.util.Arrays.stream(DemoHelp.ROWS).anyMatch(r -> r[0].contains(text)),
                        name + ": no row of DemoHelp.ROWS (the F1 panel, docs/demo.md) names its key " + text);
            }
            assertEquals(1, items.stream().filter(a -> a == e.action()).count(), name + " has one menu item");
        }
    }

    /** The actions of every item in the bar, submenus included. */
    private static List<Action> items(JMenuBar bar) {
        List<Action> out = new ArrayList<>();
        for (int i = 0; i < bar.getMenuCount(); i++) {
            collect(bar.getMenu(i), out);
        }
        return out;
    }

    private static void collect(JMenu menu, List<Action> out) {
        for (Component c : menu.getMenuComponents()) {
            if (c instanceof JMenu sub) {
                collect(sub, out);
            } else if (c instanceof JMenuItem item && item.getAction() != null) {
                out.add(item.getAction());
            }
        }
    }
}
