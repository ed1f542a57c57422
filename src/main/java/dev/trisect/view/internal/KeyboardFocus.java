package dev.trisect.view.internal;

import dev.trisect.scene.Node;
import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.util.ArrayDeque;
import java.util.Deque;
import javax.swing.JComponent;

/**
 * Which node of the scene has a view's keyboard (as Sixth 3D's keyboard focus stack): the last one
 * given it, on top of those given it before. Keys reaching the view go first to that node's key
 * listeners and on to its groups ({@link Node#fireKeyEvent}); one they consume never reaches the
 * view's own keys (camera, commands), which are key bindings and so come after key listeners. Escape
 * gives the keyboard back to the node below, or to the view when none is left. Event thread only.
 */
public final class KeyboardFocus extends KeyAdapter {
    private final JComponent view;
    private final Deque<Node> owners = new ArrayDeque<>();

    public KeyboardFocus(JComponent view) {
        this.view = view;
        view.addKeyListener(this);
    }

    /** Gives the keyboard to {@code node} (on top of the nodes holding it before), and the view the window's. */
    public void give(Node node) {
        owners.remove(node);
        owners.push(node);
        view.requestFocusInWindow();
    }

    /** Gives the keyboard back from the node holding it to the one before (or to the view). */
    public void release() {
        owners.poll();
    }

    /** The node holding the keyboard, or null when the view's own keys have it. */
    public Node owner() {
        return owners.peek();
    }

    @Override
    public void keyPressed(KeyEvent e) {
        if (!owners.isEmpty() && e.getKeyCode() == KeyEvent.VK_ESCAPE && e.getModifiersEx() == 0) {
            owners.pop();
            e.consume();
            return;
        }
        route(e);
    }

    @Override
    public void keyReleased(KeyEvent e) {
        route(e);
    }

    @Override
    public void keyTyped(KeyEvent e) {
        route(e);
    }

    private void route(KeyEvent e) {
        Node owner = owners.peek();
        if (owner != null) {
            owner.fireKeyEvent(e);
        }
    }
}
