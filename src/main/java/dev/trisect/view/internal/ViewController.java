package dev.trisect.view.internal;

import dev.trisect.base.internal.ErrorLine;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.RenderMode;
import dev.trisect.texture.TextureFilter;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import java.util.function.UnaryOperator;
import javax.swing.SwingUtilities;

/**
 * The event thread's side of one view: the settings the user and the host change, the commands, the
 * render thread's start and stop, the frame on screen, and who hears about frames and messages. The
 * render thread is reached through {@link ViewState} alone. Event thread only, except where a method
 * says otherwise.
 */
public final class ViewController {
    /** The host's update hooks, as the render loop runs them. */
    @FunctionalInterface
    public interface Updates {
        /**
         * Render thread, before frame {@code frame} ({@code seconds} after the last frame started):
         * runs every hook; whether one asked for the frame after this one.
         */
        boolean update(double seconds, long frame);
    }

        /** What the controller asks of the component it drives. Event thread. */
    public interface Surface {
        /** Asks for a paint of the newest frame (any thread). */
        void repaint();

        /** Turns the pixel inspector on (it follows the mouse) or off. */
        void inspector(boolean on);

        /** Shows or hides the developer tools window. */
        void showDevTools(boolean on);
    }

    private final ViewState state;
    private final Surface surface;
    private final int threads;
    private final TripleBuffer buffers = new TripleBuffer();
    private final ViewCommands commands;
    private final List<Consumer<FrameReport>> frameListeners = new CopyOnWriteArrayList<>();
    private final List<Consumer<String>> messageListeners = new CopyOnWriteArrayList<>();
    private final List<Consumer<ViewSettings>> settingsListeners = new CopyOnWriteArrayList<>();
    /** The host's update hooks, run on the render thread before each frame. */
    private volatile Updates updates = (seconds, frame) -> false;
    /** Read by {@link #stop}, which may run on any thread (a view closed from elsewhere). */
    private volatile RenderLoop loop;
    private volatile Thread thread;
    private FrameSlot front;
    private int toolsShowing;
    private boolean syncQueued;
    /** Whether the auto-orbit command shows on, for the render thread to compare with the input. */
    private volatile boolean orbitShown;

    public ViewController(ViewState state, Surface surface, int threads) {
        this.state = state;
        this.surface = surface;
        this.threads = threads;
        this.commands = new ViewCommands(this);
        commands.sync(state.settings());
    }

    public ViewState state() {
        return state;
    }

    public ViewCommands commands() {
        return commands;
    }

    /** Worker threads the renderer fills each frame with. */
    public int threads() {
        return threads;
    }

    /** Starts the render thread, unless it runs. Event thread. */
    public synchronized void start() {
        if (thread != null && thread.isAlive() && !loop.stopping()) {
            return;
        }
        loop = new RenderLoop(state, buffers, surface::repaint, threads);
        loop.listener(new RenderLoop.LoopListener() {
            @Override
            public void frameDone(FrameReport report) {
                if (state.input.orbit() != orbitShown) {
                    settingsChangedLater();
                }
                for (Consumer<FrameReport> l : frameListeners) {
                    try {
                        l.accept(report);
                    } catch (RuntimeException e) {
                        // A listener's failure must not end the render thread; say so once per frame.
                        problem(ErrorLine.of("a frame listener failed: " + e));
                    }
                }
            }

            @Override
            public void problem(String message) {
                SwingUtilities.invokeLater(() -> message(message));
            }

            @Override
            public boolean update(double seconds, long frame) {
                return updates.update(seconds, frame);
            }
        });
        thread = new Thread(loop, "trisect-render");
        // A library's thread never keeps a program alive: the windows (the event thread) decide.
        thread.setDaemon(true);
        thread.start();
    }

    /** Asks the render thread to stop after its frame; it closes its renderer as it ends. Any thread. */
    public synchronized void stop() {
        RenderLoop l = loop;
        if (l != null) {
            l.stop();
        }
    }

    /** The render thread, or null before the first {@link #start}; for tests and shutdown. */
    public Thread renderThread() {
        return thread;
    }

    /** The running render loop, or null before the first {@link #start}. */
    public RenderLoop loop() {
        return loop;
    }

    /** Takes the newest finished frame for painting, handing back the one shown until now. */
    public FrameSlot acquireFront() {
        front = buffers.acquire(front);
        return front;
    }

    /** The frame on screen now, or null before the first one. */
    public FrameSlot front() {
        return front;
    }

    /** Tells the render thread that the frame with this serial number is on screen. */
    public void framePainted(long serial) {
        RenderLoop l = loop;
        if (l != null) {
            l.framePainted(serial);
        }
    }

