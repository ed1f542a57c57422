package dev.trisect.view.internal;

import java.util.concurrent.locks.LockSupport;

/**
 * The time that paces the render loop's frames and gives the update hooks their steps, and the wait
 * until a frame may start: {@link #SYSTEM}, the JVM's monotonic clock, unless a test sets its own
 * ({@link FrameDemand#clock}), so that what it checks of the pace and the steps does not depend on how
 * fast the machine runs. Read on the render thread only.
 */
interface FrameClock {
    /** The system's clock: {@link System#nanoTime} and {@link LockSupport#parkNanos}. */
    FrameClock SYSTEM = new FrameClock() {
        @Override
        public long nanos() {
            return System.nanoTime();
        }

        @Override
        public void park(long nanos) {
            LockSupport.parkNanos(nanos);
        }
    };

    /** Now, in nanoseconds from an arbitrary origin (only differences mean anything). */
    long nanos();

    /** Waits about {@code nanos} nanoseconds (less if woken). */
    void park(long nanos);
}
