package dev.trisect.view;

import dev.trisect.math.Vec3;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Scene;
import dev.trisect.view.internal.RenderLoop;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewKeys;
import dev.trisect.view.internal.ViewLifecycle;
import dev.trisect.view.internal.ViewState;
import java.awt.Dimension;
import java.util.Arrays;
import java.util.Objects;
import javax.swing.JComponent;

/**
 * The half of {@link TrisectView} that says what it draws and how often: the scene, the camera, the
 * render settings and scale, the camera controls, the frame-time target and frame-rate cap, and its
 * life cycle (the render thread's start and stop). Not API by itself: package private, its public
 * methods are {@code TrisectView}'s, documented there. The other half (listening, picking, commands,
 * developer tools, painting) is {@code TrisectView} itself.
 */
abstract class ViewDrawing extends JComponent implements AutoCloseable {
    private static final long serialVersionUID = 1L;

    /** The longest time step an {@link UpdateListener} is given, seconds. */
    public static final double MAX_STEP_SECONDS = RenderLoop.MAX_STEP_SECONDS;

    /** The camera a new view starts with: 6 units back and 2 up from the origin, looking at it. */
    public static final Camera DEFAULT_CAMERA = Camera.looking(new Vec3(0, 2, 6), Vec3.ZERO);

    final transient ViewState state;
    final transient ViewController controller;
    final transient ViewLifecycle life;
    private final transient ViewKeys keys;

    ViewDrawing(Scene scene, int renderThreads) {
        Objects.requireNonNull(scene, "scene is null: use new Scene() for an empty one");
        if (renderThreads < 1 || renderThreads > FrameRenderer.MAX_THREADS) {
            throw new IllegalArgumentException("render threads must be between 1 and " + FrameRenderer.MAX_THREADS
                    + ", got " + renderThreads);
        }
        state = new ViewState(scene, DEFAULT_CAMERA);
        controller = new ViewController(state, new Surface(), renderThreads);
        setPreferredSize(new Dimension(800, 600));
        setOpaque(true);
        setFocusable(true);
        keys = new ViewKeys(this, controller, Arrays.stream(ViewAction.values()).map(a -> a.id).toList());
        life = new ViewLifecycle(this, controller, this::left);
    }

    /** Turns the pixel inspector on (it follows the mouse) or off. Event thread. */
    abstract void inspector(boolean on);

    /** Shows or hides the developer tools window. Event thread. */
    abstract void devTools(boolean on);

    /** The view left its window or was closed: end what goes with it. Event thread. */
    abstract void left();

    /** What the controller asks of this component. */
    private final class Surface implements ViewController.Surface {
        @Override
        public void repaint() {
            ViewDrawing.this.repaint();
        }

        @Override
        public void inspector(boolean on) {
            ViewDrawing.this.inspector(on);
        }

        @Override
        public void showDevTools(boolean on) {
            devTools(on);
        }
    }

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
     * The camera of the newest frame. In an update hook ({@link TrisectView#addUpdateListener}) it is the camera of the
     * frame the hook runs before, already moved by the camera controls: a light that follows the camera,
     * set from it there, is lit from where that frame looks.
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
     * Holds this frame time — the whole frame, as the frame rate counts it — by choosing the
     * tessellated path's split threshold each frame, never looser than the one in the render settings
     * (its ceiling); 0 turns it off (the default). Any thread.
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
     * @return milliseconds per frame, or 0 when off
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
     * Draws animated frames at most this often: while an update hook animates, the camera moves or
     * the developer tools show. A change to a view that idles is drawn at once, or, within one cap
     * interval of the last frame's start, at the end of that interval. Any thread.
     *
     * @param framesPerSecond the cap, greater than 0; or 0 for none (as fast as the view can draw, to
     *                        measure its frame rate). A new view takes its screen's refresh rate, or 60
     *                        when the screen does not tell it.
     */
    public void setMaxFrameRate(double framesPerSecond) {
        life.checkOpen();
        if (!(framesPerSecond >= 0 && framesPerSecond < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("max frame rate must be 0 (no cap) or more, got " + framesPerSecond);
        }
        state.maxFrameRate(framesPerSecond);
    }

    /**
     * The frame-rate cap.
     *
     * @return frames per second at most, or 0 for none
     */
    public double getMaxFrameRate() {
        return state.maxFrameRate();
    }

    /**
     * Draws one more frame although nothing the view can see changed: after writing a texture's pixels
     * in place, say (changes to the scene graph, the camera and the settings are seen without this).
     * Any thread.
     */
    public void requestFrame() {
        state.demand.request();
    }

    /**
     * Threads that fill each frame.
     *
     * @return the render threads, as given when the view was made
     */
    public int getRenderThreads() {
        return controller.threads();
    }

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
}
