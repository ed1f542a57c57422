package dev.trisect.texture;

import static dev.trisect.texture.TestImages.write;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.base.InputException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Damaged files in every format, named with the format's extension: cut short at many lengths, with
 * random bytes changed, and random bytes after the magic number. Each must give a valid texture or an
 * InputException naming the file, quickly; any other exception or a hang fails the test.
 */
@org.junit.jupiter.api.Timeout(300) // a guard against hangs: no damaged file may make the reader loop
class TextureReaderFuzzTest {
    private static final int CUTS = 40;
    private static final int MUTANTS = 200;
    private static final int GARBAGE = 20;

    @TempDir
    Path dir;

    /** A valid seed file per format and per reading path (TGA raw, run-length, colour-mapped and tiny). */
    static List<Arguments> seeds() {
        List<Arguments> seeds = new ArrayList<>();
        TextureReaderErrorsTest.validFiles().forEach(arguments -> {
            Object[] values = arguments.get();
            seeds.add(Arguments.of(values[1], values[2]));
        });
        seeds.add(Arguments.of("run.tga", TestImages.concat(TestImages.tgaHeader(10, 8, 2, 24, 0),
                TestImages.bytes(0x87, 255, 0, 0, 0x03, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 0x83, 9, 9, 9))));
        byte[] colourMapped = TestImages.tgaHeader(1, 8, 4, 8, 0);
        colourMapped[1] = 1; // a colour map of 4 entries, 24 bits each
        colourMapped[5] = 4;
        colourMapped[7] = 24;
        byte[] indices = new byte[8 * 4];
        for (int i = 0; i < indices.length; i++) {
            indices[i] = (byte) (i % 4);
        }
        seeds.add(Arguments.of("mapped.tga", TestImages.concat(colourMapped,
                TestImages.bytes(0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255), indices)));
        seeds.add(Arguments.of("tiny.tga", TestImages.concat(TestImages.tgaHeader(10, 2, 2, 32, 0x28),
                TestImages.bytes(0x83, 1, 2, 3, 4))));
        return seeds;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("seeds")
    void damagedFilesGiveATextureOrAnInputException(String fileName, byte[] valid) {
        Random random = new Random(fileName.hashCode());
        List<byte[]> cases = new ArrayList<>();
        for (int i = 0; i < CUTS; i++) {
            cases.add(Arrays.copyOf(valid, (int) ((long) valid.length * i / CUTS)));
        }
        for (int i = 0; i < MUTANTS; i++) {
            byte[] mutant = valid.clone();
            // Mostly early bytes, where the headers are, and a few anywhere.
            int changes = 1 + random.nextInt(4);
            for (int c = 0; c < changes; c++) {
                int limit = random.nextBoolean() ? Math.min(64, mutant.length) : mutant.length;
                mutant[random.nextInt(limit)] = (byte) random.nextInt(256);
            }
            cases.add(mutant);
        }
        for (int i = 0; i < GARBAGE; i++) {
            byte[] garbage = new byte[random.nextInt(300)];
            random.nextBytes(garbage);
            byte[] withMagic = TestImages.concat(Arrays.copyOf(valid, 3), garbage);
            cases.add(withMagic);
        }
        for (int i = 0; i < cases.size(); i++) {
            Path file = write(dir, i + "-" + fileName, cases.get(i));
            readOrFailCleanly(file);
        }
    }

    /** Reads {@code file}: a valid texture or a one-line InputException naming it; nothing else. */
    static void readOrFailCleanly(Path file) {
        try {
            Texture texture = TextureReader.read(file);
            assertTrue(texture.width() >= 1 && texture.width() <= Texture.MAX_SIDE, "width");
            assertTrue(texture.height() >= 1 && texture.height() <= Texture.MAX_SIDE, "height");
            assertEquals((long) texture.width() * texture.height(), texture.argb().length, "texel count");
        } catch (InputException e) {
            assertTrue(e.getMessage().startsWith(file + ": "), e.getMessage());
            assertFalse(e.getMessage().contains("\n"), e.getMessage());
        }
    }
}
