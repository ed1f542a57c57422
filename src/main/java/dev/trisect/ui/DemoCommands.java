package dev.trisect.ui;

import dev.trisect.content.SceneLighting;
import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowEvent;
import java.util.List;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.ActionMap;
import javax.swing.InputMap;
import javax.swing.JComponent;
import javax.swing.KeyStroke;

/**
 * The demo's own commands (the view brings its own, {@code TrisectView.action}), in one table: each is
 * one {@link Action} for its menu item and its key, placed in a menu. To add one, add a line to
 * {@link #table} and its row to {@link DemoHelp#ROWS} (the F1 panel and docs/demo.md); the menus and
 * the key bindings follow from the table, and {@code DemoCommandsTest} fails when a key has no help
 * row or is taken twice. Event thread only.
 */
final class DemoCommands {
    /** The menu a command's item goes in. Items go after the menu's own, in table order. */
    enum Menu {
        FILE, VIEW, RENDER, SCENE, HELP
    }

    /**
     * A command of the table: its menu (null: its item is placed elsewhere, as Open OBJ's by
     * {@link FileMenu}), its action, and whether the item is a check box.
     */
    record Entry(Menu menu, Action action, boolean check) {
        KeyStroke key() {
            return (KeyStroke) action.getValue(Action.ACCELERATOR_KEY);
        }
    }

    private DemoCommands() {
    }

    /** The demo's commands on window {@code w}, in the order of their items. */
    static List<Entry> table(DemoWindow w) {
        return List.of(
                new Entry(null, w.fileMenu.open, false),
                new Entry(Menu.FILE, command("Save screenshot", "Save the frame on screen as a PNG in "
                        + Screenshots.folder(), ctrl(KeyEvent.VK_S), () -> Screenshots.save(w.view().frameImage(),
                        w::status)), false),
                new Entry(Menu.FILE, command("Exit", "Close Trisect", ctrl(KeyEvent.VK_Q),
                        () -> w.frame().dispatchEvent(new WindowEvent(w.frame(), WindowEvent.WINDOW_CLOSING))), false),
                new Entry(Menu.VIEW, toggle("Uncapped frame rate", "Draw frames continuously, as fast as the view "
                        + "can, with no cap: the status bar's rate is then the uncapped one (a still scene otherwise "
                        + "draws no frames, an animated one at most the screen's rate)", KeyStroke.getKeyStroke(
                        KeyEvent.VK_M, 0), w::measureUncapped), true),
                new Entry(Menu.SCENE, command("Lighting: off, flat, smooth", "Light the scene (a lamp from the "
                        + "camera, a warm light circling, a dim ambient) flat, then smooth, then not", KeyStroke.getKeyStroke(
                        KeyEvent.VK_L, 0), () -> w.status("Lighting: " + SceneLighting.word(w.lighting.cycle()))), false),
                new Entry(Menu.SCENE, toggle("Fog", "OpenGL's linear fog towards the sky's colour (on while the "
                        + "scene has any fog, the developer tools' too: G then turns it off)", KeyStroke.getKeyStroke(
                        KeyEvent.VK_G, 0), w.lighting::fog, w.lighting::setFog), true),
                new Entry(Menu.SCENE, toggle("Labels, axes and glass pane", "Labels on the scene's things, an axes "
                        + "gizmo at the origin and a blended glass pane: the engine's lines, text and transparency "
                        + "(the command line draws the scene without them)", KeyStroke.getKeyStroke(KeyEvent.VK_X, 0),
                        w.shapes::setExtras), true),
                new Entry(Menu.SCENE, command("Wireframe: filled, filled and wire, wire", "Draw the scene's objects "
                        + "filled, filled with their edges over them, then as wire alone", KeyStroke.getKeyStroke(
                        KeyEvent.VK_Z, 0), () -> w.status("Wireframe: " + w.shapes.cycleStyle().name().toLowerCase(
                        java.util.Locale.ROOT).replace('_', ' '))), false),
                new Entry(Menu.SCENE, toggle("Frame-rate HUD", "A line in the frame's bottom-left corner, drawn by the "
                        + "engine as screen text: frames per second and milliseconds a frame", KeyStroke.getKeyStroke(
                        KeyEvent.VK_H, 0), w.shapes::setHud), true),
                new Entry(Menu.HELP, command("Keys and mouse", "Show every key and mouse gesture of the demo in a "
                        + "panel", KeyStroke.getKeyStroke(KeyEvent.VK_F1, 0), w::toggleHelp), false));
    }

