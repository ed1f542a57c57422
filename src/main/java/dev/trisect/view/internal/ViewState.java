package dev.trisect.view.internal;

import dev.trisect.base.internal.ChangeSignal;
import dev.trisect.perf.BudgetController;
import java.util.Locale;
import dev.trisect.metrics.Comparison;
import dev.trisect.scene.Camera;
import dev.trisect.content.AssetScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.scene.Scene;
import dev.trisect.render.Fog;
import dev.trisect.render.Shading;
import java.util.List;
import java.util.Optional;

/**
 * What the event thread and the render thread of one view share. Each field is an immutable value
 * behind a volatile reference: one side replaces it, the other reads the latest. Each change that a
 * frame shows wakes an idle render loop ({@link ChangeSignal}).
 */
public final class ViewState {
    /** Largest frame the view renders, in pixels, so a huge window cannot exhaust memory. */
    public static final long MAX_FRAME_PIXELS = 3840L * 2160;

    /** The frame-rate cap when the screen does not tell its refresh rate, frames per second. */
    public static final double DEFAULT_FRAME_RATE = 60;

    /** How the user's input moves the camera. */
    public enum Controls {
        /** Fly: keys move, drags look around, the wheel raises and lowers. */
        FLY,
        /** Orbit round the camera's target: drags turn round it, the wheel and W/S move nearer or further. */
        ORBIT,
        /** None: the camera stays where it was set. */
        NONE
    }

    public final InputState input = new InputState();
    /** Freeze and step: set by the event thread, obeyed by the render loop. */
    public final FreezeGate freeze = new FreezeGate();
    /** Whether a frame is due, and the pace of animated ones. */
    public final FrameDemand demand = new FrameDemand();
    /** Frames per second at most, as the host set it: 0 for no cap, NaN for the screen's refresh rate. */
    private volatile double maxFrameRate = Double.NaN;
    /** The refresh rate of the view's screen, frames per second (60 when the screen does not say). */
    private volatile double screenRate = DEFAULT_FRAME_RATE;
    /** The node whose hover highlight the frames draw: the one under the pointer holding one; null for none. */
    private volatile dev.trisect.scene.Node hovered;
    private volatile ViewSettings settings = ViewSettings.defaults();
    private volatile Scene scene;
    /** The camera set by the host (and the one R returns to), with a serial so the loop sees each setting. */
    private volatile CameraRequest home;
    private volatile Controls controls = Controls.FLY;
    /** The camera of the newest frame drawn, or the home camera before the first. */
    private volatile Camera current;
    /** View size in device pixels, width in the high half; 0 when hidden or minimized. */
    private volatile long viewSize;
    /** Device pixels per logical (Swing) pixel of the view's screen: 2 on a high-density screen at 200 %. */
    private volatile double screenScale = 1;
    private volatile Measurement measurement;
    private volatile Progress progress = new Progress(0, 0, 0);
    /** The pixel the inspector looks at, frame pixels x in the high half; -1 when the inspector is off. */
    private volatile long inspected = -1;
    /** Pinned pixels, packed as {@link #inspected}, oldest first; a new array on each change. */
    private volatile long[] pins = new long[0];
    /** How many pixels may be pinned at once: a short list that reads at a glance. */
    public static final int MAX_PINS = 4;
    /** The last few seconds of frame times by stage, for the graph. */
    public final FrameTimes frameTimes = new FrameTimes();
    /** Milliseconds each path (by RenderMode ordinal) took on the last measured frame, or null. */
    private volatile double[] pathMs;
    /** Whether developer tools are showing, so that their numbers are worth measuring. */
    private volatile boolean toolsOpen;
    private volatile boolean statOverlay;

    private volatile Budget budget = new Budget(false, Budget.DEFAULT_TARGET_MS);
    /** What the budget controller chose for the last frame; null when it is off. */
    private volatile BudgetChoice budgetChoice;

    /** A camera the host set, numbered so that setting the same camera twice still moves the view back. */
    public record CameraRequest(Camera camera, long serial) {
    }

