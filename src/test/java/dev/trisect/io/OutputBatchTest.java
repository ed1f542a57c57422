package dev.trisect.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import dev.trisect.base.InputException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class OutputBatchTest {
    @TempDir
    Path dir;

    private List<String> listing() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void aFullDiskOnTheSecondOutputChangesNeither() throws IOException {
        Path a = dir.resolve("a.ppm");
        Path b = dir.resolve("b.pfm");
        Files.writeString(a, "old a");
        Files.writeString(b, "old b");
        try (OutputBatch batch = new OutputBatch()) {
            batch.write(a, out -> out.write("new a".getBytes(StandardCharsets.US_ASCII)));
            InputException e = assertThrows(InputException.class, () -> batch.write(b, out -> {
                out.write(new byte[100_000]);
                throw new IOException("No space left on device");
            }));
            assertEquals(b + ": cannot write: No space left on device", e.getMessage());
        }
        assertEquals("old a", Files.readString(a));
        assertEquals("old b", Files.readString(b));
        assertEquals(List.of("a.ppm", "b.pfm"), listing());
    }

    @Test
    void commitReplacesAllAndLeavesNoTemporaries() throws IOException {
        Path a = dir.resolve("a.ppm");
        Files.writeString(a, "old a");
        try (OutputBatch batch = new OutputBatch()) {
            batch.write(a, out -> out.write('A'));
            batch.write(dir.resolve("b.pfm"), out -> out.write('B'));
            assertEquals(List.of("a.ppm"), listing().stream().filter(n -> !n.startsWith(".")).toList(),
                    "nothing is visible before the commit");
            batch.commit();
        }
        assertEquals("A", Files.readString(a));
        assertEquals("B", Files.readString(dir.resolve("b.pfm")));
        assertEquals(List.of("a.ppm", "b.pfm"), listing());
    }

    @Test
    void theSameFileTwiceInOneBatchIsRefused() {
        try (OutputBatch batch = new OutputBatch()) {
            batch.write(dir.resolve("x.png"), out -> out.write(1));
            InputException e = assertThrows(InputException.class,
                    () -> batch.write(dir.resolve("sub/../x.png"), out -> out.write(2)));
            assertEquals(2, e.exitStatus());
        }
    }
}