    /** A plain command: one action for its menu item and its key ({@code key} may be null). */
    static Action command(String name, String description, KeyStroke key, Runnable behaviour) {
        Action a = new AbstractAction(name) {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(ActionEvent e) {
                behaviour.run();
            }
        };
        a.putValue(Action.SHORT_DESCRIPTION, description);
        a.putValue(Action.ACCELERATOR_KEY, key);
        return a;
    }

    /**
     * An on/off command for a check-box item ({@link Entry#check} true): each use flips its state and
     * hands the new one to {@code behaviour}; it starts off.
     */
    static Action toggle(String name, String description, KeyStroke key, Consumer<Boolean> behaviour) {
        boolean[] state = {false};
        return toggle(name, description, key, () -> state[0], on -> {
            state[0] = on;
            behaviour.accept(on);
        });
    }

    /** The value of a toggle's {@link BooleanSupplier}, its state (see {@link #showStates}). */
    static final String STATE = "trisect.state";

    /**
     * An on/off command whose state is {@code state}'s answer, wherever it lives (the scene's fog, which
     * the developer tools change too): each use hands the opposite to {@code behaviour}. The state is
     * never read from the action's {@code SELECTED_KEY}: a check-box item flips that before the action
     * runs, so a menu click read it as already on and turned it off again.
     */
    static Action toggle(String name, String description, KeyStroke key, BooleanSupplier state,
                         Consumer<Boolean> behaviour) {
        Action a = new AbstractAction(name) {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(ActionEvent e) {
                behaviour.accept(!state.getAsBoolean());
                putValue(Action.SELECTED_KEY, state.getAsBoolean());
            }
        };
        a.putValue(Action.SHORT_DESCRIPTION, description);
        a.putValue(Action.ACCELERATOR_KEY, key);
        a.putValue(STATE, state);
        a.putValue(Action.SELECTED_KEY, state.getAsBoolean());
        return a;
    }

    /** Sets each toggle's check to its state, which may have changed elsewhere (a menu is about to show). */
    static void showStates(List<Entry> table) {
        for (Entry e : table) {
            if (e.action().getValue(STATE) instanceof BooleanSupplier state) {
                e.action().putValue(Action.SELECTED_KEY, state.getAsBoolean());
            }
        }
    }

    /** The value after {@code current} in a key's {@code cycle}, round to the first (the first when it is not in it). */
    static <T> T next(T[] cycle, T current) {
        for (int i = 0; i < cycle.length; i++) {
            if (cycle[i] == current) {
                return cycle[(i + 1) % cycle.length];
            }
        }
        return cycle[0];
    }

    /** Ctrl and a key. */
    static KeyStroke ctrl(int keyCode) {
        return KeyStroke.getKeyStroke(keyCode, InputEvent.CTRL_DOWN_MASK);
    }

    /** Binds each command's key on the window (the view binds its own while it has the keyboard). */
    static void bindKeys(JComponent root, List<Entry> table) {
        InputMap in = root.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW);
        ActionMap act = root.getActionMap();
        for (Entry e : table) {
            if (e.key() != null) {
                in.put(e.key(), e.action());
                act.put(e.action(), e.action());
            }
        }
    }

    /** How a key reads in the help table: "Ctrl+S", "F1", "L". */
    static String keyText(KeyStroke key) {
        String mods = InputEvent.getModifiersExText(key.getModifiers());
        return (mods.isEmpty() ? "" : mods + "+") + KeyEvent.getKeyText(key.getKeyCode());
    }
}
