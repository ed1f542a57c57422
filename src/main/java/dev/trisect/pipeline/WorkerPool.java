package dev.trisect.pipeline;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

/**
 * The threads a frame's stages run on: the calling thread (thread 0) and {@code threads - 1} daemon
 * helpers of its own, started once and parked between runs. {@link #run} hands out the indices of one
 * job, each exactly once, to whichever thread asks next, and returns when all threads are done.
 *
 * <p>Failure semantics, which callers may rely on:
 * <ul>
 * <li>When a task throws anything — an exception, an {@link Error}, {@link OutOfMemoryError}
 *     included — no thread takes another index of that run (tasks already running finish), and
 *     {@link #run} rethrows the first failure, as itself: a {@link RuntimeException} or an
 *     {@link Error} unchanged (the same instance), any other throwable wrapped in an
 *     {@link IllegalStateException}. Later failures of the same run are dropped.</li>
 * <li>{@link #run} always returns, normally or by that throw, and only after every helper has
 *     finished its part of the run: no task of a run is still running when it returns, so the next
 *     run may reuse all scratch memory. The pool stays usable after a failed run.</li>
 * <li>No helper thread ever ends with an uncaught throwable, and the failure path allocates nothing:
 *     a helper catches every throwable of its tasks, claims the first-failure slot with a
 *     compare-and-set on an {@link AtomicInteger} and stores the throwable in a volatile field, counts
 *     itself done with an atomic decrement and wakes the caller with {@link LockSupport#unpark}. None
 *     of that allocates or links anything on first use (no {@code VarHandle}: {@code AtomicReference}
 *     and {@code AtomicIntegerArray} would link one, which allocates, the first time a failure took
 *     that path), so an out-of-memory error cannot stop the handshake (the cause of the hang issue 14
 *     reports, when the pool was an {@code ExecutorService} and the caller waited in
 *     {@code FutureTask.get()}).</li>
 * <li>An interrupt of the calling thread does not cut a run short (the helpers are using the
 *     frame's scratch); it is kept, set again when {@link #run} returns.</li>
 * <li>After {@link #close}, {@link #run} throws {@link IllegalStateException} ("closed").</li>
 * </ul>
 *
 * <p>One run at a time: {@link #run} is not re-entrant and is called from one thread at a time (a
 * nested call throws {@link IllegalStateException}). Nothing is allocated per run.
 */
final class WorkerPool implements AutoCloseable {
    /** A job over an index: {@code thread} is 0 for the calling thread, 1.. for the helpers. */
    @FunctionalInterface
    interface Task {
        void run(int thread, int index);
    }

    private static final AtomicInteger POOLS = new AtomicInteger();

    /** A helper thread and the number of the last run it was asked to join. */
    private static final class Helper {
        Thread thread;
        volatile int started;
    }

    private final int threads;
    private final Helper[] helpers;
    /** The next index to hand out. */
    private final AtomicInteger next = new AtomicInteger();
    /** Helpers still in the current run. */
    private final AtomicInteger running = new AtomicInteger();
    /** 1 once a task of the current run has failed: the first failing thread claims {@link #failure}. */
    private final AtomicInteger failed = new AtomicInteger();
    /** The first failure of the current run, written once by the thread that claimed it. */
    private volatile Throwable failure;
    private volatile boolean closed;
    private volatile Thread caller;
    /** The current run's job and its index count; published to the helpers by {@link Helper#started}. */
    private Task task;
    private int count;
    private int runs;
    private boolean busy;

    /**
     * @param threads threads to run on, &gt;= 1, the calling thread included
     * @param name    prefix of the helpers' names (a number is added)
     */
    WorkerPool(int threads, String name) {
        this(threads, name, Thread::new);
    }

