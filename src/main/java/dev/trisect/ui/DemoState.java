package dev.trisect.ui;

import dev.trisect.metrics.Comparison;
import dev.trisect.scene.Camera;
import dev.trisect.content.SceneAsset;

/**
 * What the event thread and the render thread share. Each field is an immutable value behind a
 * volatile reference: one side replaces it, the other reads the latest.
 */
final class DemoState {
    /** Largest frame the view renders, in pixels, so a huge window cannot exhaust memory. */
    static final long MAX_FRAME_PIXELS = 3840L * 2160;

    final InputState input = new InputState();
    /** Freeze and step: set by the event thread, obeyed by the render loop. */
    final FreezeGate freeze = new FreezeGate();
    private volatile ViewSettings settings = ViewSettings.defaults();
    private volatile SceneAsset scene;
    private volatile long sceneSerial;
    /** View size in device pixels, width in the high half; 0 when hidden or minimized. */
    private volatile long viewSize;
    private volatile Measurement measurement;
    private volatile Progress progress = new Progress(0, 0, 0);
    private volatile String problem;
    /** The pixel the inspector looks at, frame pixels x in the high half; -1 when the inspector is off. */
    private volatile long inspected = -1;
    /** The last few seconds of frame times by stage, for the graph. */
    final FrameTimes frameTimes = new FrameTimes();
    /** Milliseconds each path (by RenderMode ordinal) took on the last measured frame, or null. */
    private volatile double[] pathMs;
    /** Whether the developer tools are showing, so that their numbers are worth measuring. */
    private volatile boolean toolsOpen;

    private volatile Budget budget = new Budget(false, Budget.DEFAULT_TARGET_MS);
    /** The split threshold the budget controller chose for the last frame, pixels; NaN when off. */
    private volatile double chosenThreshold = Double.NaN;

    /**
     * The frame-time budget: when on, the tessellated path's threshold follows a
     * {@link dev.trisect.perf.BudgetController} holding {@code targetMs}, the user's threshold being
     * its ceiling.
     */
    record Budget(boolean on, double targetMs) {
        static final double DEFAULT_TARGET_MS = 16.7;
    }

    /** A comparison of one frame against the per-pixel path, and what it was made from. */
    record Measurement(Comparison comparison, long frame, Camera camera, ViewSettings settings, int width,
                       int height, long nanos) {
    }

    /**
     * The render loop's pace: frames so far, frames per second over the last second, and milliseconds
     * the last comparison took.
     */
    record Progress(long frames, double fps, double compareMs) {
    }

    DemoState(SceneAsset scene) {
        this.scene = scene;
    }

    ViewSettings settings() {
        return settings;
    }

    void settings(ViewSettings s) {
        settings = s;
    }

    SceneAsset scene() {
        return scene;
    }

    long sceneSerial() {
        return sceneSerial;
    }

    /** Shows another scene from the next frame on; the camera goes to the scene's own. */
    void scene(SceneAsset s) {
        scene = s;
        sceneSerial++;
    }

    void viewSize(int width, int height) {
        viewSize = ((long) Math.max(0, width) << 32) | Math.max(0, height);
    }

    int viewWidth() {
        return (int) (viewSize >>> 32);
    }

    int viewHeight() {
        return (int) viewSize;
    }

    Measurement measurement() {
        return measurement;
    }

    void measurement(Measurement m) {
        measurement = m;
    }

    /** Points the inspector at frame pixel (x, y), or turns it off with a negative x. */
    void inspect(int x, int y) {
        inspected = x < 0 ? -1 : ((long) x << 32) | (y & 0xFFFFFFFFL);
    }

    /** The inspected pixel packed as in {@link #inspect}, -1 when off. */
    long inspected() {
        return inspected;
    }

    double[] pathMs() {
        return pathMs;
    }

    void pathMs(double[] ms) {
        pathMs = ms;
    }

    boolean toolsOpen() {
        return toolsOpen;
    }

    void toolsOpen(boolean open) {
        toolsOpen = open;
    }

    /** A problem the render thread met, for the status bar; taken once. */
    String takeProblem() {
        String p = problem;
        problem = null;
        return p;
    }

    void problem(String message) {
        problem = message;
    }

    Budget budget() {
        return budget;
    }

    void budget(Budget b) {
        budget = b;
    }

    double chosenThreshold() {
        return chosenThreshold;
    }

    void chosenThreshold(double t) {
        chosenThreshold = t;
    }

    Progress progress() {
        return progress;
    }

    void progress(Progress p) {
        progress = p;
    }
}
