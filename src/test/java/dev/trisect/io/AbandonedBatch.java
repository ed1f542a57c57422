package dev.trisect.io;

import dev.trisect.base.InputException;
import java.nio.file.Path;

/**
 * Test helper run in its own JVM (it stops the process's batches for good): a batch in the middle of a
 * command when the shutdown hook runs. Reserves and writes {@code args[0]}, runs the hook's cleanup as
 * SIGTERM would, then tries to go on, printing what each step threw, one line each.
 */
public final class AbandonedBatch {
    private AbandonedBatch() {
    }

    public static void main(String[] args) {
        Path out = Path.of(args[0]);
        try (OutputBatch batch = new OutputBatch()) {
            batch.reserve(out);
            batch.writeText(out, "NEW");
            OutputBatch.abandonAll();
            for (Runnable step : new Runnable[] {() -> batch.writeText(out.resolveSibling("other.ppm"), "x"),
                () -> batch.reserve(out.resolveSibling("third.ppm")), batch::commit}) {
                try {
                    step.run();
                    System.out.println("no exception");
                } catch (InputException e) {
                    System.out.println(e.getMessage());
                } catch (RuntimeException e) {
                    System.out.println("internal error: " + e);
                }
            }
        }
    }
}