    /**
     * The frame-time budget: when on, the tessellated path's threshold follows a
     * {@link dev.trisect.perf.BudgetController} holding {@code targetMs}, the user's threshold being
     * its ceiling.
     */
    public record Budget(boolean on, double targetMs) {
        public static final double DEFAULT_TARGET_MS = 16.7;
    }

    /**
     * What the budget controller chose for a frame, and why, in one value, so that every readout of it
     * agrees: the status bar's warning and the tools' chosen threshold, its reason and its last change.
     *
     * @param threshold  the split threshold chosen for the next frame, pixels
     * @param limit      what holds the controller there
     * @param medianMs   the median frame time (as the status bar's rate counts it) of the last window,
     *                   milliseconds (NaN before one)
     * @param targetMs   the target it holds, milliseconds
     * @param ceiling    the user's threshold, the loosest it may choose, pixels
     * @param drawnAt    the threshold of the frame just drawn, pixels
     * @param pieces     that frame's pieces (filled and dropped off screen: what the piece budget counts)
     * @param pieceBudget that frame's piece budget
     * @param pieceFloor the finest threshold that frame's pieces allow (0 before any), pixels
     * @param lastChange the last change of threshold and why ("32.000 → 21.333 px: median frame 52.0 ms
     *                   over the 40.0 ms target")
     */
    public record BudgetChoice(double threshold, BudgetController.Limit limit, double medianMs, double targetMs,
                               double ceiling, double drawnAt, long pieces, long pieceBudget, double pieceFloor,
                               String lastChange) {
        /**
         * Why the threshold is where it is, in a few words for a readout: "your threshold" (the ceiling:
         * the target is out of reach), "the finest" (the floor: met with room to spare), "piece budget"
         * (finer would overfill it); empty when it simply follows the target.
         */
        public String reason() {
            return switch (limit) {
                case CEILING -> "your threshold";
                case FLOOR -> "the finest";
                case PIECE_BUDGET -> "piece budget";
                case TARGET -> "";
            };
        }

        /**
         * Why, in a sentence whose numbers are those the tools show beside it: the median frame time against
         * the target, or the pieces against their budget.
         */
        public String why() {
            if (Double.isNaN(medianMs)) {
                return String.format(Locale.ROOT, "measuring: the first %d frames decide", BudgetController.WINDOW);
            }
            return switch (limit) {
                case CEILING -> String.format(Locale.ROOT, "out of reach: median frame %.1f ms over the %.1f ms target "
                        + "even at your threshold, %.3f px, the loosest Auto may choose", medianMs, targetMs, ceiling);
                case FLOOR -> String.format(Locale.ROOT, "met with room to spare: median frame %.1f ms under the %.1f ms "
                        + "target even at the finest threshold, %.3f px", medianMs, targetMs, threshold);
                case PIECE_BUDGET -> String.format(Locale.ROOT, "piece budget: %,d of %,d pieces at %.3f px, so finer "
                        + "than %.3f px would fill more than %.0f %% of it (median frame %.1f ms, target %.1f ms)",
                        pieces, pieceBudget, drawnAt, pieceFloor, 100 * BudgetController.BUDGET_AIM, medianMs, targetMs);
                case TARGET -> String.format(Locale.ROOT, "following the target: median frame %.1f ms against %.1f ms",
                        medianMs, targetMs);
            };
        }
    }

