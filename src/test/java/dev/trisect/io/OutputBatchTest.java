package dev.trisect.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.base.InputException;
import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;
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

    @Test
    void aLinkIsWrittenThroughAndAReplacedFileKeepsItsPermissions() throws IOException {
        Path real = dir.resolve("real.png");
        Files.writeString(real, "old");
        Files.setPosixFilePermissions(real, PosixFilePermissions.fromString("rw-------"));
        Path link = Files.createSymbolicLink(dir.resolve("link.png"), Path.of("real.png"));
        OutputFiles.writeAtomically(link, out -> out.write('N'));
        assertTrue(Files.isSymbolicLink(link), "the link stays a link");
        assertEquals("N", Files.readString(real), "the file it names has the new content");
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(real)));
        assertEquals(List.of("link.png", "real.png"), listing());
    }

    @Test
    void staleTemporariesOfOurPatternAreCleanedAndThoseInUseOrOfOtherNamesAreNot() throws IOException {
        List<String> stale = List.of(".x.png.0123456789ab.tmp", ".y.PFM.fedcba987654.tmp", ".e.obj.00000000000a.tmp");
        List<String> kept = List.of(".x.png.0123.tmp", ".notes.txt.0123456789ab.tmp", "x.png.0123456789ab.tmp",
                ".x.png.0123456789ab.old");
        for (String n : stale) {
            Files.writeString(dir.resolve(n), "left by a killed run");
        }
        for (String n : kept) {
            Files.writeString(dir.resolve(n), "not ours");
        }
        Path inUse = dir.resolve(".z.ppm.aaaaaaaaaaaa.tmp");
        try (FileChannel held = FileChannel.open(inUse, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
             FileLock lock = held.lock()) {
            OutputFiles.writeAtomically(dir.resolve("new.png"), out -> out.write(1));
        }
        List<String> expected = new java.util.ArrayList<>(kept);
        expected.addAll(List.of(inUse.getFileName().toString(), "new.png"));
        assertEquals(expected.stream().sorted().toList(), listing());
    }

    @Test
    void aMissingFolderIsReportedWhenTheOutputIsReservedBeforeTheWork() {
        Path out = dir.resolve("no/x.png");
        try (OutputBatch batch = new OutputBatch()) {
            InputException e = assertThrows(InputException.class, () -> batch.reserve(out));
            assertEquals(out + ": cannot write: no such directory " + dir.resolve("no"), e.getMessage());
        }
    }

    @Test
    void aReservedOutputIsWrittenIntoItsTemporaryAndAnUnwrittenOneIsDropped() throws IOException {
        try (OutputBatch batch = new OutputBatch()) {
            batch.reserve(dir.resolve("a.ppm"));
            batch.reserve(dir.resolve("b.ppm"));
            assertEquals(2, listing().size(), "two temporary files, made at once: " + listing());
            batch.write(dir.resolve("a.ppm"), out -> out.write('A'));
            batch.commit();
        }
        assertEquals(List.of("a.ppm"), listing());
        assertEquals("A", Files.readString(dir.resolve("a.ppm")));
    }

    @Test
    void aFolderThatCannotBeCreatedGivesItsReason() throws IOException {
        Files.writeString(dir.resolve("file"), "");
        InputException e = assertThrows(InputException.class, () -> OutputBatch.createFolders(dir.resolve("file/sub")));
        assertEquals("cannot create the directory " + dir.resolve("file/sub") + ": Not a directory", e.getMessage());
    }

    /**
     * A FIFO (or a device or socket) named as an output was replaced by a regular file, the node gone
     * (found by the command-line fault probe); now it is refused before any work, through a link too,
     * and left as it was.
     */
    @Test
    void aTargetThatIsNotARegularFileIsRefusedAndKept() throws Exception {
        Path fifo = dir.resolve("p.png");
        Process mkfifo;
        try {
            mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).start();
        } catch (IOException e) {
            org.junit.jupiter.api.Assumptions.abort("needs mkfifo");
            return;
        }
        org.junit.jupiter.api.Assumptions.assumeTrue(mkfifo.waitFor() == 0, "mkfifo made a FIFO");
        Path link = Files.createSymbolicLink(dir.resolve("link.png"), fifo.getFileName());
        for (Path out : List.of(fifo, link)) {
            try (OutputBatch batch = new OutputBatch()) {
                InputException e = assertThrows(InputException.class, () -> batch.reserve(out));
                assertEquals(out + ": cannot write: it is not a regular file (a FIFO, device or socket), which the "
                        + "output would replace", e.getMessage());
            }
        }
        assertTrue(Files.exists(fifo) && !Files.isRegularFile(fifo) && !Files.isDirectory(fifo), "the FIFO stays");
        try (var files = Files.list(dir)) {
            assertEquals(List.of("link.png", "p.png"), files.map(p -> p.getFileName().toString()).sorted().toList());
        }
    }
}
