package dev.trisect.io;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Test helper run in its own JVM: starts writing {@code args[0]} all-or-nothing, creates the marker
 * file {@code args[1]} once its temporary file has data, then waits to be killed.
 */
public final class HoldOutputs {
    private HoldOutputs() {
    }

    public static void main(String[] args) {
        OutputFiles.writeAtomically(Path.of(args[0]), stream -> {
            stream.write(new byte[1 << 20]);
            stream.flush();
            Files.createFile(Path.of(args[1]));
            try {
                Thread.sleep(600_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
    }
}
