package dev.trisect.view.internal;

import dev.trisect.base.internal.ChangeSignal;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Freeze and step. While frozen the render loop draws nothing new unless asked: a step draws the
 * next frame one {@link #STEP_SECONDS} later (orbit and held keys move on by that much), and a change
 * of settings or view size redraws the same frame from the same camera, so a frozen frame can be
 * inspected with borders, another view or another split policy. Every frame drawn while frozen is
 * measured, so the numbers always describe the frame on screen.
 *
 * <p>The event thread calls {@link #freeze} and {@link #step}; the render thread calls
 * {@link #next}.
 */
public final class FreezeGate {
    /** Time one step moves on, seconds: one frame at 60 frames per second. */
    static final double STEP_SECONDS = 1.0 / 60;

    /** What the render loop does next. */
    enum Action {
        /** Draw the next frame in real time. */
        RUN,
        /** Draw one frame {@link #STEP_SECONDS} on from the frozen one. */
        STEP,
        /** Draw the frozen frame again, same camera (settings or size changed). */
        REDRAW,
        /** Draw nothing: keep showing the frozen frame. */
        HOLD
    }

    private volatile boolean frozen;
    /** Written by the render thread: whether its last answer was {@link Action#HOLD}. */
    private volatile boolean holding;
    private final AtomicInteger steps = new AtomicInteger();
    /** Render thread only: what the frozen frame was drawn with. */
    private ViewSettings drawnSettings;
    private long drawnSize = -1;
    private long drawnInspected = -1;

    public boolean frozen() {
        return frozen;
    }

    /**
     * Whether the render loop has answered {@link Action#HOLD} since it last drew: frozen, and the
     * frame it drew last (a frame under way when {@link #freeze} was called included) is handed to
     * the screen, with nothing new under way. {@link #frozen} alone does not say that frame is done.
     * Any thread.
     */
    public boolean holding() {
        return holding;
    }

    /** Event thread: freezes or thaws; thawing drops steps not yet taken. */
    public void freeze(boolean on) {
        frozen = on;
        if (!on) {
            steps.set(0);
        }
        ChangeSignal.signal();
    }

    /** Event thread: asks for one step; freezes first if running. */
    public void step() {
        frozen = true;
        steps.incrementAndGet();
        ChangeSignal.signal();
    }

    /**
     * Render thread: what to do now, given the settings and view size in force. A STEP or REDRAW
     * (and RUN) counts as drawn with these settings.
     */
    Action next(ViewSettings settings, long size) {
        return next(settings, size, -1);
    }

    /** As {@link #next(ViewSettings, long)}; a change of the inspected pixel also redraws the frozen frame. */
    Action next(ViewSettings settings, long size, long inspected) {
        Action a;
        if (!frozen) {
            a = Action.RUN;
        } else if (steps.get() > 0) {
            steps.decrementAndGet();
            a = Action.STEP;
        } else if (!settings.equals(drawnSettings) || size != drawnSize || inspected != drawnInspected) {
            a = Action.REDRAW;
        } else {
            holding = true;
            return Action.HOLD;
        }
        holding = false;
        drawnSettings = settings;
        drawnSize = size;
        drawnInspected = inspected;
        return a;
    }
}
