package dev.trisect.texture;

import static dev.trisect.texture.TestImages.assertTexels;
import static dev.trisect.texture.TestImages.concat;
import static dev.trisect.texture.TestImages.pam;
import static dev.trisect.texture.TestImages.plain;
import static dev.trisect.texture.TestImages.ppm;
import static dev.trisect.texture.TestImages.write;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The grey and bitmap Netpbm textures beside the colour ones: binary PGM ({@code P5}) and PBM
 * ({@code P4}), and PAM's {@code GRAYSCALE}, {@code BLACKANDWHITE} and their {@code _ALPHA} forms. The
 * plain P1 and P2 were read while their binary forms, which ImageMagick and Netpbm's own programs write
 * for a grey image, were refused as unsupported (found by the command-line fault probe).
 */
class GreyNetpbmTest {
    @TempDir
    Path dir;

    private Texture read(String fileName, byte[] bytes) {
        return TextureReader.read(write(dir, fileName, bytes));
    }

    private String failure(String fileName, byte[] bytes) {
        return TextureReaderErrorsTest.failureMessage(write(dir, fileName, bytes));
    }

    private static int grey(int g) {
        return 0xFF000000 | g * 0x010101;
    }

    @Test
    void binaryPgmReadsAsThePlainOneDoes() {
        int[] samples = {0, 50, 100, 255, 7, 128};
        Texture binary = read("b.pgm", ppm("P5\n3 2\n255\n", 255, samples));
        Texture ascii = read("a.pgm", plain("P2\n3 2\n255\n", samples));
        assertTexels(new int[] {grey(0), grey(50), grey(100), grey(255), grey(7), grey(128)}, 3, 2, binary);
        assertArrayEquals(ascii.argb(), binary.argb());
        // 16 bits a sample, big-endian, scaled to 8 bits as the colour formats are.
        assertTexels(new int[] {grey(0), grey(128), grey(255)}, 3, 1, read("w.pgm", ppm("P5\n3 1\n1000\n", 1000,
                0, 502, 1000)));
    }

    /** Rows are packed 8 texels a byte, the first in the high bit, each row padded to whole bytes; 1 is black. */
    @Test
    void binaryPbmReadsAsThePlainOneDoes() {
        String bits = "1 0 1 1 0 0 0 0 1 1\n0 1 0 0 0 0 0 0 0 1\n";
        byte[] packed = concat("P4\n10 2\n".getBytes(StandardCharsets.US_ASCII),
                new byte[] {(byte) 0b1011_0000, (byte) 0b1100_0000, (byte) 0b0100_0000, (byte) 0b0100_0000});
        Texture binary = read("b.pbm", packed);
        Texture ascii = read("a.pbm", ("P1\n10 2\n" + bits).getBytes(StandardCharsets.US_ASCII));
        int k = 0xFF000000;
        int w = 0xFFFFFFFF;
        assertTexels(new int[] {k, w, k, k, w, w, w, w, k, k, w, k, w, w, w, w, w, w, w, k}, 10, 2, binary);
        assertArrayEquals(ascii.argb(), binary.argb());
    }

    @Test
    void pamGreyTypesWithAndWithoutAlpha() {
        assertTexels(new int[] {grey(10), grey(200)}, 2, 1,
                read("g.pam", pam("WIDTH 2\nHEIGHT 1\nDEPTH 1\nMAXVAL 255\nTUPLTYPE GRAYSCALE\n", 1, 10, 200)));
        assertTexels(new int[] {0x800A0A0A, 0x00C8C8C8}, 2, 1,
                read("ga.pam", pam("WIDTH 2\nHEIGHT 1\nDEPTH 2\nMAXVAL 255\nTUPLTYPE GRAYSCALE_ALPHA\n", 1,
                        10, 128, 200, 0)));
        assertTexels(new int[] {0xFF808080, 0xFFFFFFFF}, 2, 1,
                read("g16.pam", pam("WIDTH 2\nHEIGHT 1\nDEPTH 1\nMAXVAL 65535\nTUPLTYPE GRAYSCALE\n", 2, 32896, 65535)));
        // Without a TUPLTYPE, DEPTH 1 and 2 are grey, as 3 and 4 are RGB and RGB_ALPHA.
        assertTexels(new int[] {0x800A0A0A}, 1, 1, read("d2.pam", pam("WIDTH 1\nHEIGHT 1\nDEPTH 2\nMAXVAL 255\n", 1,
                10, 128)));
    }

    /** PAM's bitmap is the other way round from PBM's: 0 black, 1 white (the PAM specification). */
    @Test
    void pamBlackAndWhiteIsZeroBlackOneWhite() {
        assertTexels(new int[] {0xFF000000, 0xFFFFFFFF}, 2, 1,
                read("bw.pam", pam("WIDTH 2\nHEIGHT 1\nDEPTH 1\nMAXVAL 1\nTUPLTYPE BLACKANDWHITE\n", 1, 0, 1)));
        assertTexels(new int[] {0x00FFFFFF, 0xFF000000}, 2, 1,
                read("bwa.pam", pam("WIDTH 2\nHEIGHT 1\nDEPTH 2\nMAXVAL 1\nTUPLTYPE BLACKANDWHITE_ALPHA\n", 1,
                        1, 0, 0, 1)));
        String m = failure("bw255.pam", pam("WIDTH 1\nHEIGHT 1\nDEPTH 1\nMAXVAL 255\nTUPLTYPE BLACKANDWHITE\n", 1, 0));
        assertTrue(m.endsWith("PAM corrupt header: tuple type BLACKANDWHITE needs MAXVAL 1, the header says 255"), m);
    }

    @Test
    void shortOrMismatchedGreyFilesAreOneLine() {
        String m = failure("short.pgm", ppm("P5\n4 4\n255\n", 255, 1, 2, 3));
        assertTrue(m.endsWith("PGM truncated: the pixel data needs 16 bytes, the file has 3 after the header"), m);
        m = failure("short.pbm", concat("P4\n9 3\n".getBytes(StandardCharsets.US_ASCII), new byte[5]));
        assertTrue(m.endsWith("PBM truncated: the pixel data needs 6 bytes, the file has 5 after the header"), m);
        m = failure("over.pgm", ppm("P5\n1 1\n100\n", 100, 101));
        assertTrue(m.endsWith("PGM corrupt pixel data: sample 101 at texel (0, 0) is above maxval 100"), m);
        // The last WIDTH was taken, and the file called truncated.
        m = failure("twice.pam", pam("WIDTH 1\nWIDTH 3\nHEIGHT 1\nDEPTH 1\nMAXVAL 255\n", 1, 9));
        assertTrue(m.endsWith("PAM corrupt header: WIDTH is given twice"), m);
        m = failure("depth.pam", pam("WIDTH 1\nHEIGHT 1\nDEPTH 3\nMAXVAL 255\nTUPLTYPE GRAYSCALE\n", 1, 1, 2, 3));
        assertTrue(m.endsWith("PAM corrupt header: tuple type GRAYSCALE needs DEPTH 1, the header says 3"), m);
    }
}