    /**
     * As {@link #WorkerPool(int, String)}, the helper threads made by {@code factory} (for tests that
     * make a thread's start fail).
     */
    WorkerPool(int threads, String name, java.util.function.BiFunction<Runnable, String, Thread> factory) {
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be at least 1, got " + threads);
        }
        this.threads = threads;
        this.helpers = new Helper[threads - 1];
        int pool = POOLS.incrementAndGet();
        for (int h = 0; h < helpers.length; h++) {
            int thread = h + 1;
            Helper helper = new Helper();
            helper.thread = factory.apply(() -> serve(thread, helper), name + "-" + pool + "-" + thread);
            helper.thread.setDaemon(true);
            helpers[h] = helper;
        }
        try {
            for (Helper h : helpers) {
                h.thread.start();
            }
        } catch (RuntimeException | Error e) {
            // No caller holds the pool to close it, so the helpers already started would wait for work
            // for good (a start fails when the system is out of threads).
            close();
            throw e;
        }
    }

    /** Threads this pool runs on, the calling thread included. */
    int threads() {
        return threads;
    }

    /** Whether a task of the current run has failed: long waits inside tasks should give up then. */
    boolean failed() {
        return failed.get() != 0;
    }

    /**
     * Runs {@code task} for indices 0..count-1, each once, on all threads; returns when all are done.
     * See the class comment for what happens when a task fails.
     */
    void run(int count, Task task) {
        if (closed) {
            throw new IllegalStateException("the renderer is closed: its threads have stopped");
        }
        if (busy) {
            throw new IllegalStateException("a frame is already being drawn on this renderer's threads");
        }
        busy = true;
        try {
            failure = null;
            failed.set(0);
            int helping = Math.min(helpers.length, count - 1);
            if (helping <= 0) {
                for (int i = 0; i < count; i++) {
                    task.run(0, i);
                }
                return;
            }
            this.task = task;
            this.count = count;
            next.set(0);
            caller = Thread.currentThread();
            running.set(helping);
            int run = ++runs;
            for (int h = 0; h < helping; h++) {
                // A volatile write: publishes task and count to the helper that reads it.
                helpers[h].started = run;
                LockSupport.unpark(helpers[h].thread);
            }
            drain(0);
            boolean interrupted = false;
            while (running.get() > 0) {
                LockSupport.park(this);
                // Clearing the flag lets park wait again; the flag is set again below.
                interrupted |= Thread.interrupted();
            }
            this.task = null;
            caller = null;
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
            Throwable first = failure;
            failure = null;
            if (first instanceof RuntimeException e) {
                throw e;
            }
            if (first instanceof Error e) {
                throw e;
            }
            if (first != null) {
                throw new IllegalStateException("a render thread failed", first);
            }
        } finally {
            busy = false;
        }
    }

    /** Takes indices until they run out or a task fails; records a failure instead of throwing it. */
    private void drain(int thread) {
        Task job = task;
        int n = count;
        try {
            for (int i = next.getAndIncrement(); i < n && failed.get() == 0; i = next.getAndIncrement()) {
                job.run(thread, i);
            }
        } catch (Throwable e) {
            fail(e);
        }
    }

    /** Records {@code e} if it is the run's first failure; allocates nothing. */
    private void fail(Throwable e) {
        if (failed.compareAndSet(0, 1)) {
            failure = e;
        }
    }

    /** A helper's life: wait for a run, take its indices, count itself done; never throws. */
    private void serve(int thread, Helper helper) {
        int seen = 0;
        while (!closed) {
            try {
                int run = helper.started;
                if (run == seen) {
                    LockSupport.park(this);
                    continue;
                }
                seen = run;
                try {
                    drain(thread);
                } finally {
                    if (running.decrementAndGet() == 0) {
                        LockSupport.unpark(caller);
                    }
                }
            } catch (Throwable e) {
                // drain records its tasks' failures: nothing should reach here, and if anything
                // does, the thread keeps serving rather than die.
                fail(e);
            }
        }
    }

    /** Stops the helper threads; later {@link #run} calls throw. Idempotent. */
    @Override
    public void close() {
        closed = true;
        for (Helper h : helpers) {
            LockSupport.unpark(h.thread);
        }
    }
}
