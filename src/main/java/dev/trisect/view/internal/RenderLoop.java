package dev.trisect.view.internal;

import dev.trisect.base.InputException;
import dev.trisect.math.Viewport;
import dev.trisect.metrics.Comparison;
import dev.trisect.metrics.HeatMap;
import dev.trisect.metrics.ImageComparison;
import dev.trisect.metrics.TexelToScreen;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Scene;
import dev.trisect.scene.internal.DrawnFrame;

/**
 * The render thread: draws frames — when something changed or animates ({@link FrameDemand}), at
 * most at the view's frame-rate cap — into the engine's framebuffers and hands them to the
 * event thread through a {@link TripleBuffer}. It never touches Swing; it only asks for a repaint.
 *
 * <p>Per frame it runs the host's update hooks with the time step, reads the latest
 * {@link ViewSettings}, moves the camera by the input gathered since
 * the last frame, draws, and — for the difference and split views, or when a comparison is due (at
 * least twice a second while the developer tools are open) — also draws the per-pixel path with UV
 * output and measures the difference.
 * It then waits until the event thread has shown the frame (at most a short while), so it never
 * runs more than one frame ahead of the screen nor starves the event thread of processor time.
 */
public final class RenderLoop implements Runnable {
    /** A comparison is due when the last one is this old. */
    static final long COMPARE_INTERVAL_NANOS = 400_000_000L;
    /** Longest wait for the event thread to show a frame before drawing the next. */
    static final long PAINT_WAIT_MILLIS = 40;

    private final ViewState state;
    private final TripleBuffer buffers;
    private final Runnable repaint;
    private final FrameRenderer renderer;
    private volatile boolean running = true;
    private final Object paintSignal = new Object();
    private long painted;

    private FrameSlot back;
    private Framebuffer reference;
    /** Time the last frame spent on the comparison: the per-pixel render, other paths' timing, measuring. */
    private long compareStageNanos;
    private float[] displacement;
    /** The scene of the last frame drawn: another one releases the renderer's storage first. */
    private Scene drawnScene;
    /**
     * Frames still to draw after a scene was replaced, even in a still view: until every frame slot has
     * been drawn with the new scene, the others hold the old one's draws (its meshes) from being collected.
     */
    private int settleFrames;
    private final CameraDriver cameras;
    private final BudgetHook budget = new BudgetHook();
    private final HoverHighlight highlight = new HoverHighlight();
    private volatile LoopListener listener;
    private long frames;
    private long lastCompare;
    private double compareMs;

    /**
     * What the loop tells its view, on the render thread: each frame drawn, and problems met.
     */
    public interface LoopListener {
        /** A frame has been handed to the screen. */
        void frameDone(FrameReport report);

        /** A frame could not be drawn; {@code message} is one line. The loop goes on with the next. */
        void problem(String message);

        /**
         * Before frame {@code frame} is drawn, {@code seconds} after the last one started: the host's
         * update hooks run. Returns whether one of them asked for the frame after this one.
         */
        default boolean update(double seconds, long frame) {
            return false;
        }
    }

    /** The longest time step an update hook is given, seconds: after a pause, things move on by at most this. */
    public static final double MAX_STEP_SECONDS = 0.25;

    /**
     * @param state   what the loop shares with the event thread
     * @param buffers where finished frames go
     * @param repaint asks the event thread to paint (called on the render thread)
     * @param threads worker threads of the renderer
     */
    public RenderLoop(ViewState state, TripleBuffer buffers, Runnable repaint, int threads) {
        this.state = state;
        this.buffers = buffers;
        this.repaint = repaint;
        this.renderer = new FrameRenderer(threads);
        this.cameras = new CameraDriver(state);
    }

    public int threads() {
        return renderer.threads();
    }

    /** The loop's renderer, for tests of what it keeps. */
    FrameRenderer renderer() {
        return renderer;
    }

    /** Sets who hears about frames and problems (any thread; one listener). */
    public void listener(LoopListener l) {
        listener = l;
    }

    /** Asks the loop to finish its frame and stop; {@link #run} then closes the renderer and returns. */
    public void stop() {
        running = false;
        framePainted(Long.MAX_VALUE);
    }

    /** Whether {@link #stop} has been called. */
    public boolean stopping() {
        return !running;
    }

    /** The one-line message for a failure: an input error's own, or what went wrong inside. */
    public static String message(Throwable t) {
        if (t instanceof InputException ie) {
            return ie.getMessage();
        }
        if (t instanceof OutOfMemoryError) {
            return "out of memory (lower the render scale, or give Java more with -Xmx)";
        }
        return "internal error: " + t;
    }

