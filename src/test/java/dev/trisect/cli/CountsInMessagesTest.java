package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A count of one reads in the singular wherever the command line prints a count: {@code --frames 1},
 * {@code --threads 1} and an OBJ of one triangle and one material are ordinary, and "1 frames" reads as
 * a slip (found by the command-line trial: bench's "1 frames after 0 warm-up", export's "1 materials").
 */
class CountsInMessagesTest {
    @TempDir
    Path dir;

    private Path oneTriangle(String nanCorner) throws IOException {
        Path obj = dir.resolve("one.obj");
        Files.writeString(obj, "v 0 0 0\nv 1 0 0\nv 0 1 " + nanCorner + "\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
        Path t = dir.resolve("t.ppm");
        byte[] header = "P6\n1 1\n255\n".getBytes(StandardCharsets.US_ASCII);
        byte[] data = java.util.Arrays.copyOf(header, header.length + 3);
        Files.write(t, data);
        return obj;
    }

    @Test
    void benchHeaderSaysFrameThreadAndTriangleInTheSingular() throws IOException {
        Path obj = oneTriangle("0");
        CliRun r = CliRun.of("bench", "--obj", obj.toString(), "--texture", dir.resolve("t.ppm").toString(),
                "--size", "16x12", "--frames", "1", "--warmup", "1", "--threads", "1", "--modes", "affine");
        assertEquals(0, r.status(), r.err());
        String header = r.out().lines().findFirst().orElseThrow();
        assertTrue(header.contains("1 triangle, 1 thread, nearest filter, 1 frame after 1 warm-up frame"), header);
        CliRun none = CliRun.of("bench", "--scene", "floor", "--size", "16x12", "--frames", "2", "--warmup", "0",
                "--threads", "2", "--modes", "affine");
        assertEquals(0, none.status(), none.err());
        assertTrue(none.out().contains("2 threads, nearest filter, 2 frames after 0 warm-up frames"), none.out());
    }

    @Test
    void exportSummarySaysTriangleAndMaterialInTheSingular() throws IOException {
        Path obj = oneTriangle("0");
        CliRun r = CliRun.of("export", "--obj", obj.toString(), "--texture", dir.resolve("t.ppm").toString(),
                "--to", dir.resolve("out/e.obj").toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("(1 triangle, 1 material: ["), r.out());
    }

    @Test
    void skippedTriangleNoteSaysTriangleInTheSingular() throws IOException {
        Path obj = oneTriangle("nan");
        CliRun r = CliRun.of("render", "--obj", obj.toString(), "--texture", dir.resolve("t.ppm").toString(),
                "--size", "16x12", "--out", dir.resolve("o.png").toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(r.err().contains("note: 1 of 1 triangle skipped:"), r.err());
    }

    @Test
    void aTruncatedTextureSaysByteInTheSingular() throws IOException {
        // A TGA header of one 8-bit gray texel, and no pixel data: one byte is missing.
        Path tga = dir.resolve("g.tga");
        byte[] header = new byte[18];
        header[2] = 3;
        header[12] = 1;
        header[14] = 1;
        header[16] = 8;
        Files.write(tga, header);
        Path obj = oneTriangle("0");
        CliRun r = CliRun.of("render", "--obj", obj.toString(), "--texture", tga.toString(), "--size", "16x12",
                "--out", dir.resolve("o.png").toString());
        assertEquals(1, r.status(), r.err());
        assertTrue(r.errLine().contains("the pixel data needs at least 1 byte, the file has 0"), r.err());
    }
}
