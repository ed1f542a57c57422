package dev.trisect.io;

import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Test support: a full disk injected into {@link OutputBatch}'s writes, for tests outside this package.
 * Tests run one at a time, so one process-wide switch is enough; always {@link #clear} it.
 */
public final class Faults {
    private Faults() {
    }

    /**
     * From now on the {@code n}-th output file written (1 for the first) fails at its first byte with
     * "No space left on device", as a full disk does; the others are written normally.
     *
     * @return the count of output files written so far, for checking how many there were
     */
    public static AtomicInteger fullDiskAt(int n) {
        AtomicInteger count = new AtomicInteger();
        OutputBatch.faults = stream -> count.incrementAndGet() != n ? stream : new FilterOutputStream(stream) {
            @Override
            public void write(int b) throws IOException {
                throw new IOException("No space left on device");
            }

            @Override
            public void write(byte[] b, int off, int len) throws IOException {
                throw new IOException("No space left on device");
            }
        };
        return count;
    }

    /** Writes work again. */
    public static void clear() {
        OutputBatch.faults = null;
    }
}
