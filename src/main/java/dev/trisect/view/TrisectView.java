package dev.trisect.view;

import dev.trisect.content.SceneAsset;
import dev.trisect.devtools.DevToolsDialog;
import dev.trisect.devtools.DevToolsPanel;
import dev.trisect.metrics.HeatMap;
import dev.trisect.render.RenderSettings;
import dev.trisect.math.Vec3;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Pick;
import dev.trisect.scene.Scene;
import dev.trisect.view.internal.FramePainter;
import dev.trisect.view.internal.FrameReport;
import dev.trisect.view.internal.FrameSlot;
import dev.trisect.view.internal.InputState;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewKind;
import dev.trisect.view.internal.ViewMouse;
import dev.trisect.view.internal.ViewState;
import java.awt.Dimension;
import java.awt.Graphics2D;
import java.awt.Graphics;
import java.awt.Window;
import java.awt.event.ActionEvent;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.FocusAdapter;
import java.awt.event.FocusEvent;
import java.awt.event.HierarchyEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.MouseEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.ActionMap;
import javax.swing.InputMap;
import javax.swing.JComponent;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;

/**
 * A Swing component that shows a {@link Scene} and renders it continuously on a thread of its own.
 *
 * <pre>{@code
 * TrisectView view = new TrisectView(scene);
 * view.setCamera(Camera.looking(new Vec3(3, 2, 4), Vec3.ZERO));
 * frame.add(view);                       // rendering starts when it is shown
 * view.addFrameListener(f -> System.out.println(f.framesPerSecond() + " fps"));
 * view.addPickListener((pick, click) -> System.out.println("clicked " + pick.object().name()));
 * }</pre>
 *
 * <p>The scene may change at any time from any thread — objects added, moved, hidden, removed — and
 * the next frame shows it (see {@link Scene} for how changes reach a frame).
 *
 * <p><b>Threads.</b> Build it, add it and call its Swing methods on the event thread, as with any
 * component. The setters of what it shows — scene, camera, render settings, render scale, camera
 * controls, frame-time target — may be called from any thread at any time; each takes effect from
 * the next frame. The render thread starts when the view is added to a shown window and stops when
 * it is removed from it or {@link #close closed}; it draws into frames of its own and hands them to
 * the event thread without tearing, at the screen's device pixels on HiDPI displays. A closed view
 * stays closed: its setters, {@code showDevTools(true)} and {@code createDevToolsPanel} then throw
 * {@link IllegalStateException}; make a new view instead.
 *
 * <p><b>Input.</b> Its built-in {@link CameraControls} fly (the default) or orbit the camera, or
 * stay out of the way. Its commands ({@link ViewAction}: the texturing path, the polygon borders,
 * the developer tools on F12, ...) are Swing actions bound to keys in its {@code WHEN_FOCUSED} input
 * map; take them with {@link #action} for your menus, and rebind or remove keys through
 * {@link #getInputMap()} as with any component. A click in the view gives it the keyboard.
 *
 * <p><b>Developer tools.</b> {@link #showDevTools} opens them in a window beside the view's (as F12
 * does); {@link #createDevToolsPanel} gives them as a panel to place in your own window.
 */
public class TrisectView extends JComponent implements AutoCloseable {
    private static final long serialVersionUID = 1L;

