package dev.trisect.ui;

import static dev.trisect.GuiTests.onEdt;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.GuiTests;
import java.awt.Component;
import java.awt.event.ActionEvent;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BooleanSupplier;
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

    /**
     * Every check-box command turns on from its menu item as from its key, and off again either way: a
     * check-box item flips the action's selected state before the action runs, and the demo's toggles
     * read that as already on, so a click on Frame-rate HUD, Fog, Labels or Uncapped did nothing.
     */
    @Test
    void eachToggleTurnsOnAndOffFromItsItemAsFromItsKey() throws Exception {
        GuiTests.requireDisplay();
        window = onEdt(DemoWindows::demo);
        Map<String, BooleanSupplier> effect = Map.of(
                "Uncapped frame rate", () -> window.view().getMaxFrameRate() == 0,
                "Fog", () -> window.lighting.fog(),
                "Labels, axes and glass pane", () -> window.shapes.extras(),
                "Frame-rate HUD", () -> window.shapes.hud());
        List<JMenuItem> items = onEdt(() -> menuItems(window.frame().getJMenuBar()));
        ActionEvent key = new ActionEvent(window.frame().getRootPane(), ActionEvent.ACTION_PERFORMED, null);
        for (DemoCommands.Entry e : window.commands) {
            if (!e.check()) {
                continue;
            }
            String name = (String) e.action().getValue(Action.NAME);
            BooleanSupplier on = effect.get(name);
            assertTrue(on != null, name + ": a new toggle; say here what it does, to check it");
            JMenuItem item = items.stream().filter(i -> i.getAction() == e.action()).findFirst().orElseThrow();
            assertFalse(onEdt(on::getAsBoolean), name + " starts off");
            onEdt(() -> {
                item.doClick(0);
                return null;
            });
            assertTrue(onEdt(on::getAsBoolean), name + ": on from its menu item");
            assertTrue(onEdt(item::isSelected), name + ": its item checked");
            onEdt(() -> {
                e.action().actionPerformed(key);
                return null;
            });
            assertFalse(onEdt(on::getAsBoolean), name + ": off from its key");
            assertFalse(onEdt(item::isSelected), name + ": its item unchecked");
            onEdt(() -> {
                e.action().actionPerformed(key);
                item.doClick(0);
                return null;
            });
            assertFalse(onEdt(on::getAsBoolean), name + ": on from its key, off from its item");
        }
    }

    /** Every item in the bar, submenus included. */
    private static List<JMenuItem> menuItems(JMenuBar bar) {
        List<JMenuItem> out = new ArrayList<>();
        for (int i = 0; i < bar.getMenuCount(); i++) {
            collectItems(bar.getMenu(i), out);
        }
        return out;
    }

    private static void collectItems(JMenu menu, List<JMenuItem> out) {
        for (Component c : menu.getMenuComponents()) {
            if (c instanceof JMenu sub) {
                collectItems(sub, out);
            } else if (c instanceof JMenuItem item) {
                out.add(item);
            }
        }
    }

    /** The actions of every item in the bar, submenus included. */
    private static List<Action> items(JMenuBar bar) {
        return menuItems(bar).stream().map(JMenuItem::getAction).filter(a -> a != null).toList();
    }
}
