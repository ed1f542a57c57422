package dev.trisect.cli;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;

/** Test support: runs the command line in-process and keeps what it printed. */
record CliRun(int status, String out, String err) {

    static CliRun of(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Cli.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
        return new CliRun(status, out.toString(), err.toString());
    }

    /**
     * Runs {@code args} with a standard output that fails as a full disk does: every write throws
     * "No space left on device", as writing to /dev/full does.
     */
    static CliRun withFullStdout(String... args) {
        return withFailingStdout("No space left on device", args);
    }

    /** Runs {@code args} with a standard output whose every write throws with {@code reason}. */
    static CliRun withFailingStdout(String reason, String... args) {
        StringWriter err = new StringWriter();
        OutputWriter out = OutputWriter.over(new OutputStream() {
            @Override
            public void write(int b) throws IOException {
                throw new IOException(reason);
            }
        });
        int status = Cli.run(out, new PrintWriter(err, true), args);
        return new CliRun(status, "", err.toString());
    }

    /** Standard error as one line, or fails if it is more (or a stack trace). */
    String errLine() {
        String e = err.strip();
        if (e.contains("\n") || e.contains("\tat ") || e.contains("Exception")) {
            throw new AssertionError("expected one clean line on stderr, got:\n" + err);
        }
        return e;
    }
}
