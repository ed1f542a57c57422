package dev.trisect.view.internal;

import dev.trisect.base.internal.ChangeSignal;
import dev.trisect.scene.Scene;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Whether the render loop should draw a frame now, and when the next may start. A view draws only
 * when something it shows changed since its last frame — the scene ({@link Scene#version()}), the
 * settings, the size, the host's camera, the controls, the frame-time budget, the inspected pixel,
 * the node under the pointer whose hover highlight shows —
 * or when something animates: an update hook that said so, the camera moving under the user's input
 * (or the auto-orbit), the developer tools showing (their live graph), the budget controller, or a
 * reason registered with {@link #keepDrawing}. Otherwise the loop idles until a change wakes it: each
 * setter of {@link ViewState}, the input, the freeze gate, {@link #request}, {@link #keepDrawing} and
 * every change to a scene signal it ({@link dev.trisect.base.internal.ChangeSignal}), so a change is
 * drawn at once, not at the next look; the loop also looks every {@link #IDLE_LOOK_NANOS} in case a
 * change came without a signal. Animated frames are paced to at most the view's maximum frame rate.
 *
 * <p>{@link #keepDrawing} and {@link #request} from any thread; the rest on the render thread.
 */
public final class FrameDemand {
    /** How often an idle loop looks for a change that came without a signal, nanoseconds. */
    static final long IDLE_LOOK_NANOS = 1_000_000_000L;

    /** How long an idle loop waits between looks; a test lengthens it to show that signals alone wake it. */
    volatile long idleLook = IDLE_LOOK_NANOS;

    /** Everything the last frame was drawn from that a host or user may change. */
    private record Seen(Scene scene, long version, ViewSettings settings, long size, long home,
                        ViewState.Controls controls, ViewState.Budget budget, long inspected, long[] pins,
                        Object hovered) {
    }

    private final Set<Object> reasons = ConcurrentHashMap.newKeySet();
    private final AtomicBoolean requested = new AtomicBoolean();
    /** What the last frame drawn saw; null before the first (or after a failed one). Render thread. */
    private Seen drawn;
    /** Whether an update hook asked for the next frame. Render thread. */
    private boolean animating;
    /** The time the pace and the update hooks' steps are read from; set before the loop starts. */
    volatile FrameClock clock = FrameClock.SYSTEM;
    /** {@link #clock} when the last frame started, for the pace. Render thread. */
    private long lastStart;
    private boolean started;

    /**
     * Keeps frames coming while {@code reason} is registered (an animation, a live readout), or stops
     * doing so for it. Any thread; the same key twice counts once.
     */
    public void keepDrawing(Object reason, boolean on) {
        if (on) {
            reasons.add(reason);
            ChangeSignal.signal();
        } else {
            reasons.remove(reason);
        }
    }

    /** Asks for one more frame even though nothing the view can see changed. Any thread. */
    public void request() {
        requested.set(true);
        ChangeSignal.signal();
    }

    /** Whether a frame is due now: something changed since the last one, or something animates. */
    boolean due(ViewState state, long size) {
        if (drawn == null || animating || requested.get() || !reasons.isEmpty() || state.toolsOpen()
                || state.budget().on() || CameraRig.moving(state.input) || state.input.pendingReset()) {
            return true;
        }
        // The scene first: the usual change, found without building and comparing the whole record (which
        // runs in the interpreter, as a loop that idles runs this rarely: 0.1 ms a wake).
        Scene scene = state.scene();
        return drawn.scene() != scene || drawn.version() != scene.version() || !drawn.equals(seen(state, size));
    }

    /**
     * The cap in force, frames per second (0 for none): the view's, raised under a frame-time target to
     * the target's rate, so that a 10 ms target can show 100 fps where the screen's 60 Hz cap held it
     * at 60 and Auto could never meet it.
     */
    static double cap(ViewState state) {
        double cap = state.maxFrameRate();
        ViewState.Budget b = state.budget();
        return cap > 0 && b.on() ? Math.max(cap, 1000 / b.targetMs()) : cap;
    }

    /** Render thread: waits until the cap allows the next frame to start (at once when it is off). */
    void pace(ViewState state, RenderLoop loop) {
        double cap = cap(state);
        if (!started || cap <= 0) {
            return;
        }
        long next = lastStart + (long) (1e9 / cap);
        long wait;
        FrameClock c = clock;
        while (!loop.stopping() && (wait = next - c.nanos()) > 0) {
            c.park(wait);
        }
    }

    /**
     * Render thread: a frame starts now, from what {@code state} holds (read after the update hooks
     * ran); {@code animates} is whether a hook asked for the next frame.
     */
    void starting(ViewState state, long size, boolean animates, long now) {
        requested.set(false);
        drawn = seen(state, size);
        animating = animates;
        lastStart = now;
        started = true;
    }

    /** Render thread: the frame failed; the next look draws again. */
    void failed() {
        drawn = null;
    }

    private static Seen seen(ViewState state, long size) {
        Scene scene = state.scene();
        return new Seen(scene, scene.version(), state.settings(), size, state.home().serial(), state.controls(),
                state.budget(), state.inspected(), state.pins(), state.hovered());
    }
}