    /** Event thread: the frame with this serial number is now on screen. */
    public void framePainted(long serial) {
        synchronized (paintSignal) {
            if (serial > painted) {
                painted = serial;
                paintSignal.notifyAll();
            }
        }
    }

    @Override
    public void run() {
        long last = System.nanoTime();
        FrameRate rate = new FrameRate();
        FrameDemand demand = state.demand;
        try {
            while (running) {
                servePicks();
                int w = state.viewWidth();
                int h = state.viewHeight();
                if (w <= 0 || h <= 0) {
                    // Minimized or not shown yet: nothing to draw.
                    rate.pause();
                    sleep(50);
                    continue;
                }
                long size = ((long) w << 32) | h;
                if (!state.freeze.frozen() && !demand.due(state, size)) {
                    // Nothing changed and nothing animates: idle, and look again shortly.
                    rate.pause();
                    java.util.concurrent.locks.LockSupport.parkNanos(FrameDemand.POLL_NANOS);
                    continue;
                }
                demand.pace(state, this);
                ViewSettings settings = state.settings();
                long now = System.nanoTime();
                // Measured, never negative, and capped after a pause (idle, frozen, hidden, a slow frame).
                double step = Math.max(0, Math.min(MAX_STEP_SECONDS, (now - last) / 1e9));
                double dt = Math.min(0.1, step);
                last = now;
                FreezeGate.Action action = state.freeze.next(settings, frameSize(w, h, settings), state.inspected());
                if (action == FreezeGate.Action.HOLD) {
                    // Frozen: mouse looks and wheel turns made now must not jump the camera on the next step.
                    state.input.takeDrag();
                    state.input.takeWheel();
                    rate.pause();
                    sleep(15);
                    continue;
                }
                boolean animates = false;
                if (action != FreezeGate.Action.REDRAW) {
                    // The hooks' changes (scene, camera, settings) show in this frame: read them after.
                    animates = update(action == FreezeGate.Action.STEP ? FreezeGate.STEP_SECONDS : step, frames + 1);
                    settings = state.settings();
                }
                demand.starting(state, size, animates, now);
                long frameSize = frameSize(w, h, settings);
                int fw = (int) (frameSize >>> 32);
                int fh = (int) frameSize;
                long frameStart = System.nanoTime();
                try {
                    drawFrame(settings, fw, fh, action, action == FreezeGate.Action.STEP ? FreezeGate.STEP_SECONDS : dt);
                } catch (RuntimeException | OutOfMemoryError e) {
                    // Keep the view alive and say what happened; the next frame starts afresh.
                    LoopListener l = listener;
                    if (l != null) {
                        l.problem("rendering failed: " + message(e));
                    }
                    back = null;
                    reference = null;
                    demand.failed();
                    sleep(200);
                    continue;
                }
                long serial = back.serial;
                FrameStats st = back.stats;
                long overlay = back.overlayNanos;
                long presentStart = System.nanoTime();
                double fps = rate.frameShown(presentStart);
                FrameReport report = report(back, settings, (presentStart - frameStart) / 1e6, fps);
                back = buffers.publish(back);
                repaint.run();
                state.progress(new ViewState.Progress(frames, fps, compareMs));
                if (settleFrames > 0) {
                    settleFrames--;
                    demand.request();
                }
                LoopListener l = listener;
                if (l != null) {
                    l.frameDone(report.withFps(fps));
                }
                awaitPaint(serial);
                long end = System.nanoTime();
                state.frameTimes.add(new double[] {st.transformNanos() / 1e6, st.clipNanos() / 1e6,
                    st.tessellateNanos() / 1e6, st.rasterNanos() / 1e6, (st.overlayNanos() + overlay) / 1e6,
                    compareStageNanos / 1e6, (end - presentStart) / 1e6}, (end - frameStart) / 1e6);
                // The budget holds the frame time the user sees: the whole frame, tools and overlay included.
                state.budgetChoice(budget.frameDone(st, (end - frameStart) / 1e6, compareStageNanos / 1e6));
            }
        } finally {
            renderer.close();
        }
    }

    /** The frame's size for a view of w x h device pixels: the render scale, at most the largest frame; width in the high half. */
    private static long frameSize(int w, int h, ViewSettings settings) {
        int fw = Math.max(1, (int) Math.round(w * settings.renderScale()));
        int fh = Math.max(1, (int) Math.round(h * settings.renderScale()));
        double shrink = Math.sqrt((double) ViewState.MAX_FRAME_PIXELS / ((long) fw * fh));
        if (shrink < 1) {
            fw = Math.max(1, (int) (fw * shrink));
            fh = Math.max(1, (int) (fh * shrink));
        }
        return ((long) fw << 32) | fh;
    }

