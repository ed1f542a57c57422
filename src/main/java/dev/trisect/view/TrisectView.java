package dev.trisect.view;

import dev.trisect.devtools.DevToolsPanel;
import dev.trisect.devtools.DevToolsWindow;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.RenderSettings;
import dev.trisect.math.Vec3;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Scene;
import dev.trisect.view.internal.FramePainter;
import dev.trisect.view.internal.FrameSlot;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewKeys;
import dev.trisect.view.internal.ViewLifecycle;
import dev.trisect.view.internal.ViewMouse;
import dev.trisect.view.internal.ViewState;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.event.MouseEvent;
import java.awt.image.BufferedImage;
import java.util.Arrays;
import java.util.Objects;
import java.util.function.Consumer;
import javax.swing.Action;
import javax.swing.JComponent;

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
    private final transient ViewListeners listeners = new ViewListeners();
    private final transient ViewKeys keys;
    private final transient DevToolsWindow devTools;
    private final transient ViewLifecycle life;

    /** The camera a new view starts with: 6 units back and 2 up from the origin, looking at it. */
    public static final Camera DEFAULT_CAMERA = Camera.looking(new Vec3(0, 2, 6), Vec3.ZERO);

    /** A view of an empty scene (add objects to {@link #getScene()}), rendering with one thread per processor (at most 256). */
    public TrisectView() {
        this(new Scene());
    }

    /**
     * A view of {@code scene} from {@link #DEFAULT_CAMERA}, rendering with one thread per processor (at most 256).
     *
     * @param scene what to show; it may change while the view draws it
     */
    public TrisectView(Scene scene) {
        this(scene, FrameRenderer.defaultThreads());
    }

    /**
     * A view of {@code scene} from {@link #DEFAULT_CAMERA}.
     *
     * @param scene         what to show; it may change while the view draws it
     * @param renderThreads threads that fill each frame, 1 to 256
     */
    public TrisectView(Scene scene, int renderThreads) {
        Objects.requireNonNull(scene, "scene is null: use new Scene() for an empty one");
        if (renderThreads < 1 || renderThreads > FrameRenderer.MAX_THREADS) {
            throw new IllegalArgumentException("render threads must be between 1 and " + FrameRenderer.MAX_THREADS
                    + ", got " + renderThreads);
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
        devTools = new DevToolsWindow(this, controller);
        keys = new ViewKeys(this, controller, Arrays.stream(ViewAction.values()).map(a -> a.id).toList());
        life = new ViewLifecycle(this, controller, devTools::dispose);
        controller.addFrameListener(listeners::frameDone);
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
            devTools.show(on);
        }
    }

    // ---- What it shows -----------------------------------------------------------------------

    /**
     * Shows another scene from the next frame on; the camera stays where it is. Any thread.
     *
     * @param scene what to show
     */
    public void setScene(Scene scene) {
        life.checkOpen();
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
        life.checkOpen();
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
        life.checkOpen();
        Objects.requireNonNull(settings, "settings");
        state.updateSettings(s -> s.withRender(settings));
        controller.settingsChangedLater();
    }

    /**
     * The settings frames are drawn with. A new view draws with {@link RenderSettings#display()}
     * (tessellated, trilinear filtering, a sky-blue background, borders off and faded yellow when turned
     * on), as {@code SceneRenderer.renderImage} draws a picture.
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
        life.checkOpen();
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
        life.checkOpen();
        if (milliseconds == 0) {
            state.budget(new ViewState.Budget(false, state.budget().targetMs()));
        } else if (milliseconds > 0 && milliseconds <= 1000) {
            state.budget(new ViewState.Budget(true, milliseconds));
        } else {
            throw new IllegalArgumentException("frame time target must be more than 0 and at most 1000 milliseconds "
                    + "(or 0 for none), got " + milliseconds);
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
        life.checkOpen();
        state.controls(ViewState.Controls.valueOf(Objects.requireNonNull(controls, "controls").name()));
        keys.controlsChanged();
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
     * @throws IllegalStateException after {@link #close()}
     */
    public void addFrameListener(FrameListener listener) {
        life.checkOpen();
        listeners.addFrameListener(listener);
    }

    /**
     * Stops telling a listener about frames; it may still hear of one being reported now.
     *
     * @param listener one added before
     */
    public void removeFrameListener(FrameListener listener) {
        listeners.removeFrameListener(listener);
    }

    /**
     * Hears one-line messages meant for the user, on the event thread: a frame that could not be
     * drawn (the view goes on with the next), a command the developer tools copied. A status bar is
     * a good place for them.
     *
     * @param listener given each message, one line
     * @throws IllegalStateException after {@link #close()}
     */
    public void addMessageListener(Consumer<String> listener) {
        life.checkOpen();
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
     * @throws IllegalStateException after {@link #close()}
     */
    public void addPickListener(PickListener listener) {
        life.checkOpen();
        listeners.addPickListener(listener);
    }

    /**
     * Stops telling a listener about clicks on objects.
     *
     * @param listener one added before
     */
    public void removePickListener(PickListener listener) {
        listeners.removePickListener(listener);
    }

    /** A click (not a drag): tell the pick listeners what the frame on screen shows there. */
    private void clicked(MouseEvent e) {
        if (listeners.hearPicks()) {
            mouse.pick(e, pick -> listeners.picked(pick, e));
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
        return f == null ? null : FramePainter.image(f);
    }

    // ---- Commands and developer tools -----------------------------------------------------

    /**
     * One of the view's commands, to put in a menu or on a button (see {@link ViewAction}).
     *
     * @param which the command
     * @return its action: the same object each time, shared with the view's key and the developer tools
     * @throws IllegalStateException after {@link #close()}, as the setters and listeners do: a closed
     *                               view takes no new commands (removing a listener stays allowed)
     */
    public Action action(ViewAction which) {
        life.checkOpen();
        return controller.commands().byId(which.id);
    }

    /**
     * Opens (beside the view's window) or closes the developer tools window, as F12 does. Event thread.
     *
     * @param on whether to show it
     */
    public void showDevTools(boolean on) {
        if (on) {
            life.checkOpen();
        }
        controller.showDevTools(on);
    }

    /**
     * Whether the developer tools window shows.
     *
     * @return true while it is open
     */
    public boolean isDevToolsShowing() {
        return devTools.showing();
    }

    /**
     * The developer tools as a panel to place in your own window (it scrolls; about 420 pixels wide
     * suits it). Each call makes a new panel; while one shows, the view also measures what it displays,
     * which costs frame time. Event thread.
     *
     * @return a new panel of the developer tools
     */
    public JComponent createDevToolsPanel() {
        life.checkOpen();
        return new DevToolsPanel(controller);
    }

    // ---- Life cycle -------------------------------------------------------------------------

    /** Stops rendering for good and closes the developer tools window. Any thread; closing twice does nothing. */
    @Override
    public void close() {
        life.close();
    }

    /**
     * Whether the view was closed.
     *
     * @return true once {@link #close} was called
     */
    public boolean isClosed() {
        return life.closed();
    }

    /** Starts the render thread (unless closed): the view is now in a window. */
    @Override
    public void addNotify() {
        super.addNotify();
        life.added();
    }

    /** Stops the render thread and closes the developer tools window: the view has left its window. */
    @Override
    public void removeNotify() {
        life.removed();
        super.removeNotify();
    }

    @Override
    protected void paintComponent(Graphics g) {
        FramePainter.present(g, controller, getWidth(), getHeight(), mouse.pinned());
    }
}