    /**
     * A comparison of one frame against the per-pixel path, and what it was made from: with the lights
     * that shone on it (world space, as placed for that frame: the demo's lamp moves every frame), its
     * fog, and the one shading all its materials had ({@code null} when they differed).
     */
    public record Measurement(Comparison comparison, long frame, Camera camera, ViewSettings settings, int width,
                              int height, long nanos, List<Scene.PlacedLight> lights, Optional<Fog> fog,
                              Shading shading) {
        /** Keeps an unmodifiable copy of the lights. */
        public Measurement {
            lights = List.copyOf(lights);
        }

        /** A frame without light or fog, its materials unlit. */
        public Measurement(Comparison comparison, long frame, Camera camera, ViewSettings settings, int width,
                           int height, long nanos) {
            this(comparison, frame, camera, settings, width, height, nanos, List.of(), Optional.empty(), Shading.NONE);
        }

        /**
         * The one shading of every material of {@code objects} that draw {@code mesh} (of all of them when it
         * is null), or null when they differ; none without materials. The command line draws a built-in
         * scene's or a model's mesh alone, without what the demo adds (labels, axes, glass), whose shading
         * is not the command's.
         */
        static Shading shading(List<Scene.Placed> objects, dev.trisect.mesh.Mesh mesh) {
            Shading one = null;
            for (Scene.Placed o : objects) {
                if (mesh != null && o.mesh() != mesh) {
                    continue;
                }
                for (dev.trisect.scene.Material m : o.materials()) {
                    if (one != null && m.shading() != one) {
                        return null;
                    }
                    one = m.shading();
                }
            }
            return one == null ? Shading.NONE : one;
        }
    }

    /**
     * The render loop's pace: frames so far, frames per second over the last second, and milliseconds
     * the last comparison took.
     */
    public record Progress(long frames, double fps, double compareMs) {
    }

    /** A view of {@code scene} from {@code camera}. */
    public ViewState(Scene scene, Camera camera) {
        this.scene = scene;
        camera(camera);
    }

    /** A view of a built-in scene or an OBJ file, from its own camera (the command line draws the same). */
    public ViewState(SceneAsset asset) {
        this(AssetScenes.scene(asset), asset.camera());
    }

    public ViewSettings settings() {
        return settings;
    }

    public synchronized void settings(ViewSettings s) {
        settings = s;
        ChangeSignal.signal();
    }

    /** Replaces the settings by {@code change} of them, atomically against other changes (any thread). */
    public synchronized ViewSettings updateSettings(java.util.function.UnaryOperator<ViewSettings> change) {
        settings = change.apply(settings);
        ChangeSignal.signal();
        return settings;
    }

    public Scene scene() {
        return scene;
    }

    /**
     * Shows another scene from the next frame on; the camera stays where it is. The last measurement
     * and each path's time described the scene shown before: they go, so that the developer tools
     * neither show them for this one nor copy a compare command that names this scene with the other's
     * camera and numbers (as they did with measuring off, or until the next measurement).
     */
    public synchronized void scene(Scene s) {
        scene = s;
        measurement = null;
        pathMs = null;
        ChangeSignal.signal();
    }

    /** Puts the camera here from the next frame on, and makes it the one R returns to. */
    public synchronized void camera(Camera c) {
        long serial = home == null ? 0 : home.serial() + 1;
        home = new CameraRequest(c, serial);
        current = c;
        ChangeSignal.signal();
    }

    public CameraRequest home() {
        return home;
    }

    /**
     * The camera of the newest frame, from when the controls moved it for that frame (before its update
     * hooks run), or the one just set, before it is drawn.
     */
    public Camera currentCamera() {
        return current;
    }

    /** Render thread: the camera the newest frame is drawn with, moved by the controls from home camera {@code homeSerial}. */
    public synchronized void drawnWith(Camera c, long homeSerial) {
        // A camera set after this frame began wins until its own frame is drawn.
        if (home.serial() == homeSerial) {
            current = c;
        }
    }

    public Controls controls() {
        return controls;
    }

    public void controls(Controls c) {
        controls = c;
        ChangeSignal.signal();
    }

    public void viewSize(int width, int height) {
        viewSize = ((long) Math.max(0, width) << 32) | Math.max(0, height);
        ChangeSignal.signal();
    }

    /** Sets the device pixels per logical pixel of the view's screen (1 when it does not say). */
    public void screenScale(double scale) {
        screenScale = Double.isFinite(scale) && scale > 0 ? scale : 1;
    }

    /** Device pixels per logical pixel of the view's screen. */
    public double screenScale() {
        return screenScale;
    }

    public int viewWidth() {
        return (int) (viewSize >>> 32);
    }

    public int viewHeight() {
        return (int) viewSize;
    }

