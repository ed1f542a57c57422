package dev.trisect.view.internal;

import java.awt.event.ActionEvent;
import java.util.function.Consumer;
import javax.swing.AbstractAction;
import javax.swing.AbstractButton;
import javax.swing.Action;
import javax.swing.KeyStroke;

/**
 * A user command: one {@link Action} serves its menu item, its key binding and any control bound to
 * it. A toggle keeps its state in {@link Action#SELECTED_KEY}, so every button bound to it shows the
 * same state whichever way it was changed.
 */
public final class Command extends AbstractAction {
    private static final long serialVersionUID = 1L;
    private final transient Consumer<Command> behaviour;
    private final boolean toggle;

    private Command(String name, String description, KeyStroke key, boolean toggle, Consumer<Command> behaviour) {
        super(name);
        this.behaviour = behaviour;
        this.toggle = toggle;
        putValue(SHORT_DESCRIPTION, description);
        putValue(ACCELERATOR_KEY, key);
        if (toggle) {
            putValue(SELECTED_KEY, Boolean.FALSE);
        }
    }

    /** A command that does something. */
    public static Command action(String name, String description, KeyStroke key, Runnable behaviour) {
        return new Command(name, description, key, false, c -> behaviour.run());
    }

    /** An on/off command; {@code behaviour} sees the new state through {@link #selected()}. */
    public static Command toggle(String name, String description, KeyStroke key, Consumer<Command> behaviour) {
        return new Command(name, description, key, true, behaviour);
    }

    public boolean selected() {
        return Boolean.TRUE.equals(getValue(SELECTED_KEY));
    }

    /** Sets the toggle's state without running its behaviour (to reflect a change made elsewhere). */
    public void show(boolean on) {
        putValue(SELECTED_KEY, on);
    }

    public KeyStroke key() {
        return (KeyStroke) getValue(ACCELERATOR_KEY);
    }

    @Override
    public void actionPerformed(ActionEvent e) {
        // A toggle button flips the state itself before calling us; a key binding or a plain menu
        // item does not, so flip it here.
        if (toggle && !(e != null && e.getSource() instanceof AbstractButton b && b.getAction() == this
                && b.getModel().isSelected() == selected())) {
            putValue(SELECTED_KEY, !selected());
        }
        behaviour.accept(this);
    }
}
