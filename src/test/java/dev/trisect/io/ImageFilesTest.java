package dev.trisect.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import dev.trisect.base.InputException;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class ImageFilesTest {
    private static final int W = 7;
    private static final int H = 5;

    @TempDir
    Path dir;

    /** Distinct colours with all sorts of alpha, which the files do not keep. */
    private static int[] testImage() {
        int[] argb = new int[W * H];
        for (int i = 0; i < argb.length; i++) {
            argb[i] = (i * 0x9E3779B1) ^ (i << 5);
        }
        argb[0] = 0x00000000;
        argb[1] = 0xFFFFFFFF;
        argb[2] = 0x80FF0000;
        return argb;
    }

    @ParameterizedTest
    @ValueSource(strings = {"out.png", "OUT.PNG"})
    void pngRoundTripKeepsRgbAndRowOrder(String name) throws IOException {
        Path out = dir.resolve(name);
        int[] argb = testImage();
        int[] before = argb.clone();

        ImageFiles.write(out, W, H, argb);

        assertArrayEquals(before, argb, "the caller's pixels are not modified");
        BufferedImage image = ImageIO.read(out.toFile());
        assertEquals(W, image.getWidth());
        assertEquals(H, image.getHeight());
        assertFalse(image.getColorModel().hasAlpha());
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                assertEquals(0xFF000000 | argb[y * W + x], image.getRGB(x, y), "pixel " + x + "," + y);
            }
        }
        assertEquals(List.of(out.getFileName()), listing());
    }

    @Test
    void ppmIsBinaryP6WithRowZeroFirst() throws IOException {
        Path out = dir.resolve("out.ppm");
        int[] argb = testImage();

        ImageFiles.write(out, W, H, argb);

        byte[] bytes = Files.readAllBytes(out);
        byte[] header = ("P6\n" + W + " " + H + "\n255\n").getBytes(StandardCharsets.US_ASCII);
        assertEquals(header.length + 3 * W * H, bytes.length);
        for (int i = 0; i < header.length; i++) {
            assertEquals(header[i], bytes[i], "header byte " + i);
        }
        for (int p = 0; p < W * H; p++) {
            int at = header.length + 3 * p;
            int rgb = (bytes[at] & 0xFF) << 16 | (bytes[at + 1] & 0xFF) << 8 | bytes[at + 2] & 0xFF;
            assertEquals(argb[p] & 0xFFFFFF, rgb, "pixel " + p);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"out.xyz", "out", "out.png.txt", "out.jpg"})
    void otherExtensionsAreAUsageError(String name) throws IOException {
        Path out = dir.resolve(name);
        InputException e = assertThrows(InputException.class, () -> ImageFiles.write(out, W, H, testImage()));
        assertEquals(out + ": unsupported output format (use .png, .ppm or .pam)", e.getMessage());
        assertEquals(InputException.Kind.USAGE, e.kind());
        assertEquals(List.of(), listing());
    }

    @ParameterizedTest
    @ValueSource(strings = {"out.png", "out.ppm", "out.pam"})
    void missingDirectoryIsReported(String name) throws IOException {
        Path out = dir.resolve("missing").resolve(name);
        InputException e = assertThrows(InputException.class, () -> ImageFiles.write(out, W, H, testImage()));
        assertEquals(out + ": cannot write: no such directory " + out.toAbsolutePath().getParent(), e.getMessage());
        assertEquals(InputException.Kind.UNREADABLE, e.kind());
        assertEquals(List.of(), listing());
    }

    @Test
    void directoryGivenIsReportedAndKept() throws IOException {
        Path out = Files.createDirectory(dir.resolve("shots.png"));
        Files.writeString(out.resolve("keep.txt"), "x");
        InputException e = assertThrows(InputException.class, () -> ImageFiles.write(out, W, H, testImage()));
        assertEquals(out + ": cannot write: it is a directory", e.getMessage());
        assertTrue(Files.isRegularFile(out.resolve("keep.txt")));
        assertEquals(List.of(out.getFileName()), listing());
    }

    @Test
    void readOnlyDirectoryIsReported() throws IOException {
        assumeTrue(FileSystems.getDefault().supportedFileAttributeViews().contains("posix"), "needs POSIX permissions");
        Path locked = Files.createDirectory(dir.resolve("locked"));
        Files.setPosixFilePermissions(locked, PosixFilePermissions.fromString("r-xr-xr-x"));
        try {
            // Root ignores permissions: nothing to test then.
            assumeFalse(Files.isWritable(locked), "running with permission to write anywhere");
            Path out = locked.resolve("out.png");
            InputException e = assertThrows(InputException.class, () -> ImageFiles.write(out, W, H, testImage()));
            assertEquals(out + ": cannot write: permission denied", e.getMessage());
            assertFalse(Files.exists(out));
        } finally {
            Files.setPosixFilePermissions(locked, PosixFilePermissions.fromString("rwxr-xr-x"));
        }
    }

    @Test
    void existingFileIsReplacedWhole() throws IOException {
        Path out = dir.resolve("out.ppm");
        Files.write(out, new byte[100_000]);

        ImageFiles.write(out, W, H, testImage());

        assertTrue(new String(Files.readAllBytes(out), StandardCharsets.US_ASCII).startsWith("P6\n7 5\n255\n"));
        assertEquals(11 + 3 * W * H, Files.size(out));
        assertEquals(List.of(out.getFileName()), listing());
    }

    @Test
    void failureWhileWritingKeepsTheExistingFileAndLeavesNoTemporary() throws IOException {
        Path out = dir.resolve("out.png");
        Files.writeString(out, "the old picture");

        InputException e = assertThrows(InputException.class, () -> OutputFiles.writeAtomically(out, stream -> {
            stream.write(new byte[200_000]);
            throw new IOException("No space left on device");
        }));
        assertEquals(out + ": cannot write: No space left on device", e.getMessage());
        assertThrows(IllegalStateException.class, () -> OutputFiles.writeAtomically(out, stream -> {
            stream.write(new byte[10]);
            throw new IllegalStateException("a bug while encoding");
        }));

        assertEquals("the old picture", Files.readString(out));
        assertEquals(List.of(out.getFileName()), listing());
    }

    @Test
    void sizeMismatchIsAProgrammingError() {
        Path out = dir.resolve("out.png");
        assertThrows(IllegalArgumentException.class, () -> ImageFiles.write(out, W, H, new int[W * H - 1]));
        assertThrows(IllegalArgumentException.class, () -> ImageFiles.write(out, 0, 0, new int[0]));
    }

    private List<Path> listing() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(Path::getFileName).sorted().toList();
        }
    }
}
