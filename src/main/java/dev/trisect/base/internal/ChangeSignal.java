package dev.trisect.base.internal;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

/**
 * Wakes idle render loops the moment something they draw may have changed: a scene changed (any
 * scene), a view's settings, camera, size or input. A loop with nothing to draw reads {@link #epoch},
 * checks whether a frame is due, and if not {@link #await}s a change; whoever changes something calls
 * {@link #signal}. One signal for the whole process: a change wakes every idle view, each of which
 * looks whether the change was its own and sleeps again if not — a few microseconds, against a
 * scene graph that would otherwise need a listener per view. Any thread.
 */
public final class ChangeSignal {
    private static final AtomicLong EPOCH = new AtomicLong();
    private static final Set<Thread> WAITING = ConcurrentHashMap.newKeySet();

    private ChangeSignal() {
    }

    /** The count of signals so far: read it before looking whether there is work, and pass it to {@link #await}. */
    public static long epoch() {
        return EPOCH.get();
    }

    /** Something changed: every thread in {@link #await} wakes. */
    public static void signal() {
        EPOCH.incrementAndGet();
        for (Thread t : WAITING) {
            LockSupport.unpark(t);
        }
    }

    /**
     * Waits until a signal after the one counted by {@code seen} (at once if there has been one since),
     * or {@code timeoutNanos} passed, or the thread was interrupted.
     */
    public static void await(long seen, long timeoutNanos) {
        Thread me = Thread.currentThread();
        WAITING.add(me);
        try {
            long deadline = System.nanoTime() + timeoutNanos;
            long left;
            // A signal between reading seen and joining WAITING shows in the epoch: no wake is lost.
            while (EPOCH.get() == seen && !me.isInterrupted() && (left = deadline - System.nanoTime()) > 0) {
                LockSupport.parkNanos(ChangeSignal.class, left);
            }
        } finally {
            WAITING.remove(me);
        }
    }
}
