package dev.trisect.cli;

import dev.trisect.base.internal.Counts;
import java.io.PrintWriter;

/**
 * While open, says on standard error how far a bench got should the program be stopped (Ctrl-C, SIGTERM):
 * "trisect: interrupted after measuring 2 of 4 paths: their rows are printed, the others are missing".
 * The bench prints each row as it is measured, so what was measured is kept; this line says the table is
 * short. A shutdown hook, removed on close: a run that ends normally says nothing.
 */
final class InterruptNotice implements AutoCloseable {
    private final Thread hook;
    /** Written by the measuring thread, read by the hook. */
    private volatile int measured;

    /**
     * @param progress erased first, as it shares the terminal
     * @param total    how many rows the run measures
     * @param unit     what a row measures, singular ("path", "setting")
     */
    InterruptNotice(PrintWriter err, ProgressLine progress, int total, String unit) {
        hook = new Thread(() -> {
            progress.close();
            err.println("trisect: interrupted after measuring " + measured + " of " + Counts.of(total, unit)
                    + ": their rows are printed, the others are missing");
            err.flush();
        }, "trisect-bench-interrupted");
        Runtime.getRuntime().addShutdownHook(hook);
    }

    /** One more row measured and printed. */
    void measured() {
        measured++;
    }

    @Override
    public void close() {
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException e) {
            // The program is being stopped: the notice runs.
        }
    }
}
