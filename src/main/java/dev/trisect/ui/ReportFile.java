package dev.trisect.ui;

import java.nio.file.Path;

/**
 * Where {@code demo --soak S --report FILE} writes its report: opened, and so checked, before the soak,
 * and written all or nothing after it, as every output of the program is. The launcher supplies it
 * (the demo uses only what a library user can, and the writer is the command line's).
 */
public interface ReportFile extends AutoCloseable {
    /** Opens a report file. */
    @FunctionalInterface
    interface Opener {
        /**
         * Checks now that {@code file} can be written.
         *
         * @throws dev.trisect.base.InputException "{@code file}: cannot write: reason"
         */
        ReportFile open(Path file);
    }

    /**
     * Replaces the file with {@code text}, whole, or leaves the old file as it was.
     *
     * @throws dev.trisect.base.InputException "{@code file}: cannot write: reason"
     */
    void write(String text);

    /** Gives up the file if it was not written; nothing visible changes then. */
    @Override
    void close();
}
