package dev.trisect.cli;

import dev.trisect.pipeline.FrameRenderer;
import java.io.PrintWriter;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** Options every command has, and its output streams. */
final class CommonOptions {
    @Spec(Spec.Target.MIXEE)
    CommandSpec spec;

    /** Most threads a renderer may be given: the renderer's own limit. */
    static final int MAX_THREADS = FrameRenderer.MAX_THREADS;

    /** Render threads, or null for one per processor. */
    Integer threads;

    /** Checked as it is parsed, so every command refuses a bad count the same way (exit status 2). */
    @Option(names = "--threads", paramLabel = "N",
            description = "Render threads (default: one per processor, here ${sys:trisect.processors}).")
    void threads(int n) {
        if (n < 1 || n > MAX_THREADS) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    "--threads must be between 1 and " + MAX_THREADS + ", got " + n);
        }
        threads = n;
    }

    @Option(names = "--verbose", description = "On an error, also print the stack trace.")
    boolean verbose;

    PrintWriter out() {
        return spec.commandLine().getOut();
    }

    PrintWriter err() {
        return spec.commandLine().getErr();
    }

    /** A remark for the user on standard error, prefixed so it is not mistaken for output. */
    void note(String message) {
        err().println("trisect: note: " + Cli.oneLine(message));
        err().flush();
    }

    FrameRenderer renderer() {
        int n = threads == null ? FrameRenderer.defaultThreads() : threads;
        return new FrameRenderer(n);
    }
}
