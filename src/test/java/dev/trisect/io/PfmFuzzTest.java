package dev.trisect.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.junit.FuzzTest;
import dev.trisect.base.InputException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Jazzer fuzz target: the PFM reader (UV outputs given to {@code diff}). Every input must give an
 * image whose data matches its header or an {@link InputException} naming the file in one line.
 * Seeds and regression cases are in {@code src/test/resources/dev/trisect/io/PfmFuzzTestInputs}.
 */
class PfmFuzzTest {
    @FuzzTest(maxDuration = "5m")
    void pfmGivesAnImageOrAOneLineError(byte[] input) throws IOException {
        Path file = Files.createTempFile("trisect-fuzz", ".pfm");
        try {
            Files.write(file, input);
            try {
                Pfm.Image image = Pfm.read(file);
                assertTrue(image.channels() == 1 || image.channels() == 3, "channels");
                assertEquals((long) image.channels() * image.width() * image.height(), image.data().length);
            } catch (InputException e) {
                assertTrue(e.getMessage().startsWith(file + ": "), e.getMessage());
                assertFalse(e.getMessage().contains("\n"), e.getMessage());
            }
        } finally {
            Files.delete(file);
        }
    }
}
