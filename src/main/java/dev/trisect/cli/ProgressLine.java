package dev.trisect.cli;

import dev.trisect.perf.FrameBench;
import java.io.PrintWriter;

/**
 * A progress line on standard error that rewrites itself ("bench: tessellated 120/300 frames"), shown
 * only when the program runs in a terminal, so that redirected output and logs stay clean. Updated at
 * most every 100 ms; closing erases it.
 */
final class ProgressLine implements AutoCloseable {
    private static final long INTERVAL_NANOS = 100_000_000L;

    private final PrintWriter err;
    private final boolean active;
    private long lastPrinted;
    private int width;

    ProgressLine(PrintWriter err, boolean active) {
        this.err = err;
        this.active = active;
    }

    /** A progress line that shows when standard input and output are a terminal ({@link System#console()}). */
    static ProgressLine forTerminal(PrintWriter err) {
        return new ProgressLine(err, System.console() != null);
    }

    /** Progress of one named task, to pass to {@link FrameBench}. */
    FrameBench.Progress task(String name) {
        if (!active) {
            return FrameBench.Progress.NONE;
        }
        return (done, total) -> {
            long now = System.nanoTime();
            if (done < total && now - lastPrinted < INTERVAL_NANOS) {
                return;
            }
            lastPrinted = now;
            show("bench: " + name + " " + done + "/" + total + " frames");
        };
    }

    private void show(String text) {
        StringBuilder line = new StringBuilder("\r").append(text);
        for (int i = text.length(); i < width; i++) {
            line.append(' ');
        }
        width = text.length();
        err.print(line);
        err.flush();
    }

    /** Erases the line. */
    @Override
    public void close() {
        if (active && width > 0) {
            show("");
            err.print('\r');
            err.flush();
            width = 0;
        }
    }
}
