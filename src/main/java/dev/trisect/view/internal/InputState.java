package dev.trisect.view.internal;

import dev.trisect.base.internal.ChangeSignal;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Input gathered on the event thread and consumed by the render thread: held movement keys, mouse
 * drag and wheel amounts since the last frame, and one-shot requests. Lock-free.
 */
public final class InputState {
    public static final int FORWARD = 1;
    public static final int BACK = 2;
    public static final int LEFT = 4;
    public static final int RIGHT = 8;
    public static final int UP = 16;
    public static final int DOWN = 32;
    public static final int FAST = 64;

    private final AtomicInteger held = new AtomicInteger();
    /**
     * Keys pressed since the render thread last took the held keys: a key pressed and released
     * between two frames (a quick tap) would otherwise never be seen held, and the camera would not
     * move at all.
     */
    private final AtomicInteger pressed = new AtomicInteger();
    /** Drag in logical pixels, x in the high half and y in the low half, as two packed ints. */
    private final AtomicLong drag = new AtomicLong();
    private final AtomicInteger wheel = new AtomicInteger();
    private final AtomicBoolean reset = new AtomicBoolean();
    private volatile boolean orbit;

    public void press(int key) {
        held.getAndUpdate(v -> v | key);
        pressed.getAndUpdate(v -> v | key);
        ChangeSignal.signal();
    }

    public void release(int key) {
        held.getAndUpdate(v -> v & ~key);
    }

    /** Forgets held keys, for when the window loses the keyboard and would miss their release. */
    public void releaseAll() {
        held.set(0);
        pressed.set(0);
    }

    /** The keys held now. */
    public int held() {
        return held.get();
    }

    /** The keys held now or pressed since the last call (a tap between two frames moves for one). */
    public int takeHeld() {
        return held.get() | pressed.getAndSet(0);
    }

    /** {@link #takeHeld()} without taking: the keys held now or pressed since it was last called. */
    public int pendingHeld() {
        return held.get() | pressed.get();
    }

    public void drag(int dx, int dy) {
        drag.getAndUpdate(v -> pack(unpackX(v) + dx, unpackY(v) + dy));
        ChangeSignal.signal();
    }

    /** The drag since the last call, {dx, dy} in logical pixels. */
    public int[] takeDrag() {
        long v = drag.getAndSet(0);
        return new int[] {unpackX(v), unpackY(v)};
    }

    public void wheel(int notches) {
        wheel.addAndGet(notches);
        ChangeSignal.signal();
    }

    /** Whether a drag waits to be taken. */
    public boolean pendingDrag() {
        return drag.get() != 0;
    }

    /** Whether wheel turns wait to be taken. */
    public boolean pendingWheel() {
        return wheel.get() != 0;
    }

    public int takeWheel() {
        return wheel.getAndSet(0);
    }

    public void requestReset() {
        reset.set(true);
        ChangeSignal.signal();
    }

    /** Whether a reset waits to be taken. */
    public boolean pendingReset() {
        return reset.get();
    }

    public boolean takeReset() {
        return reset.getAndSet(false);
    }

    public boolean orbit() {
        return orbit;
    }

    public void orbit(boolean on) {
        orbit = on;
        ChangeSignal.signal();
    }

    private static long pack(int x, int y) {
        return ((long) x << 32) | (y & 0xFFFFFFFFL);
    }

    private static int unpackX(long v) {
        return (int) (v >> 32);
    }

    private static int unpackY(long v) {
        return (int) v;
    }
}