    private final transient ViewState state;
    private final transient ViewController controller;
    private final transient ViewMouse mouse;
    private final transient List<FrameListener> frameListeners = new CopyOnWriteArrayList<>();
    private final transient List<PickListener> pickListeners = new CopyOnWriteArrayList<>();
    private final transient List<Action> movement = new ArrayList<>();
    private transient DevToolsDialog devTools;
    private transient Window window;
    private final transient WindowAdapter windowWatcher = new WindowAdapter() {
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
    private transient volatile boolean closed;

    /** The camera a new view starts with: 6 units back and 2 up from the origin, looking at it. */
    public static final Camera DEFAULT_CAMERA = Camera.looking(new Vec3(0, 2, 6), Vec3.ZERO);

    /** A view of an empty scene (add objects to {@link #getScene()}), rendering with one thread per processor. */
    public TrisectView() {
        this(new Scene());
    }

    /**
     * A view of {@code scene} from {@link #DEFAULT_CAMERA}, rendering with one thread per processor.
     *
     * @param scene what to show; it may change while the view draws it
     */
    public TrisectView(Scene scene) {
        this(scene, Runtime.getRuntime().availableProcessors());
    }

    /**
     * A view of {@code scene} from {@link #DEFAULT_CAMERA}.
     *
     * @param scene         what to show; it may change while the view draws it
     * @param renderThreads threads that fill each frame, 1 to 256
     */
    public TrisectView(Scene scene, int renderThreads) {
        Objects.requireNonNull(scene, "scene is null: use new Scene() for an empty one");
        if (renderThreads < 1 || renderThreads > 256) {
            throw new IllegalArgumentException("render threads must be between 1 and 256, got " + renderThreads);
        }
        state = new ViewState(scene, DEFAULT_CAMERA);
        controller = new ViewController(state, new Surface(), renderThreads);
        mouse = new ViewMouse(this, controller, this::clicked);
        // The view's engine room, for the developer tools and for tests; not API.
        putClientProperty(ViewController.class, controller);
        putClientProperty(ViewMouse.class, mouse);
        setPreferredSize(new Dimension(800, 600));
        setOpaque(true);
        setFocusable(true);
        bindKeys();
        addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                publishSize();
            }
        });
        addHierarchyListener(e -> {
            if ((e.getChangeFlags() & HierarchyEvent.SHOWING_CHANGED) != 0) {
                publishSize();
            }
        });
        addFocusListener(new FocusAdapter() {
            @Override
            public void focusLost(FocusEvent e) {
                state.input.releaseAll();
            }
        });
        controller.addFrameListener(this::frameDone);
    }

    /** What the controller asks of this component. */
    private final class Surface implements ViewController.Surface {
        @Override
        public void repaint() {
            TrisectView.this.repaint();
        }

        @Override
        public void inspector(boolean on) {
            mouse.inspector(on);
        }

        @Override
        public void showDevTools(boolean on) {
            showToolsWindow(on);
        }
    }

    // ---- What it shows -----------------------------------------------------------------------

    /**
     * Shows another scene from the next frame on; the camera stays where it is. Any thread.
     *
     * @param scene what to show
     */
    public void setScene(Scene scene) {
        checkOpen();
        state.scene(Objects.requireNonNull(scene, "scene is null: use new Scene() for an empty one"));
    }

    /**
     * The scene shown.
     *
     * @return the scene: change it from any thread, and the next frame shows the change
     */
    public Scene getScene() {
        return state.scene();
    }

    /**
     * Puts the camera here from the next frame on; the camera controls move it from there, and R
     * (reset) brings it back here. It also ends an auto-orbit. Any thread.
     *
     * @param camera where to look from, world space
     */
    public void setCamera(Camera camera) {
        checkOpen();
        state.camera(Objects.requireNonNull(camera, "camera is null"));
        // A camera put somewhere by the program ends an auto-orbit.
        state.input.orbit(false);
        controller.settingsChangedLater();
    }

    /**
     * The camera of the newest frame.
     *
     * @return the camera as the user moved it, or the one just set if no frame has been drawn with it yet
     */
    public Camera getCamera() {
        return state.currentCamera();
    }

    /**
     * Draws with these settings from the next frame on: texturing path, split policy, filter,
     * borders, background... Any thread.
     *
     * @param settings how to draw; change the current ones with {@code getRenderSettings().with...}
     */
    public void setRenderSettings(RenderSettings settings) {
        checkOpen();
        Objects.requireNonNull(settings, "settings");
        state.updateSettings(s -> s.withRender(settings));
        controller.settingsChangedLater();
    }

    /**
     * The settings frames are drawn with. A new view draws tessellated with trilinear filtering on
     * a sky-blue background, borders off (faded yellow when turned on).
     *
     * @return the settings in force
     */
    public RenderSettings getRenderSettings() {
        return state.settings().render();
    }

    /**
     * Renders this share of the view's device pixels, and scales the frame up: lower is faster.
     * Any thread.
     *
     * @param scale greater than 0, at most 1 (the default)
     */
    public void setRenderScale(double scale) {
        checkOpen();
        if (!(scale > 0 && scale <= 1)) {
            throw new IllegalArgumentException("render scale must be greater than 0 and at most 1, got " + scale);
        }
        state.updateSettings(s -> s.withRenderScale(scale));
        controller.settingsChangedLater();
    }

    /**
     * The share of the view's device pixels rendered.
     *
     * @return the render scale, greater than 0 and at most 1
     */
    public double getRenderScale() {
        return state.settings().renderScale();
    }

    /**
     * Holds this much engine time per frame by choosing the tessellated path's split threshold each
     * frame, never looser than the one in the render settings (its ceiling); 0 turns it off (the
     * default). Any thread.
     *
     * @param milliseconds the target, greater than 0 and at most 1000; or 0
     */
    public void setFrameTimeTarget(double milliseconds) {
        checkOpen();
        if (milliseconds == 0) {
            state.budget(new ViewState.Budget(false, state.budget().targetMs()));
        } else if (milliseconds > 0 && milliseconds <= 1000) {
            state.budget(new ViewState.Budget(true, milliseconds));
        } else {
            throw new IllegalArgumentException("frame time target must be between 0 and 1000 milliseconds, got "
                    + milliseconds);
        }
        controller.settingsChangedLater();
    }

    /**
     * The frame-time target.
     *
     * @return milliseconds of engine time per frame, or 0 when off
     */
    public double getFrameTimeTarget() {
        ViewState.Budget b = state.budget();
        return b.on() ? b.targetMs() : 0;
    }

    /**
     * How the mouse and keys move the camera. Any thread.
     *
     * @param controls fly (the default), orbit, or {@link CameraControls#NONE} to leave the camera to the program
     */
    public void setCameraControls(CameraControls controls) {
        checkOpen();
        state.controls(ViewState.Controls.valueOf(Objects.requireNonNull(controls, "controls").name()));
        if (SwingUtilities.isEventDispatchThread()) {
            enableMovement();
        } else {
            SwingUtilities.invokeLater(this::enableMovement);
        }
    }

    /**
     * How the mouse and keys move the camera now.
     *
     * @return the camera controls in force
     */
    public CameraControls getCameraControls() {
        return CameraControls.valueOf(state.controls().name());
    }

    /**
     * Threads that fill each frame.
     *
     * @return the render threads, as given when the view was made
     */
    public int getRenderThreads() {
        return controller.threads();
    }

    // ---- What it tells ---------------------------------------------------------------------

    /**
     * Hears about every frame drawn, on the render thread (see {@link FrameListener}).
     *
     * @param listener told of each frame
     */
    public void addFrameListener(FrameListener listener) {
        frameListeners.add(Objects.requireNonNull(listener, "listener"));
    }

    /**
     * Stops telling a listener about frames; it may still hear of one being reported now.
     *
     * @param listener one added before
     */
    public void removeFrameListener(FrameListener listener) {
        frameListeners.remove(listener);
    }

    /**
     * Hears one-line messages meant for the user, on the event thread: a frame that could not be
     * drawn (the view goes on with the next), a command the developer tools copied. A status bar is
     * a good place for them.
     *
     * @param listener given each message, one line
     */
    public void addMessageListener(Consumer<String> listener) {
        controller.addMessageListener(Objects.requireNonNull(listener, "listener"));
    }

    /**
     * Stops passing messages to a listener.
     *
     * @param listener one added before
     */
    public void removeMessageListener(Consumer<String> listener) {
        controller.removeMessageListener(listener);
    }

    /**
     * Hears about clicks on objects, on the event thread (see {@link PickListener}). A click is picked
     * against the frame on screen; when that frame kept no per-pixel texel coordinates (it does only
     * while the developer tools measure), the render thread draws it once more to read them, so a
     * click costs about one frame and frames cost nothing extra.
     *
     * @param listener told of each click on an object
     */
    public void addPickListener(PickListener listener) {
        pickListeners.add(Objects.requireNonNull(listener, "listener"));
    }

    /**
     * Stops telling a listener about clicks on objects.
     *
     * @param listener one added before
     */
    public void removePickListener(PickListener listener) {
        pickListeners.remove(listener);
    }

    /** A click (not a drag): tell the pick listeners what the frame on screen shows there. */
    private void clicked(MouseEvent e) {
        FrameSlot f = controller.front();
        if (pickListeners.isEmpty() || f == null || f.drawn == null) {
            return;
        }
        state.picks.request(f, mouse.frameX(f, e.getX()), mouse.frameY(f, e.getY()), pick -> {
            if (pick != null) {
                if (SwingUtilities.isEventDispatchThread()) {
                    tellPickListeners(pick, e);
                } else {
                    SwingUtilities.invokeLater(() -> tellPickListeners(pick, e));
                }
            }
        });
    }

    private void tellPickListeners(Pick pick, MouseEvent click) {
        for (PickListener l : pickListeners) {
            l.picked(pick, click);
        }
    }

    private void frameDone(FrameReport r) {
        if (frameListeners.isEmpty()) {
            return;
        }
        FrameInfo info = new FrameInfo(r.frame(), r.width(), r.height(), r.camera(), r.settings(), r.stats(),
                r.frameMs(), r.fps(), r.warning());
        for (FrameListener l : frameListeners) {
            l.frameDrawn(info);
        }
    }

    /**
     * The frame on screen, as an image. Event thread.
     *
     * @return a copy of the frame (with its borders, without the legends painted over it; in the
     *         developer tools' Difference view, the heat map with its scale's legend drawn in, as
     *         {@code trisect compare --heatmap} writes it), or null before the first
     */
    public BufferedImage frameImage() {
        FrameSlot f = controller.front();
        if (f == null) {
            return null;
        }
        BufferedImage image = f.frame.toImage();
        if (f.view == ViewKind.DIFFERENCE && f.heatScale != null) {
            // A heat map means nothing without its scale.
            int[] argb = image.getRGB(0, 0, f.width(), f.height(), null, 0, f.width());
            HeatMap.drawLegend(argb, f.width(), f.height(), f.heatScale);
            image.setRGB(0, 0, f.width(), f.height(), argb, 0, f.width());
        }
        return image;
    }

    // ---- Commands and developer tools -----------------------------------------------------

    /**
     * One of the view's commands, to put in a menu or on a button (see {@link ViewAction}).
     *
     * @param which the command
     * @return its action: the same object each time, shared with the view's key and the developer tools
     */
    public Action action(ViewAction which) {
        return controller.commands().byId(which.id);
    }

    /**
     * Opens (beside the view's window) or closes the developer tools window, as F12 does. Event thread.
     *
     * @param on whether to show it
     */
    public void showDevTools(boolean on) {
        if (on) {
            checkOpen();
        }
        controller.showDevTools(on);
    }

    /**
     * Whether the developer tools window shows.
     *
     * @return true while it is open
     */
    public boolean isDevToolsShowing() {
        return devTools != null && devTools.isVisible();
    }

    /**
     * The developer tools as a panel to place in your own window (it scrolls; about 420 pixels wide
     * suits it). Each call makes a new panel; while one shows, the view also measures what it displays,
     * which costs frame time. Event thread.
     *
     * @return a new panel of the developer tools
     */
    public JComponent createDevToolsPanel() {
        checkOpen();
        return new DevToolsPanel(controller);
    }

    private void showToolsWindow(boolean on) {
        if (on) {
            if (devTools == null) {
                devTools = new DevToolsDialog(SwingUtilities.getWindowAncestor(this), controller);
            }
            devTools.panel().syncFromSettings();
            devTools.showBeside(SwingUtilities.getWindowAncestor(this));
        } else if (devTools != null) {
            devTools.setVisible(false);
        }
    }

    // ---- Life cycle -------------------------------------------------------------------------

    /** Stops rendering for good and closes the developer tools window. Any thread; closing twice does nothing. */
    @Override
    public void close() {
        synchronized (controller) {
            closed = true;
            controller.stop();
        }
        SwingUtilities.invokeLater(this::disposeTools);
    }

    private void checkOpen() {
        if (closed) {
            throw new IllegalStateException("this TrisectView is closed: make a new one");
        }
    }

    /**
     * Whether the view was closed.
     *
     * @return true once {@link #close} was called
     */
    public boolean isClosed() {
        return closed;
    }

    /** Starts the render thread (unless closed): the view is now in a window. */
    @Override
    public void addNotify() {
        super.addNotify();
        window = SwingUtilities.getWindowAncestor(this);
        if (window != null) {
            window.addWindowListener(windowWatcher);
        }
        publishSize();
        synchronized (controller) {
            // Against a close() from another thread: either it sees this loop and stops it, or this sees it closed.
            if (!closed) {
                controller.start();
            }
        }
    }

    /** Stops the render thread and closes the developer tools window: the view has left its window. */
    @Override
    public void removeNotify() {
        controller.stop();
        if (window != null) {
            window.removeWindowListener(windowWatcher);
            window = null;
        }
        disposeTools();
        state.viewSize(0, 0);
        super.removeNotify();
    }

    private void disposeTools() {
        if (devTools != null) {
            devTools.dispose();
            devTools = null;
            controller.devToolsClosed();
        }
    }

    /** Tells the render thread the view's size in device pixels (0 while it does not show). */
    private void publishSize() {
        if (!isShowing()) {
            state.viewSize(0, 0);
            return;
        }
        double scale = getGraphicsConfiguration() == null ? 1
                : getGraphicsConfiguration().getDefaultTransform().getScaleX();
        state.viewSize((int) Math.round(getWidth() * scale), (int) Math.round(getHeight() * scale));
    }

    @Override
    protected void paintComponent(Graphics g) {
        FrameSlot front = controller.acquireFront();
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            FramePainter.paint(g2, front, getWidth(), getHeight(), mouse.pinned());
        } finally {
            g2.dispose();
        }
        if (front != null) {
            controller.framePainted(front.serial);
        }
    }

    // ---- Keys -------------------------------------------------------------------------------

    /** Every command's key, and the movement keys, in the view's WHEN_FOCUSED input map. */
    private void bindKeys() {
        InputMap in = getInputMap(WHEN_FOCUSED);
        ActionMap act = getActionMap();
        for (ViewAction a : ViewAction.values()) {
            Action c = action(a);
            in.put((KeyStroke) c.getValue(Action.ACCELERATOR_KEY), a.id);
            act.put(a.id, c);
        }
        int[][] moves = {
            {KeyEvent.VK_W, InputState.FORWARD}, {KeyEvent.VK_UP, InputState.FORWARD},
            {KeyEvent.VK_S, InputState.BACK}, {KeyEvent.VK_DOWN, InputState.BACK},
            {KeyEvent.VK_A, InputState.LEFT}, {KeyEvent.VK_LEFT, InputState.LEFT},
            {KeyEvent.VK_D, InputState.RIGHT}, {KeyEvent.VK_RIGHT, InputState.RIGHT},
            {KeyEvent.VK_E, InputState.UP}, {KeyEvent.VK_PAGE_UP, InputState.UP},
            {KeyEvent.VK_Q, InputState.DOWN}, {KeyEvent.VK_PAGE_DOWN, InputState.DOWN},
            {KeyEvent.VK_SHIFT, InputState.FAST}};
        for (int[] move : moves) {
            for (int modifiers : new int[] {0, InputEvent.SHIFT_DOWN_MASK}) {
                String name = "move-" + move[0] + "-" + modifiers;
                in.put(KeyStroke.getKeyStroke(move[0], modifiers, false), name + "-press");
                in.put(KeyStroke.getKeyStroke(move[0], modifiers, true), name + "-release");
                int bit = move[1];
                act.put(name + "-press", movement(true, bit));
                act.put(name + "-release", movement(false, bit));
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

    /** Movement keys act only with camera controls; without, they are left to the host (a disabled action passes the key on). */
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
