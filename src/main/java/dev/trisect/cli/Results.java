package dev.trisect.cli;

import dev.trisect.base.InputException;
import dev.trisect.io.OutputBatch;
import java.io.PrintWriter;
import java.util.List;
import java.util.function.Function;

/**
 * How a command hands over what it computed: its files in one {@link OutputBatch} and its lines on
 * standard output, in the order that loses least when a write fails (docs/reading-limits.md,
 * "Standard output"):
 * <ol>
 * <li>the files are written to their temporary files, nothing visible yet;</li>
 * <li>the lines are printed, even when a file failed, so that what was computed is not lost (a sweep's
 *     table still appears when its plot cannot be written);</li>
 * <li>only when both succeeded are the files renamed into place; otherwise every old output is left as
 *     it was and the first failure ends the command with its reason and exit status 1.</li>
 * </ol>
 */
final class Results {
    /** Writes a command's files into the batch. */
    @FunctionalInterface
    interface Files {
        void write(OutputBatch batch);
    }

    private Results() {
    }

    /** Writes {@code files} and prints {@code lines} as the class comment says, then commits the batch. */
    static void deliver(PrintWriter out, OutputBatch batch, Files files, List<String> lines) {
        deliver(out, batch, files, ok -> lines);
    }

    /**
     * As {@link #deliver(PrintWriter, OutputBatch, Files, List)}, with lines that depend on whether the
     * files were written (true) or failed (false).
     */
    static void deliver(PrintWriter out, OutputBatch batch, Files files, Function<Boolean, List<String>> lines) {
        InputException failed = null;
        try {
            files.write(batch);
        } catch (InputException e) {
            failed = e;
        }
        String stdout = printed(out, lines.apply(failed == null));
        if (failed != null) {
            throw failed;
        }
        if (stdout != null) {
            throw new InputException(stdout);
        }
        batch.commit();
    }

    /** Prints {@code lines}; throws the one-line reason when standard output cannot take them. */
    static void print(PrintWriter out, List<String> lines) {
        String failure = printed(out, lines);
        if (failure != null) {
            throw new InputException(failure);
        }
    }

    /** Prints and flushes {@code lines}; returns null, or the message when the writer failed. */
    private static String printed(PrintWriter out, List<String> lines) {
        for (String line : lines) {
            out.println(line);
        }
        out.flush();
        String reason = OutputWriter.failure(out);
        return reason == null ? null : cannotWrite(reason);
    }

    /** The message for a failed standard output. */
    static String cannotWrite(String reason) {
        return "cannot write to standard output: " + reason;
    }
}
