package dev.trisect.view;

import dev.trisect.scene.Camera;
import dev.trisect.scene.Scene;
import java.awt.BorderLayout;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;

/**
 * A window holding one {@link TrisectView}, for the quick case:
 *
 * <pre>{@code
 * ViewFrame.open("My scene", scene, Camera.looking(new Vec3(3, 2, 4), Vec3.ZERO));
 * }</pre>
 *
 * <p>It closes (and stops rendering) with its close button; the program ends when its last window
 * closes. F12 opens the developer tools beside it.
 */
public final class ViewFrame extends JFrame {
    private static final long serialVersionUID = 1L;

    private final transient TrisectView view;

    /**
     * A window around a view, sized to the view's preferred size. Event thread.
     *
     * @param title the window's title
     * @param view  the view to show in it
     * @throws NullPointerException when {@code view} is null
     */
    public ViewFrame(String title, TrisectView view) {
        super(title);
        // Checked here: Swing would fail later, inside its layout, without saying what was null.
        this.view = java.util.Objects.requireNonNull(view, "view is null");
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        getContentPane().add(view, BorderLayout.CENTER);
        pack();
        setLocationByPlatform(true);
        closeOnKeys(this);
    }

    /**
     * Closes {@code window} on Ctrl+Q, Ctrl+W or Escape, as the demo's window closes, with the same
     * event as its close button (its listeners hear {@code WINDOW_CLOSING}). The keys are bound in the
     * window's root pane for the whole window; a component that uses one of them (a text field's
     * Escape) keeps it while it has the keyboard. Event thread.
     *
     * @param window the window to close
     */
    public static void closeOnKeys(JFrame window) {
        javax.swing.Action close = new javax.swing.AbstractAction("Close") {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(java.awt.event.ActionEvent e) {
                window.dispatchEvent(new java.awt.event.WindowEvent(window, java.awt.event.WindowEvent.WINDOW_CLOSING));
            }
        };
        javax.swing.InputMap in = window.getRootPane().getInputMap(javax.swing.JComponent.WHEN_IN_FOCUSED_WINDOW);
        for (javax.swing.KeyStroke k : CLOSE_KEYS) {
            in.put(k, "trisect-close");
        }
        window.getRootPane().getActionMap().put("trisect-close", close);
    }

    /** The keys that close a window: Ctrl+Q, Ctrl+W and Escape. */
    private static final javax.swing.KeyStroke[] CLOSE_KEYS = {
        javax.swing.KeyStroke.getKeyStroke(java.awt.event.KeyEvent.VK_Q, java.awt.event.InputEvent.CTRL_DOWN_MASK),
        javax.swing.KeyStroke.getKeyStroke(java.awt.event.KeyEvent.VK_W, java.awt.event.InputEvent.CTRL_DOWN_MASK),
        javax.swing.KeyStroke.getKeyStroke(java.awt.event.KeyEvent.VK_ESCAPE, 0)};

    /**
     * The view in this window.
     *
     * @return the view
     */
    public TrisectView view() {
        return view;
    }

    /**
     * Opens a window showing a scene, with the fly controls. Any thread (it builds the window on the
     * event thread and waits for it).
     *
     * @param title  the window's title
     * @param scene  what to show; it may change while the window is open
     * @param camera where to look from
     * @return the window, shown
     */
    public static ViewFrame open(String title, Scene scene, Camera camera) {
        AtomicReference<ViewFrame> frame = new AtomicReference<>();
        Runnable build = () -> {
            TrisectView view = new TrisectView(scene);
            view.setCamera(camera);
            ViewFrame f = new ViewFrame(title, view);
            f.setVisible(true);
            f.view().requestFocusInWindow();
            frame.set(f);
        };
        if (SwingUtilities.isEventDispatchThread()) {
            build.run();
        } else {
            try {
                SwingUtilities.invokeAndWait(build);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while opening the window", e);
            } catch (java.lang.reflect.InvocationTargetException e) {
                Throwable cause = e.getCause();
                if (cause instanceof RuntimeException re) {
                    throw re;
                }
                if (cause instanceof Error err) {
                    throw err;
                }
                throw new IllegalStateException(cause);
            }
        }
        return frame.get();
    }
}