    /** What the listener hears of a frame just drawn into {@code slot}. */
    private FrameReport report(FrameSlot slot, ViewSettings settings, double frameMs, double fps) {
        return new FrameReport(slot.serial, slot.width(), slot.height(), slot.camera, slot.drawnRender, slot.stats,
                frameMs, fps, Warnings.of(slot.stats, state.budgetChoice()));
    }

    private void drawFrame(ViewSettings settings, int fw, int fh, FreezeGate.Action action, double dt) {
        Camera camera = cameras.next(action == FreezeGate.Action.REDRAW, dt);
        long homeSerial = cameras.homeSerial();
        if (back == null || !back.is(fw, fh)) {
            back = new FrameSlot(fw, fh);
        }
        // One consistent snapshot of the scene for every render of this frame; the draws are the slot's
        // own, so that a click on the frame on screen is picked against what that frame drew.
        Scene scene = state.scene();
        if (scene != drawnScene) {
            // A scene replaced: its storage, sized for it, goes now rather than after the trim window, so
            // that the view can load the largest model that fits alone after another.
            renderer.release();
            reference = null;
            displacement = null;
            // The first scene replaces none: no slot holds another's draws, and a still view draws it once.
            settleFrames = drawnScene == null ? 0 : 2;
            drawnScene = scene;
        }
        DrawnFrame drawn = new DrawnFrame(scene.snapshot(), scene.fog().orElse(null), camera, fw, fh, back.draws)
                .withScreenText(scene.screenText());
        Draws draws = back.draws;
        if (!state.toolsOpen() && settings.view() != ViewKind.IMAGE) {
            // The comparison views belong to the developer tools: never shown (nor paid for) without them.
            settings = settings.withView(ViewKind.IMAGE);
        }
        long now = System.nanoTime();
        // Measure only while someone can read the numbers: the developer tools are open.
        // A frame drawn while frozen is always measured: the numbers must describe the frame on screen.
        boolean compareDue = settings.compare() && state.toolsOpen()
                && (action != FreezeGate.Action.RUN || now - lastCompare >= COMPARE_INTERVAL_NANOS);
        long inspected = state.inspected();
        boolean needReference = settings.view() != ViewKind.IMAGE || compareDue || inspected >= 0;
        Framebuffer fb = back.frame;
        // The triangle ids come with the UV output: kept for the comparison, and while anything picks.
        fb.recordUv(needReference || FrameIds.wanted(state, drawn.placed()));
        Viewport viewport = new Viewport(fw, fh);
        long compareStart = System.nanoTime();
        double[] paths = null;
        if (needReference) {
            if (reference == null || reference.width() != fw || reference.height() != fh) {
                reference = new Framebuffer(fw, fh);
                reference.recordUv(true);
                displacement = new float[fw * fh];
            }
            RenderSettings shown = settings.render().withBorders(false);
            TimedDraw draw = (mode, into) -> {
                long t0 = System.nanoTime();
                renderer.render(draws, shown.withMode(mode), into);
                return System.nanoTime() - t0;
            };
            // Before this path, so that the overlay and the inspector see this path's pieces.
            paths = drawReference(shown.mode(), compareDue, reference, draw);
        }
        long compareNanos = System.nanoTime() - compareStart;
        // This path last, so that its pieces are the ones the overlay outlines; the overlay comes after
        // the comparison, which measures the rendered image and never the borders.
        RenderSettings render = budget.apply(settings.render(), state.budget());
        back.stats = renderer.render(draws, render.withBorders(false), fb);
        if (paths != null) {
            paths[settings.render().mode().ordinal()] = back.stats.totalNanos() / 1e6;
            state.pathMs(paths, scene);
        }
        long afterThisPath = System.nanoTime();
        frames++;
        back.serial = frames;
        back.camera = camera;
        back.drawn = drawn;
        state.drawnWith(camera, homeSerial);
        back.render = settings.render();
        back.drawnRender = render;
        back.view = settings.view();
        back.splitFraction = settings.splitFraction();
        back.heatScale = settings.heatScale();
        if (compareDue) {
            long t0 = System.nanoTime();
            // The exact displacement: the loop knows the geometry (maps are built per visible triangle).
            TexelToScreen exact = new TexelToScreen(draws, viewport);
            Comparison c = ImageComparison.compare(fw, fh, fb.colour(), fb.uv(), reference.colour(), reference.uv(),
                    exact, displacement);
            compareMs = (System.nanoTime() - t0) / 1e6;
            lastCompare = now;
            // The settings the frame was drawn with (the budget may have chosen the threshold), so that the
            // copied compare command reproduces these numbers.
            state.measurement(new ViewState.Measurement(c, back.serial, camera, settings.withRender(render), fw, fh,
                    System.nanoTime()), scene);
        } else if (settings.view() == ViewKind.DIFFERENCE) {
            // Between measurements the heat map needs only the displacements, at a fraction of the cost.
            ImageComparison.displacements(fw, fh, fb.uv(), reference.uv(),
                    new TexelToScreen(draws, viewport), displacement);
        }
        compareNanos += System.nanoTime() - afterThisPath;
        back.inspection = null;
        if (inspected >= 0) {
            long t0 = System.nanoTime();
            int ix = (int) (inspected >> 32);
            int iy = (int) inspected;
            if (ix < fw && iy < fh) {
                back.inspection = PixelInspector.inspect(renderer.drawn(), fb, reference,
                        new TexelToScreen(draws, viewport), drawn, settings.render().filter(),
                        settings.render().mode().divides(),
                        settings.render().borders() && settings.view() != ViewKind.DIFFERENCE, ix, iy);
            }
            back.inspectNanos = System.nanoTime() - t0;
        }
        compareStageNanos = compareNanos;
        highlight.apply(fb, draws, drawn.placed(), state.hovered());
        if (settings.view() == ViewKind.DIFFERENCE) {
            back.overlayNanos = 0;
        } else if (settings.render().borders()) {
            // The fallback pieces' magenta outlines come with the others (B), as on the command line, never alone.
            back.overlayNanos = renderer.drawBorders(fb, settings.render().borderStyle(), render.tessellation());
        } else {
            back.overlayNanos = 0;
        }
        if (settings.view() == ViewKind.DIFFERENCE) {
            HeatMap.render(displacement, fb.uv(), reference.uv(), fw, fh, settings.heatScale(), fb.colour());
        } else if (settings.view() == ViewKind.SPLIT) {
            int divider = (int) Math.round(settings.splitFraction() * fw);
            if (divider < fw) {
                int[] dst = fb.colour();
                int[] src = reference.colour();
                for (int y = 0; y < fh; y++) {
                    System.arraycopy(src, y * fw + divider, dst, y * fw + divider, fw - divider);
                }
            }
        }
    }

