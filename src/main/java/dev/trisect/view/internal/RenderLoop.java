package dev.trisect.view.internal;

import dev.trisect.base.internal.ErrorLine;
import dev.trisect.base.internal.ChangeSignal;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.FrameStats;

/**
 * The render thread: draws frames — when something changed or animates ({@link FrameDemand}), at
 * most at the view's frame-rate cap — into the engine's framebuffers and hands them to the
 * event thread through a {@link TripleBuffer}. It never touches Swing; it only asks for a repaint.
 *
 * <p>Per frame it runs the host's update hooks with the time step, reads the latest
 * {@link ViewSettings} and has a {@link FrameDrawer} draw the frame (camera, path, comparison,
 * overlay) into a free slot.
 * It then waits until the event thread has shown the frame (at most a short while), so it never
 * runs more than one frame ahead of the screen nor starves the event thread of processor time.
 */
public final class RenderLoop implements Runnable {
    /** Longest wait for the event thread to show a frame before drawing the next. */
    static final long PAINT_WAIT_MILLIS = 40;

    private final ViewState state;
    private final TripleBuffer buffers;
    private final Runnable repaint;
    private final FrameRenderer renderer;
    private volatile boolean running = true;
    private final Object paintSignal = new Object();
    private long painted;

    private final FrameDrawer drawer;
    private FrameSlot back;
    private volatile LoopListener listener;

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
        this.drawer = new FrameDrawer(state, renderer);
    }

    public int threads() {
        return renderer.threads();
    }

    /** The loop's renderer, for tests of what it keeps. */
    FrameRenderer renderer() {
        return renderer;
    }

    /** The loop's frame drawer, for tests of what it keeps. */
    FrameDrawer drawer() {
        return drawer;
    }

    /** Sets who hears about frames and problems (any thread; one listener). */
    public void listener(LoopListener l) {
        listener = l;
    }

    /** Asks the loop to finish its frame and stop; {@link #run} then closes the renderer and returns. */
    public void stop() {
        running = false;
        framePainted(Long.MAX_VALUE);
        // An idle loop stops now, not at its next look.
        ChangeSignal.signal();
    }

    /** Whether {@link #stop} has been called. */
    public boolean stopping() {
        return !running;
    }

    /** What to do when a frame runs out of memory. */
    static final String MEMORY_HINT = "lower the render scale, or give Java more with -Xmx";

    /** The one-line message for a failure to do {@code doing}: "trisect: cannot draw the frame: reason". */
    public static String failure(String doing, Throwable t) {
        return ErrorLine.cannot(doing, t, MEMORY_HINT);
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
        FrameDemand demand = state.demand;
        long last = demand.clock.nanos();
        FrameRate rate = new FrameRate();
        try {
            while (running) {
                // Read before looking for work: a change made while looking still wakes the wait below.
                long seen = ChangeSignal.epoch();
                int w = state.viewWidth();
                int h = state.viewHeight();
                if (w <= 0 || h <= 0) {
                    // Minimized or not shown yet: nothing to draw until the size changes.
                    rate.pause();
                    ChangeSignal.await(seen, demand.idleLook);
                    continue;
                }
                long size = ((long) w << 32) | h;
                if (!state.freeze.frozen() && !demand.due(state, size)) {
                    // Nothing changed and nothing animates: idle until something does.
                    rate.pause();
                    ChangeSignal.await(seen, demand.idleLook);
                    continue;
                }
                demand.pace(state, this);
                ViewSettings settings = state.settings();
                long now = demand.clock.nanos();
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
                double cameraStep = action == FreezeGate.Action.STEP ? FreezeGate.STEP_SECONDS : dt;
                // The controls move the camera first, so that the hooks see the camera of their frame.
                drawer.aim(action == FreezeGate.Action.REDRAW, cameraStep);
                boolean animates = false;
                if (action != FreezeGate.Action.REDRAW) {
                    // The hooks' changes (scene, camera, settings) show in this frame: read them after.
                    animates = update(action == FreezeGate.Action.STEP ? FreezeGate.STEP_SECONDS : step,
                            drawer.frames() + 1);
                    settings = state.settings();
                }
                demand.starting(state, size, animates, now);
                long frameSize = frameSize(w, h, settings);
                int fw = (int) (frameSize >>> 32);
                int fh = (int) frameSize;
                long frameStart = System.nanoTime();
                try {
                    back = drawer.draw(back, settings, fw, fh, action);
                } catch (RuntimeException | OutOfMemoryError e) {
                    // Keep the view alive and say what happened; the next frame starts afresh.
                    LoopListener l = listener;
                    if (l != null) {
                        l.problem(failure("draw the frame", e));
                    }
                    back = null;
                    drawer.failed();
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
                state.progress(new ViewState.Progress(drawer.frames(), fps, drawer.compareMs()));
                if (drawer.settling()) {
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
                    drawer.compareStageNanos() / 1e6, (end - presentStart) / 1e6}, (end - frameStart) / 1e6);
                // The budget holds the frame time the user sees: the whole frame, tools and overlay included.
                state.budgetChoice(drawer.budget().frameDone(st, (end - frameStart) / 1e6,
                        drawer.compareStageNanos() / 1e6));
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

    /** Runs the update hooks before frame {@code frame}; whether one asked for the next frame. */
    private boolean update(double seconds, long frame) {
        LoopListener l = listener;
        return l != null && l.update(seconds, frame);
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
