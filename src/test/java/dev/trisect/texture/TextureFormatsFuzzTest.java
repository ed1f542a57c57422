package dev.trisect.texture;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

/**
 * Jazzer fuzz target: every texture format. The first byte picks the file's extension (the format is
 * recognised from the content, except TGA, from the name); the rest is the file. Every input must give a
 * valid texture or an {@link dev.trisect.base.InputException} naming the file in one line; any other
 * exception, a hang or running out of memory is a finding. Seeds (one small valid file per format) and regression cases
 * are in {@code src/test/resources/dev/trisect/texture/TextureFormatsFuzzTestInputs}.
 */
class TextureFormatsFuzzTest {
    private static final String[] EXTENSIONS = {"png", "jpg", "bmp", "gif", "tga", "ppm", "pam"};

    @FuzzTest(maxDuration = "5m")
    void everyFormatGivesATextureOrAOneLineError(byte[] input) throws IOException {
        if (input.length == 0) {
            return;
        }
        String extension = EXTENSIONS[(input[0] & 0xFF) % EXTENSIONS.length];
        Path file = Files.createTempFile("trisect-fuzz", "." + extension);
        try {
            Files.write(file, Arrays.copyOfRange(input, 1, input.length));
            TextureReaderFuzzTest.readOrFailCleanly(file);
        } finally {
            Files.delete(file);
        }
    }
}
