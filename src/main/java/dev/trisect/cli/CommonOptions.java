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

    @Option(names = "--threads", paramLabel = "N",
            description = "Render threads (default: one per processor, here ${sys:trisect.processors}).")
    Integer threads;

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
        err().println("trisect: note: " + message);
        err().flush();
    }

    FrameRenderer renderer() {
        int n = threads == null ? Runtime.getRuntime().availableProcessors() : threads;
        if (n < 1 || n > 256) {
            throw dev.trisect.base.InputException.usage("--threads must be between 1 and 256, got " + n);
        }
        return new FrameRenderer(n);
    }
}