    public Measurement measurement() {
        return measurement;
    }

    /** Render thread: the comparison of a frame of {@code drawn}, kept unless another scene is shown since. */
    public synchronized void measurement(Measurement m, Scene drawn) {
        if (drawn == scene) {
            measurement = m;
        }
    }

    /** Points the inspector at frame pixel (x, y), or turns it off with a negative x. */
    public void inspect(int x, int y) {
        inspected = x < 0 ? -1 : ((long) x << 32) | (y & 0xFFFFFFFFL);
        ChangeSignal.signal();
    }

    /**
     * Pins frame pixel (x, y) — its readout then shows and updates every frame — or unpins it if it is
     * pinned; a pin beyond {@link #MAX_PINS} unpins the oldest.
     */
    public synchronized void togglePin(int x, int y) {
        long p = ((long) x << 32) | (y & 0xFFFFFFFFL);
        long[] now = pins;
        int at = -1;
        for (int k = 0; k < now.length; k++) {
            at = now[k] == p ? k : at;
        }
        long[] next;
        if (at >= 0) {
            next = new long[now.length - 1];
            System.arraycopy(now, 0, next, 0, at);
            System.arraycopy(now, at + 1, next, at, now.length - at - 1);
        } else {
            int keep = Math.min(now.length, MAX_PINS - 1);
            next = new long[keep + 1];
            System.arraycopy(now, now.length - keep, next, 0, keep);
            next[keep] = p;
        }
        pins = next;
        ChangeSignal.signal();
    }

    /** Unpins every pixel. */
    public void clearPins() {
        pins = new long[0];
        ChangeSignal.signal();
    }

    /** The pinned pixels, packed as {@link #inspected}, oldest first; do not change the array. */
    public long[] pins() {
        return pins;
    }

    /** The inspected pixel packed as in {@link #inspect}, -1 when off. */
    public long inspected() {
        return inspected;
    }

    public double[] pathMs() {
        return pathMs;
    }

    /** Render thread: each path's time on a frame of {@code drawn}, kept unless another scene is shown since. */
    public synchronized void pathMs(double[] ms, Scene drawn) {
        if (drawn == scene) {
            pathMs = ms;
        }
    }

    /** Whether the statistics overlay (U) is painted over the view. */
    public boolean statOverlay() {
        return statOverlay;
    }

    /** Shows or hides the statistics overlay. */
    public void statOverlay(boolean on) {
        statOverlay = on;
    }

    public boolean toolsOpen() {
        return toolsOpen;
    }

    public void toolsOpen(boolean open) {
        toolsOpen = open;
        ChangeSignal.signal();
    }

    public Budget budget() {
        return budget;
    }

    public void budget(Budget b) {
        budget = b;
        ChangeSignal.signal();
    }

    /** What the budget controller chose for the last frame, or null when it is off. */
    public BudgetChoice budgetChoice() {
        return budgetChoice;
    }

    public void budgetChoice(BudgetChoice c) {
        budgetChoice = c;
    }

    /** The node whose hover highlight the frames draw, or null. */
    public dev.trisect.scene.Node hovered() {
        return hovered;
    }

    /** Event thread: the pointer is over this node's objects, and it holds a hover highlight (or null). */
    public void hovered(dev.trisect.scene.Node owner) {
        hovered = owner;
        ChangeSignal.signal();
    }

    /** Sets the cap: frames per second at most, 0 for none, NaN to follow the screen's refresh rate. */
    public void maxFrameRate(double fps) {
        maxFrameRate = fps;
        ChangeSignal.signal();
    }

    /** The cap in force: frames per second at most, 0 for none. */
    public double maxFrameRate() {
        double m = maxFrameRate;
        return Double.isNaN(m) ? screenRate : m;
    }

    /** The refresh rate of the screen the view shows on (0 or less when it does not say: 60 then). */
    public void screenRate(double hz) {
        screenRate = hz > 0 ? hz : DEFAULT_FRAME_RATE;
    }

    public Progress progress() {
        return progress;
    }

    public void progress(Progress p) {
        progress = p;
    }
}
