package dev.trisect.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import dev.trisect.base.InputException;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

class PfmTest {
    private static final int W = 5;
    private static final int H = 3;
    private static final String HEADER = "PF\n5 3\n-1.0\n";

    @TempDir
    Path dir;

    /** A UV buffer where pixel (x, y) holds [s = x + 0.25, t = 10 y + 0.5, id = y * W + x + 1]. */
    private static float[] uvBuffer() {
        float[] uv = new float[3 * W * H];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int k = 3 * (y * W + x);
                uv[k] = x + 0.25f;
                uv[k + 1] = 10 * y + 0.5f;
                uv[k + 2] = y * W + x + 1;
            }
        }
        uv[4] = Float.NaN;
        uv[5] = Float.NEGATIVE_INFINITY;
        return uv;
    }

    @Test
    void writeThenReadGivesTheSameBuffer() {
        Path file = dir.resolve("uv.pfm");
        float[] uv = uvBuffer();

        Pfm.write(file, W, H, uv);
        Pfm.Image image = Pfm.read(file);

        assertEquals(W, image.width());
        assertEquals(H, image.height());
        assertEquals(3, image.channels());
        assertArrayEquals(uv, image.data());
    }

    /** A framebuffer's double UV output is written as the floats it rounds to, byte for byte. */
    @Test
    void doublesAreWrittenAsTheirRoundedFloats() throws IOException {
        float[] rounded = new float[3 * W * H];
        double[] precise = new double[3 * W * H];
        java.util.Random rnd = new java.util.Random(6);
        for (int i = 0; i < precise.length; i++) {
            precise[i] = i % 3 == 2 ? i / 3 + 1 : (rnd.nextDouble() - 0.3) * 5000;
            rounded[i] = (float) precise[i];
        }
        precise[7] = Double.NaN;
        rounded[7] = Float.NaN;
        Path fromFloats = dir.resolve("f.pfm");
        Path fromDoubles = dir.resolve("d.pfm");
        Pfm.write(fromFloats, W, H, rounded);
        try (OutputBatch batch = new OutputBatch()) {
            Pfm.write(batch, fromDoubles, W, H, precise);
            batch.commit();
        }
        assertArrayEquals(Files.readAllBytes(fromFloats), Files.readAllBytes(fromDoubles));
        assertThrows(IllegalArgumentException.class, () -> {
            try (OutputBatch batch = new OutputBatch()) {
                Pfm.write(batch, dir.resolve("x.pfm"), W, H, new double[3 * W * H - 1]);
            }
        });
    }

    @Test
    void fileLayoutIsLittleEndianBottomRowFirst() throws IOException {
        Path file = dir.resolve("uv.pfm");
        float[] uv = uvBuffer();

        Pfm.write(file, W, H, uv);

        byte[] bytes = Files.readAllBytes(file);
        String header = new String(bytes, 0, HEADER.length(), StandardCharsets.US_ASCII);
        assertEquals(HEADER, header);
        assertEquals(HEADER.length() + 4 * 3 * W * H, bytes.length);
        // The first float is the bottom-left pixel's s: x + 0.25 = 0.25 = 0x3E800000, stored low byte first.
        assertArrayEquals(new byte[] {0, 0, (byte) 0x80, 0x3E},
                java.util.Arrays.copyOfRange(bytes, HEADER.length(), HEADER.length() + 4));
        ByteBuffer data = ByteBuffer.wrap(bytes, HEADER.length(), bytes.length - HEADER.length())
                .slice().order(ByteOrder.LITTLE_ENDIAN);
        for (int fileRow = 0; fileRow < H; fileRow++) {
            int y = H - 1 - fileRow;
            for (int x = 0; x < W; x++) {
                for (int c = 0; c < 3; c++) {
                    float expected = uv[3 * (y * W + x) + c];
                    assertEquals(expected, data.getFloat(4 * (3 * (fileRow * W + x) + c)),
                            "pixel " + x + "," + y + " channel " + c);
                }
            }
        }
    }

    @Test
    void readsBigEndianWhenTheScaleIsPositive() {
        float[] top = {1, 2, 3, 4, 5, 6};
        float[] bottom = {-1.5f, 0.125f, 7, 1e30f, -0f, 9};
        Path file = write("be.pfm", "PF\n2 2\n1.0\n", ByteOrder.BIG_ENDIAN, bottom, top);

        Pfm.Image image = Pfm.read(file);

        assertEquals(2, image.width());
        assertEquals(2, image.height());
        assertArrayEquals(new float[] {1, 2, 3, 4, 5, 6, -1.5f, 0.125f, 7, 1e30f, -0f, 9}, image.data());
    }

    @ParameterizedTest
    @ValueSource(strings = {"Pf\n3 2\n-1.0\n", "Pf 3 2 -1\n", "Pf\n3\n2\n-0.5\n"})
    void readsOneChannelWithAnyHeaderWhitespace(String header) {
        Path file = write("gray.pfm", header, ByteOrder.LITTLE_ENDIAN, new float[] {4, 5, 6}, new float[] {1, 2, 3});

        Pfm.Image image = Pfm.read(file);

        assertEquals(1, image.channels());
        assertEquals(3, image.width());
        assertEquals(2, image.height());
        assertArrayEquals(new float[] {1, 2, 3, 4, 5, 6}, image.data());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "''                 | 0  | not a PFM file (it is empty)",
        "P6\\n2 2\\n255\\n  | 0  | not a PFM file (it does not start with PF or Pf)",
        "PFM\\n2 2\\n-1\\n  | 0  | not a PFM file (it does not start with PF or Pf)",
        "PF\\n0 2\\n-1.0\\n | 48 | bad PFM header: width '0' is not a positive integer",
        "PF\\n2 x\\n-1.0\\n | 48 | bad PFM header: height 'x' is not a positive integer",
        "PF\\n-2 2\\n-1\\n  | 48 | bad PFM header: width '-2' is not a positive integer",
        "PF\\n9999999999 1\\n-1\\n | 0 | bad PFM header: width '9999999999' is not a positive integer",
        "PF\\n2 2\\n0\\n    | 48 | bad PFM header: scale '0' is not a non-zero number",
        "PF\\n2 2\\nNaN\\n  | 48 | bad PFM header: scale 'NaN' is not a non-zero number",
        "PF\\n2 2\\n-1.0    | 0  | bad PFM header: the file ends in or before the scale",
        "PF\\n2 2           | 0  | bad PFM header: the file ends in or before the height",
        "PF\\n2 2\\n-1.0\\n | 10 | PFM data is short: 2x2 with 3 channels needs 48 bytes after the header, "
            + "the file has 10",
        "Pf\\n2 2\\n-1.0\\n | 20 | PFM data is too long: 2x2 with 1 channel needs 16 bytes after the header, "
            + "the file has 20",
        "PF\\n60000 60000\\n-1\\n | 0 | the image is 60000x60000 pixels; at most 16384 on a side is allowed",
    })
    void malformedFilesGiveOneLineMessages(String header, int dataBytes, String message) throws IOException {
        Path file = dir.resolve("bad.pfm");
        ByteArrayOutputStream content = new ByteArrayOutputStream();
        content.write(header.replace("\\n", "\n").getBytes(StandardCharsets.US_ASCII));
        content.write(new byte[dataBytes]);
        Files.write(file, content.toByteArray());

        InputException e = assertThrows(InputException.class, () -> Pfm.read(file));

        assertEquals(file + ": " + message, e.getMessage());
    }

    @Test
    void headerTokenTooLongIsMalformed() throws IOException {
        Path file = dir.resolve("long.pfm");
        Files.writeString(file, "PF\n" + "1".repeat(100) + " 2\n-1\n");
        InputException e = assertThrows(InputException.class, () -> Pfm.read(file));
        assertEquals(file + ": bad PFM header: the width is too long", e.getMessage());
    }

    @Test
    void unreadableAndUnwritablePathsAreReported() {
        Path missing = dir.resolve("missing.pfm");
        InputException read = assertThrows(InputException.class, () -> Pfm.read(missing));
        assertEquals(missing + ": cannot read: no such file", read.getMessage());

        InputException directory = assertThrows(InputException.class, () -> Pfm.read(dir));
        assertEquals(dir + ": cannot read: it is a directory", directory.getMessage());

        Path out = dir.resolve("nowhere").resolve("uv.pfm");
        InputException write = assertThrows(InputException.class, () -> Pfm.write(out, W, H, uvBuffer()));
        assertEquals(out + ": cannot write: no such directory " + out.getParent(), write.getMessage());
    }

    @Test
    void sizeMismatchIsAProgrammingError() {
        Path out = dir.resolve("uv.pfm");
        assertThrows(IllegalArgumentException.class, () -> Pfm.write(out, W, H, new float[W * H]));
    }

    /** A PFM file with the given header and rows (as stored: bottom row first) in the given order. */
    private Path write(String name, String header, ByteOrder order, float[]... rows) {
        try {
            ByteArrayOutputStream content = new ByteArrayOutputStream();
            content.write(header.getBytes(StandardCharsets.US_ASCII));
            for (float[] row : rows) {
                ByteBuffer bytes = ByteBuffer.allocate(4 * row.length).order(order);
                bytes.asFloatBuffer().put(row);
                content.write(bytes.array());
            }
            Path file = dir.resolve(name);
            Files.write(file, content.toByteArray());
            return file;
        } catch (IOException e) {
            throw new AssertionError(e);
        }
    }
}
