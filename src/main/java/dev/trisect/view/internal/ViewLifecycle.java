package dev.trisect.view.internal;

import java.awt.Window;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.FocusAdapter;
import java.awt.event.FocusEvent;
import java.awt.event.HierarchyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import javax.swing.JComponent;
import javax.swing.SwingUtilities;

/**
 * A view's life in its window: the render thread runs from the view's {@code addNotify} (in a window)
 * to its {@code removeNotify} (out of it) or its close, and a closed view stays closed; the render
 * thread is told the view's size in device pixels, 0 while it does not show (hidden, minimised, out
 * of its window), so that it draws nothing then; and held movement keys are let go when the view
 * loses the keyboard or its window is deactivated, since their releases would never reach it.
 * Event thread, except {@link #close}, {@link #closed} and {@link #checkOpen}, which any thread may call.
 */
public final class ViewLifecycle {
    private final JComponent view;
    private final ViewController controller;
    private final ViewState state;
    private final Runnable leave;
    private Window window;
    private volatile boolean closed;
    private final WindowAdapter windowWatcher = new WindowAdapter() {
        @Override
        public void windowIconified(WindowEvent e) {
            state.viewSize(0, 0);
        }

        @Override
        public void windowDeiconified(WindowEvent e) {
            publishSize();
        }

        @Override
        public void windowDeactivated(WindowEvent e) {
            // Key releases that happen elsewhere would never reach us: stop moving.
            state.input.releaseAll();
        }
    };

    /**
     * Follows {@code view}'s size, showing and keyboard focus from now on.
     *
     * @param view       the view component
     * @param controller the view's controller, which runs its render thread
     * @param leave      what else ends when the view leaves its window or is closed (its developer tools
     *                   window); run on the event thread
     */
    public ViewLifecycle(JComponent view, ViewController controller, Runnable leave) {
        this.view = view;
        this.controller = controller;
        this.state = controller.state();
        this.leave = leave;
        view.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                publishSize();
            }
        });
        view.addHierarchyListener(e -> {
            if ((e.getChangeFlags() & HierarchyEvent.SHOWING_CHANGED) != 0) {
                publishSize();
            }
        });
        view.addFocusListener(new FocusAdapter() {
            @Override
            public void focusLost(FocusEvent e) {
                state.input.releaseAll();
            }
        });
    }

    /** The view is now in a window (from its {@code addNotify}): watch the window, and start rendering unless closed. */
    public void added() {
        window = SwingUtilities.getWindowAncestor(view);
        if (window != null) {
            window.addWindowListener(windowWatcher);
        }
        publishSize();
        if (view.getGraphicsConfiguration() != null) {
            // The frame-rate cap follows the screen's refresh rate unless the host set one (0 when unknown: 60).
            state.screenRate(view.getGraphicsConfiguration().getDevice().getDisplayMode().getRefreshRate());
        }
        synchronized (controller) {
            // Against a close() from another thread: either it sees this loop and stops it, or this sees it closed.
            if (!closed) {
                controller.start();
            }
        }
    }

    /** The view leaves its window (from its {@code removeNotify}): stop rendering and end what goes with it. */
    public void removed() {
        controller.stop();
        if (window != null) {
            window.removeWindowListener(windowWatcher);
            window = null;
        }
        leave.run();
        state.viewSize(0, 0);
    }

    /** Stops rendering for good, and ends what goes with it on the event thread. Any thread; twice does nothing more. */
    public void close() {
        synchronized (controller) {
            closed = true;
            controller.stop();
        }
        SwingUtilities.invokeLater(leave);
    }

    /**
     * Whether {@link #close} was called. Any thread.
     *
     * @return true once closed
     */
    public boolean closed() {
        return closed;
    }

    /** Throws {@link IllegalStateException} once closed, for the view's setters. Any thread. */
    public void checkOpen() {
        if (closed) {
            throw new IllegalStateException("this TrisectView is closed: make a new one");
        }
    }

    /** Tells the render thread the view's size in device pixels (0 while it does not show). */
    private void publishSize() {
        if (!view.isShowing()) {
            state.viewSize(0, 0);
            return;
        }
        double scale = view.getGraphicsConfiguration() == null ? 1
                : view.getGraphicsConfiguration().getDefaultTransform().getScaleX();
        state.screenScale(scale);
        state.viewSize((int) Math.round(view.getWidth() * scale), (int) Math.round(view.getHeight() * scale));
    }
}
