package dev.trisect.texture;

import static dev.trisect.texture.TestImages.PATTERN_HEIGHT;
import static dev.trisect.texture.TestImages.PATTERN_WIDTH;
import static dev.trisect.texture.TestImages.assertTexels;
import static dev.trisect.texture.TestImages.opaquePattern;
import static dev.trisect.texture.TestImages.plain;
import static dev.trisect.texture.TestImages.ppm;
import static dev.trisect.texture.TestImages.samples;
import static dev.trisect.texture.TestImages.write;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Plain (ASCII) Netpbm textures, P1, P2 and P3: read to the texels they describe, with the limits
 * and messages of the binary formats.
 */
class PlainNetpbmTest {
    @TempDir
    Path dir;

    private Texture read(String fileName, String text) {
        return TextureReader.read(write(dir, fileName, text.getBytes(StandardCharsets.US_ASCII)));
    }

    private String failure(String fileName, String text) {
        return failure(fileName, text.getBytes(StandardCharsets.ISO_8859_1));
    }

    private String failure(String fileName, byte[] bytes) {
        Path file = write(dir, fileName, bytes);
        return TextureReaderErrorsTest.failureMessage(file).substring(file.toString().length() + 2);
    }

    @Test
    void plainPpmReadsAsTheBinaryOneDoes() {
        Texture binary = TextureReader.read(write(dir, "b.ppm", ppm("P6\n3 2\n255\n", 255, samples(TestImages.PATTERN, 3))));
        Texture ascii = TextureReader.read(write(dir, "a.ppm", plain("P3\n3 2\n255\n", samples(TestImages.PATTERN, 3))));
        assertTexels(opaquePattern(), PATTERN_WIDTH, PATTERN_HEIGHT, ascii);
        assertArrayEquals(binary.argb(), ascii.argb());
    }

    /** As a ray tracer's tutorial writes it: one pixel a line, a comment in the header. */
    @Test
    void aTutorialsImage() {
        Texture t = read("out.ppm", "P3\n# from the tutorial\n2 2\n255\n255 0 0\n0 255 0\n0 0 255\n255 255 255\n");
        assertTexels(new int[] {0xFFFF0000, 0xFF00FF00, 0xFF0000FF, 0xFFFFFFFF}, 2, 2, t);
    }

    /** Whitespace of every kind, comments among the samples (Netpbm's readers take them) and trailing text. */
    @Test
    void whitespaceAndCommentsAnywhereBetweenSamples() {
        Texture t = read("loose.ppm", "P3\t2\r\n1 # one row\n7\n  7\t0\f0 # red\n\u000b0 7 0# green, no space\n"
                + "anything after the last sample");
        assertTexels(new int[] {0xFFFF0000, 0xFF00FF00}, 2, 1, t);
    }

    @ParameterizedTest(name = "maxval {0}")
    @CsvSource(delimiter = '|', value = {
        // The binary PPM's rounding: 32768 of 65535 -> 127.5 -> 128; 500 of 1000 -> 128; 7 of 15 -> 119.
        "65535|0 32768 65535|FF000000 FF808080 FFFFFFFF",
        "1000|500 1 1000|FF808080 FF000000 FFFFFFFF",
        "15|7 0 15|FF777777 FF000000 FFFFFFFF",
        "1|0 1 1|FF000000 FFFFFFFF FFFFFFFF"})
    void plainPgmIsGreyScaledFromMaxval(int maxval, String samples, String expected) {
        String[] texels = expected.split(" ");
        int[] argb = new int[texels.length];
        for (int i = 0; i < argb.length; i++) {
            argb[i] = Integer.parseUnsignedInt(texels[i], 16);
        }
        assertTexels(argb, argb.length, 1, read("grey.pgm", "P2\n" + argb.length + " 1\n" + maxval + "\n" + samples + "\n"));
    }

    /** 1 is black, 0 white; whitespace between bits is optional. */
    @Test
    void plainPbmBitsAreBlackAndWhite() {
        int b = 0xFF000000;
        int w = 0xFFFFFFFF;
        int[] expected = {b, w, b, w, w, b};
        assertTexels(expected, 3, 2, read("bits.pbm", "P1\n# a bitmap\n3 2\n1 0 1\n0 0 1\n"));
        assertTexels(expected, 3, 2, read("packed.pbm", "P1\n3 2\n101001"));
    }

    @Test
    void badSamplesAreNamedWithTheirTexel() {
        assertEquals("plain PPM corrupt pixel data: sample 300 at texel (0, 1) is above maxval 255",
                failure("bright.ppm", "P3\n1 2\n255\n1 2 3\n300 0 0\n"));
        assertEquals("plain PGM corrupt pixel data: sample of 7 digits at texel (1, 0) is above maxval 65535",
                failure("long.pgm", "P2\n2 1\n65535\n1 1234567\n"));
        assertEquals("plain PPM corrupt pixel data: 'x' at texel (0, 0) where a decimal sample should be",
                failure("letters.ppm", "P3\n1 1\n255\n1 x 3\n"));
        assertEquals("plain PPM corrupt pixel data: '-' at texel (0, 0) where a decimal sample should be",
                failure("minus.ppm", "P3\n1 1\n255\n1 2-3\n"));
        assertEquals("plain PBM corrupt pixel data: '2' at texel (1, 0) where a bit (0 or 1) should be",
                failure("two.pbm", "P1\n2 1\n1 2\n"));
        assertEquals("plain PGM corrupt pixel data: '\\xC3' at texel (0, 0) where a decimal sample should be",
                failure("latin.pgm", "P2\n1 1\n9\n\u00c3\n"));
    }

    @Test
    void headerAndLengthProblemsAreThoseOfTheBinaryFormats() {
        assertEquals("plain PPM corrupt header: maxval 0 is outside 1..65535", failure("zero.ppm", "P3\n1 1\n0\n0 0 0\n"));
        assertEquals("plain PGM corrupt header: expected a number for the height", failure("h.pgm", "P2\n1 x\n255\n0\n"));
        assertEquals("the plain PBM header gives an empty image (0x5)", failure("empty.pbm", "P1\n0 5\n"));
        assertEquals("plain PPM truncated: the pixel data needs at least 11 bytes, the file has 6 after the header",
                failure("short.ppm", "P3\n2 1\n255\n1 2 3\n"));
        assertEquals("plain PPM truncated: the pixel data ends in row 1 of 2",
                failure("rows.ppm", "P3\n1 2\n255\n100 200 255 # and no more\n"));
    }
}