    /** Draws this frame in one path into a framebuffer; returns the nanoseconds it took. */
    interface TimedDraw {
        long draw(RenderMode mode, Framebuffer into);
    }

    /**
     * Draws the per-pixel path into {@code reference} (which records the UV output the comparison and
     * the inspector read) and, when {@code timeAll}, first times there every other path but the shown
     * one: all are then drawn as the shown path is (after this, into a framebuffer recording the UV
     * output too), so the developer tools' rows of engine time compare like with like. Recording the
     * UV output costs a frame 10-30 %; timed in a frame without it, the other paths looked 10-20 %
     * cheaper than the shown one.
     *
     * @param shown the path the view shows, which the caller draws and times itself
     * @return each path's milliseconds by {@link RenderMode} ordinal (the shown path's left 0), or null
     *         when not {@code timeAll}
     */
    static double[] drawReference(RenderMode shown, boolean timeAll, Framebuffer reference, TimedDraw draw) {
        double[] paths = null;
        if (timeAll) {
            paths = new double[RenderMode.values().length];
            for (RenderMode m : RenderMode.values()) {
                if (m != RenderMode.PERSPECTIVE && m != shown) {
                    paths[m.ordinal()] = draw.draw(m, reference) / 1e6;
                }
            }
        }
        // Last into the reference: the comparison reads the per-pixel frame from it.
        long perspective = draw.draw(RenderMode.PERSPECTIVE, reference);
        if (paths != null) {
            paths[RenderMode.PERSPECTIVE.ordinal()] = perspective / 1e6;
        }
        return paths;
    }

    /** Runs the update hooks before frame {@code frame}; whether one asked for the next frame. */
    private boolean update(double seconds, long frame) {
        LoopListener l = listener;
        return l != null && l.update(seconds, frame);
    }

    /** Answers a click on the frame on screen, between frames (a failure is said once, as a frame's). */
    private void servePicks() {
        try {
            state.picks.serve(renderer);
        } catch (RuntimeException | OutOfMemoryError e) {
            LoopListener l = listener;
            if (l != null) {
                l.problem("picking failed: " + message(e));
            }
        }
    }

    private void awaitPaint(long serial) {
        long deadline = System.currentTimeMillis() + PAINT_WAIT_MILLIS;
        synchronized (paintSignal) {
            while (running && painted < serial) {
                long left = deadline - System.currentTimeMillis();
                if (left <= 0) {
                    return;
                }
                try {
                    paintSignal.wait(left);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    running = false;
                    return;
                }
            }
        }
    }

    private void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            running = false;
        }
    }
}
