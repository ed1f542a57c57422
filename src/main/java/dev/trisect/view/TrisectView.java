package dev.trisect.view;

import dev.trisect.devtools.DevToolsPanel;
import dev.trisect.devtools.DevToolsWindow;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.scene.Node;
import dev.trisect.scene.Pick;
import dev.trisect.scene.Scene;
import dev.trisect.view.internal.FramePainter;
import dev.trisect.view.internal.FrameSlot;
import dev.trisect.view.internal.KeyboardFocus;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewMouse;
import java.awt.Graphics;
import java.awt.event.MouseEvent;
import java.awt.image.BufferedImage;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Consumer;
import javax.swing.Action;
import javax.swing.JComponent;

/**
 * A Swing component that shows a {@link Scene} and renders it on a thread of its own: a frame whenever
 * something it shows changed, and frames at up to {@link #getMaxFrameRate()} while something animates
 * (an {@link UpdateListener} that says so, the camera moving, the developer tools showing); otherwise
 * it idles.
 *
 * <pre>{@code
 * TrisectView view = new TrisectView(scene);
 * view.setCamera(Camera.looking(new Vec3(3, 2, 4), Vec3.ZERO));
 * frame.add(view);                       // rendering starts when it is shown
 * view.addFrameListener(f -> System.out.println(f.framesPerSecond() + " fps"));
 * view.addPickListener((pick, click) -> System.out.println("clicked " + pick.object().name()));
 * }</pre>
 *
 * <p><b>Animation.</b> {@link #addUpdateListener} runs a hook before each frame with the time step;
 * what it changes shows in that frame, and while it returns true the view keeps drawing.
 *
 * <p>The scene may change at any time from any thread — objects added, moved, hidden, removed — and
 * the next frame shows it (see {@link Scene} for how changes reach a frame).
 *
 * <p><b>Threads.</b> Build it, add it and call its Swing methods on the event thread, as with any
 * component. The setters of what it shows — scene, camera, render settings, render scale, camera
 * controls, frame-time target, frame-rate cap — may be called from any thread at any time; each takes effect from
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
public class TrisectView extends ViewDrawing {
    private static final long serialVersionUID = 1L;

    private final transient ViewMouse mouse;
    private final transient ViewListeners listeners;
    private final transient DevToolsWindow devTools;
    private final transient KeyboardFocus keyboard;

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
        super(scene, renderThreads);
        listeners = new ViewListeners(controller::messageLater);
        controller.updates(listeners::update);
        mouse = new ViewMouse(this, controller, this::clicked);
        // The view's engine room, for the developer tools and for tests; not API.
        putClientProperty(ViewController.class, controller);
        putClientProperty(ViewMouse.class, mouse);
        devTools = new DevToolsWindow(this, controller);
        keyboard = new KeyboardFocus(this);
        controller.addFrameListener(listeners::frameDone);
    }

    @Override
    void inspector(boolean on) {
        mouse.inspector(on);
    }

    @Override
    void devTools(boolean on) {
        devTools.show(on);
    }

    @Override
    void left() {
        devTools.dispose();
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
     * Runs {@code hook} on the render thread before each frame, with the time step (see
     * {@link UpdateListener}); what it changes shows in that frame, and while it returns true the
     * view keeps drawing.
     *
     * @param hook moves things on before each frame
     * @throws IllegalStateException after {@link #close()}
     */
    public void addUpdateListener(UpdateListener hook) {
        life.checkOpen();
        listeners.addUpdateListener(hook);
        state.demand.request();
    }

    /**
     * Stops running an update hook; it may still run for a frame under way.
     *
     * @param hook one added before
     */
    public void removeUpdateListener(UpdateListener hook) {
        listeners.removeUpdateListener(hook);
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
     * against the frame on screen, from its triangle ids, as {@link #pick} does: nothing is drawn again.
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
     * What the frame on screen shows at view point (x, y): the object, its triangle, the exact 3D point
     * and the texel — as {@code SceneRenderer.pick} answers for the same frame — read from the frame's
     * triangle ids, which every frame records, and never drawing anything: the triangle from the ids,
     * the point, texture coordinates and texel from that triangle and the frame's camera (see
     * {@link Pick}); the same surfaces are picked (a blended one is seen through; lines, billboards and
     * labels are not picked). Event thread.
     *
     * @param x the point's column in the view, logical pixels (as mouse events give it)
     * @param y its row
     * @return the pick, or empty where the frame shows no object, outside the view, or before the first frame
     */
    public Optional<Pick> pick(int x, int y) {
        if (x < 0 || y < 0 || x >= getWidth() || y >= getHeight()) {
            return Optional.empty();
        }
        return Optional.ofNullable(mouse.pickAt(x, y));
    }

    /**
     * Gives the keyboard to {@code node} (as Sixth 3D's keyboard focus stack): keys reaching the view
     * go to its key listeners ({@link Node#addKeyListener}) and on to its groups before the view's own
     * keys (camera, commands), which do not see the ones consumed. Escape, or
     * {@link #releaseKeyboard}, gives it back to the node that had it before, and in the end to the view.
     * Also asks the window's keyboard for the view. Event thread.
     *
     * @param node the node to take the keys, in this view's scene
     */
    public void giveKeyboard(Node node) {
        keyboard.give(Objects.requireNonNull(node, "node is null"));
    }

    /** Gives the keyboard back from the node holding it to the one before it, or to the view. Event thread. */
    public void releaseKeyboard() {
        keyboard.release();
    }

    /**
     * The node holding the keyboard.
     *
     * @return the node given it last and not yet released, or empty when the view's own keys have it
     */
    public Optional<Node> keyboardOwner() {
        return Optional.ofNullable(keyboard.owner());
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

    @Override
    protected void paintComponent(Graphics g) {
        FramePainter.present(g, controller, getWidth(), getHeight(), mouse.pinned());
        // Things may have moved under a still pointer: enter and exit follow the frame on screen.
        mouse.frameShown();
    }
}