    /** Replaces the view settings; the render thread uses them from its next frame. */
    public void update(UnaryOperator<ViewSettings> change) {
        state.updateSettings(change);
        settingsChanged();
    }

    /** Shows the settings in force in the commands and the developer tools. */
    public void settingsChanged() {
        ViewSettings s = state.settings();
        commands.sync(s);
        orbitShown = commands.orbit.selected();
        for (Consumer<ViewSettings> l : settingsListeners) {
            l.accept(s);
        }
    }

    /** Any thread: {@link #settingsChanged} on the event thread, soon, once however often it is asked. */
    public synchronized void settingsChangedLater() {
        if (!syncQueued) {
            syncQueued = true;
            SwingUtilities.invokeLater(() -> {
                synchronized (this) {
                    syncQueued = false;
                }
                settingsChanged();
            });
        }
    }

    public void selectMode(RenderMode m) {
        update(s -> s.withRender(s.render().withMode(m)));
    }

    /** Sets the texture filter, in every path. */
    public void selectFilter(TextureFilter f) {
        update(s -> s.withRender(s.render().withFilter(f)));
    }

    /** Sets how the outlines are coloured (and turns them on, since that is what one wants to see). */
    public void selectBorderStyle(BorderStyle style) {
        update(s -> s.withRender(s.render().withBorders(true).withBorderStyle(style)));
    }

    /** Shows a view; the comparison views belong to the developer tools and open them. */
    public void selectView(ViewKind k) {
        update(s -> s.withView(k));
        if (k != ViewKind.IMAGE && !commands.devTools.selected()) {
            commands.devTools.show(true);
            showDevTools(true);
        }
    }

    void inspector(boolean on) {
        surface.inspector(on);
    }

    /** Puts the inspector's readout of the frame on screen on the clipboard as text (or says why not). */
    void copyInspection() {
        FrameSlot f = front;
        if (f == null || f.inspection == null) {
            message("Nothing to copy: turn the pixel inspector on (I) and point at a pixel.");
            return;
        }
        java.awt.Toolkit.getDefaultToolkit().getSystemClipboard().setContents(
                new java.awt.datatransfer.StringSelection(InspectorPainter.text(f.inspection)), null);
        message("Copied the inspector's readout of pixel " + f.inspection.x() + "," + f.inspection.y() + ".");
    }

    /** Shows or hides the developer tools window (the F12 command's behaviour). */
    public void showDevTools(boolean on) {
        commands.devTools.show(on);
        surface.showDevTools(on);
    }

    /** Called when the developer tools window was closed by its own close button. */
    public void devToolsClosed() {
        commands.devTools.show(false);
    }

    /**
     * A developer tools panel was shown ({@code +1}) or hidden ({@code -1}); while any shows, the
     * loop measures what they display. When the last one goes, the comparison views (which belong to
     * the tools) go back to the image.
     */
    public void toolsShowing(int change) {
        toolsShowing = Math.max(0, toolsShowing + change);
        state.toolsOpen(toolsShowing > 0);
        if (toolsShowing == 0 && state.settings().view() != ViewKind.IMAGE) {
            update(s -> s.withView(ViewKind.IMAGE));
        }
    }

    /** Sets the update hooks the render thread runs before each frame (one, which may run many). */
    public void updates(Updates u) {
        updates = u;
    }

    /** Hears about every frame, on the render thread, right after it is handed to the screen. */
    public void addFrameListener(Consumer<FrameReport> l) {
        frameListeners.add(l);
    }

    public void removeFrameListener(Consumer<FrameReport> l) {
        frameListeners.remove(l);
    }

    /** Hears one-line messages for the user (a copied command, a frame that failed), on the event thread. */
    public void addMessageListener(Consumer<String> l) {
        messageListeners.add(l);
    }

    public void removeMessageListener(Consumer<String> l) {
        messageListeners.remove(l);
    }

    /** Hears every change of settings, on the event thread (the developer tools show them). */
    public void addSettingsListener(Consumer<ViewSettings> l) {
        settingsListeners.add(l);
    }

    public void removeSettingsListener(Consumer<ViewSettings> l) {
        settingsListeners.remove(l);
    }

    /** Any thread: {@link #message} on the event thread. */
    public void messageLater(String text) {
        SwingUtilities.invokeLater(() -> message(text));
    }

    /** Passes a one-line message to whoever shows messages. */
    public void message(String text) {
        for (Consumer<String> l : messageListeners) {
            l.accept(text);
        }
    }
}
