package dev.trisect.view.internal;

import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.List;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.ActionMap;
import javax.swing.InputMap;
import javax.swing.JComponent;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;

/**
 * A view's keys: each command's key, and the movement keys (W A S D, the arrows, E and Q, Page Up and
 * Page Down, Shift to go faster) with the actions that hold their bits in {@link InputState}, all in
 * the view's {@code WHEN_FOCUSED} input map so that the host can rebind or remove them as with any
 * component. The movement actions are enabled only while the view has camera controls: a disabled
 * action passes its key on to the host. Event thread, except {@link #controlsChanged}.
 */
public final class ViewKeys {
    /** Key code and {@link InputState} bit of each movement key. */
    private static final int[][] MOVES = {
        {KeyEvent.VK_W, InputState.FORWARD}, {KeyEvent.VK_UP, InputState.FORWARD},
        {KeyEvent.VK_S, InputState.BACK}, {KeyEvent.VK_DOWN, InputState.BACK},
        {KeyEvent.VK_A, InputState.LEFT}, {KeyEvent.VK_LEFT, InputState.LEFT},
        {KeyEvent.VK_D, InputState.RIGHT}, {KeyEvent.VK_RIGHT, InputState.RIGHT},
        {KeyEvent.VK_E, InputState.UP}, {KeyEvent.VK_PAGE_UP, InputState.UP},
        {KeyEvent.VK_Q, InputState.DOWN}, {KeyEvent.VK_PAGE_DOWN, InputState.DOWN},
        {KeyEvent.VK_SHIFT, InputState.FAST}};

    private final ViewState state;
    private final List<Action> movement = new ArrayList<>();

    /**
     * Binds the keys in {@code view}'s {@code WHEN_FOCUSED} input map and its action map.
     *
     * @param view       the view whose maps take the keys
     * @param controller the view's controller: its commands, and the state the movement keys press
     * @param commandIds the ids of the commands whose keys the view binds (the public {@code ViewAction}s'),
     *                   each bound under its id
     */
    public ViewKeys(JComponent view, ViewController controller, List<String> commandIds) {
        state = controller.state();
        InputMap in = view.getInputMap(JComponent.WHEN_FOCUSED);
        ActionMap act = view.getActionMap();
        for (String id : commandIds) {
            Command c = controller.commands().byId(id);
            in.put(c.key(), id);
            act.put(id, c);
        }
        for (int[] move : MOVES) {
            // With and without Shift: Shift+W is W at speed, and W let go while Shift is held must still stop.
            for (int modifiers : new int[] {0, InputEvent.SHIFT_DOWN_MASK}) {
                String name = "move-" + move[0] + "-" + modifiers;
                in.put(KeyStroke.getKeyStroke(move[0], modifiers, false), name + "-press");
                in.put(KeyStroke.getKeyStroke(move[0], modifiers, true), name + "-release");
                act.put(name + "-press", movement(true, move[1]));
                act.put(name + "-release", movement(false, move[1]));
            }
        }
    }

    private Action movement(boolean press, int bit) {
        Action a = new AbstractAction() {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(ActionEvent e) {
                if (press) {
                    state.input.press(bit);
                } else {
                    state.input.release(bit);
                }
            }
        };
        movement.add(a);
        return a;
    }

    /**
     * Enables the movement keys when the view's camera controls are on, else disables them and lets
     * go of any held; on the event thread, now if called there, else later. Any thread.
     */
    public void controlsChanged() {
        if (SwingUtilities.isEventDispatchThread()) {
            enableMovement();
        } else {
            SwingUtilities.invokeLater(this::enableMovement);
        }
    }

    private void enableMovement() {
        boolean on = state.controls() != ViewState.Controls.NONE;
        if (!on) {
            state.input.releaseAll();
        }
        for (Action a : movement) {
            a.setEnabled(on);
        }
    }
}
