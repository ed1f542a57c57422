package dev.trisect.devtools;

import dev.trisect.view.internal.ViewController;
import java.awt.Window;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.ComponentListener;
import javax.swing.JComponent;
import javax.swing.SwingUtilities;

/**
 * The developer tools window of one view (F12): a {@link DevToolsDialog} owned by the view's window,
 * made the first time it is shown, docked to that window ({@link DevToolsDock}) and following it as
 * it moves or changes size, disposed when the view leaves its window or is closed. Event thread only.
 */
public final class DevToolsWindow {
    private final JComponent view;
    private final ViewController controller;
    private DevToolsDialog dialog;
    /** The window the dialog follows, and how. */
    private Window followed;
    private final ComponentListener follow = new ComponentAdapter() {
        @Override
        public void componentMoved(ComponentEvent e) {
            redock();
        }

        @Override
        public void componentResized(ComponentEvent e) {
            redock();
        }
    };

    /**
     * The tools window of {@code view}, not yet made.
     *
     * @param view       the view component, whose window owns the tools window
     * @param controller the view's controller, which the tools show and change
     */
    public DevToolsWindow(JComponent view, ViewController controller) {
        this.view = view;
        this.controller = controller;
    }

    /**
     * Shows the window beside the view's, with the settings in force, or hides it.
     *
     * @param on whether to show it
     */
    public void show(boolean on) {
        if (on) {
            Window main = SwingUtilities.getWindowAncestor(view);
            if (dialog == null) {
                dialog = new DevToolsDialog(main, controller);
            }
            if (followed != main) {
                unfollow();
                if (main != null) {
                    main.addComponentListener(follow);
                }
                followed = main;
            }
            dialog.panel().syncFromSettings();
            dialog.showBeside(main, view);
        } else if (dialog != null) {
            dialog.setVisible(false);
        }
    }

    /**
     * Whether the window shows.
     *
     * @return true while it is made and visible
     */
    public boolean showing() {
        return dialog != null && dialog.isVisible();
    }

    /** Disposes the window, if made, and shows the tools' command as off; the next {@link #show} makes a new one. */
    public void dispose() {
        unfollow();
        if (dialog != null) {
            dialog.dispose();
            dialog = null;
            controller.devToolsClosed();
        }
    }

    private void redock() {
        if (dialog != null && dialog.isVisible()) {
            dialog.dock();
        }
    }

    private void unfollow() {
        if (followed != null) {
            followed.removeComponentListener(follow);
            followed = null;
        }
    }
}
