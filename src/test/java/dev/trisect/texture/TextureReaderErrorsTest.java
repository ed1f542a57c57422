package dev.trisect.texture;

import static dev.trisect.texture.TestImages.bytes;
import static dev.trisect.texture.TestImages.concat;
import static dev.trisect.texture.TestImages.encode;
import static dev.trisect.texture.TestImages.pam;
import static dev.trisect.texture.TestImages.ppm;
import static dev.trisect.texture.TestImages.tga;
import static dev.trisect.texture.TestImages.tgaHeader;
import static dev.trisect.texture.TestImages.write;
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
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Arrays;
import java.util.Locale;
import java.util.Random;
import java.util.function.BiFunction;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** Every way a texture file can be wrong gives an InputException with one line naming the file. */
@org.junit.jupiter.api.Timeout(120) // guards against hangs (a pipe, a huge claimed size); not a speed check
class TextureReaderErrorsTest {
    @TempDir
    Path dir;

    /** Reads the file expecting failure; checks the message form and returns it. */
    static String failureMessage(Path file) {
        InputException e = assertThrows(InputException.class, () -> TextureReader.read(file));
        String message = e.getMessage();
        assertTrue(message.startsWith(file + ": "), "message starts with the file name: " + message);
        assertFalse(message.contains("\n") || message.contains("\r"), "one line: " + message);
        assertEquals(InputException.Kind.UNREADABLE, e.kind());
        assertEquals(1, e.exitStatus());
        return message;
    }

    private void assertFailsSaying(Path file, String... phrases) {
        String message = failureMessage(file);
        for (String phrase : phrases) {
            assertTrue(message.toLowerCase(Locale.ROOT).contains(phrase.toLowerCase(Locale.ROOT)),
                    "'" + phrase + "' in: " + message);
        }
    }

    private void assertFailsSaying(String fileName, byte[] bytes, String... phrases) {
        assertFailsSaying(write(dir, fileName, bytes), phrases);
    }

    // --- the file itself -----------------------------------------------------------------------

    @Test
    void missingFile() {
        assertFailsSaying(dir.resolve("nowhere.png"), "no such file");
    }

    @Test
    void directory() throws IOException {
        assertFailsSaying(Files.createDirectory(dir.resolve("textures.png")), "is a directory");
    }

    @Test
    void emptyFile() {
        assertFailsSaying("empty.png", new byte[0], "is empty");
    }

    @Test
    void unreadableFile() throws IOException {
        Path file = write(dir, "secret.png", encode(TestImages.patternImage(BufferedImage.TYPE_INT_RGB), "png"));
        Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("---------"));
        assumeFalse(Files.isReadable(file), "permissions are not enforced for this user (root?)");
        assertFailsSaying(file, "cannot be read", "permission denied");
    }

    @Test
    void namedPipeIsRejectedWithoutBlocking() throws Exception {
        Path fifo = dir.resolve("pipe.png");
        Process mkfifo;
        try {
            mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).start();
        } catch (IOException e) {
            mkfifo = null;
        }
        assumeTrue(mkfifo != null && mkfifo.waitFor() == 0, "mkfifo is available");
        // Opening a pipe with no writer would block forever.
        assertFailsSaying(fifo, "not a regular file");
    }

    // --- unsupported formats -------------------------------------------------------------------

    @Test
    void unrecognisedFormatListsTheSupportedOnes() {
        assertFailsSaying("notes.txt", "hello, world\n".getBytes(StandardCharsets.US_ASCII),
                "unrecognised image format", "PNG", "JPEG", "BMP", "GIF", "TGA", "PPM", "PAM");
    }

    @Test
    void tgaContentWithoutTheTgaNameIsNotGuessed() {
        assertFailsSaying("image.dat", tga(TestImages.PATTERN, 3, 2, true, false), "unrecognised image format",
                "named *.tga");
    }

    @Test
    void otherNetpbmVariantsAreNamed() {
        // A float map is a Netpbm file too, but no texture (diff reads it as a UV output).
        assertFailsSaying("uv.pfm", ppm("PF\n1 1\n-1.0\n", 255, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0),
                "unsupported Netpbm variant PF");
    }

    @Test
    void pamTupleTypesOtherThanRgbGreyAndBitsAreUnsupported() {
        assertFailsSaying("cmyk.pam", pam("WIDTH 1\nHEIGHT 1\nDEPTH 4\nMAXVAL 255\nTUPLTYPE CMYK\n", 1, 7, 7, 7, 7),
                "PAM unsupported tuple type 'CMYK'", "RGB, RGB_ALPHA, GRAYSCALE, GRAYSCALE_ALPHA, BLACKANDWHITE and "
                        + "BLACKANDWHITE_ALPHA");
        assertFailsSaying("five.pam", pam("WIDTH 1\nHEIGHT 1\nDEPTH 5\nMAXVAL 255\n", 1, 1, 2, 3, 4, 5),
                "DEPTH 5 without a TUPLTYPE");
    }

    @Test
    void rightToLeftTgaIsUnsupported() {
        assertFailsSaying("mirrored.tga", concat(tgaHeader(2, 2, 2, 24, 0x10), new byte[12 + 30]), "right to left");
    }

    @Test
    void tgaImageTypesItCannotRead() {
        assertFailsSaying("nothing.tga", concat(tgaHeader(0, 2, 2, 24, 0), new byte[40]), "no image data");
        assertFailsSaying("huffman.tga", concat(tgaHeader(32, 2, 2, 8, 0), new byte[40]), "unsupported image type 32");
    }

    // --- corrupt headers and data --------------------------------------------------------------

    @Test
    void corruptPamHeaders() {
        assertFailsSaying("mismatch.pam", pam("WIDTH 1\nHEIGHT 1\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB\n", 1, 1, 2, 3, 4),
                "needs DEPTH 3");
        assertFailsSaying("short.pam", pam("WIDTH 1\nDEPTH 3\nMAXVAL 255\n", 1, 1, 2, 3), "no HEIGHT");
        assertFailsSaying("odd.pam", pam("WIDTH 1\nHEIGHT 1\nDEPTH 3\nCOLOUR blue\nMAXVAL 255\n", 1, 1, 2, 3),
                "unknown PAM header line 'COLOUR blue'");
        assertFailsSaying("word.pam", pam("WIDTH one\nHEIGHT 1\nDEPTH 3\nMAXVAL 255\n", 1, 1, 2, 3),
                "WIDTH 'one' is not a number");
        assertFailsSaying("unended.pam", "P7\nWIDTH 1\nHEIGHT 1\n".getBytes(StandardCharsets.US_ASCII), "no ENDHDR");
    }

    @Test
    void corruptPpmHeaders() {
        assertFailsSaying("maxval0.ppm", ppm("P6\n1 1\n0\n", 255, 0, 0, 0), "maxval 0 is outside 1..65535");
        assertFailsSaying("maxval-big.ppm", ppm("P6\n1 1\n70000\n", 65535, 0, 0, 0), "maxval 70000");
        assertFailsSaying("letters.ppm", ppm("P6\n1 x\n255\n", 255, 0, 0, 0), "expected a number for the height");
        assertFailsSaying("cut.ppm", "P6\n1 1".getBytes(StandardCharsets.US_ASCII), "truncated header");
        byte[] endlessComment = new byte[100_000];
        Arrays.fill(endlessComment, (byte) 'x');
        assertFailsSaying("rambling.ppm", concat("P6\n#".getBytes(StandardCharsets.US_ASCII), endlessComment),
                "header: longer than");
        // Found by the command-line trial: the message read "the image is 1000000000000x2 texels".
        assertFailsSaying("wide.ppm", ppm("P6\n99999999999999999999 2\n255\n", 255, 0, 0, 0),
                "the width is more than 1000000000000");
        assertFailsSaying("wide.pam", ("P7\nWIDTH 99999999999999999999\nHEIGHT 1\nDEPTH 3\nMAXVAL 255\nENDHDR\n")
                .getBytes(StandardCharsets.US_ASCII), "the WIDTH is more than 1000000000000");
    }

    @Test
    void sampleAboveMaxvalIsCorrupt() {
        assertFailsSaying("bright.ppm", ppm("P6\n2 1\n100\n", 100, 1, 2, 3, 4, 101, 6),
                "sample 101 at texel (1, 0) is above maxval 100");
    }

    @Test
    void corruptTgaHeader() {
        byte[] header = tgaHeader(2, 2, 2, 24, 0);
        header[1] = 7;
        assertFailsSaying("colourmap.tga", concat(header, new byte[40]), "colour map type 7");
        assertFailsSaying("stub.tga", bytes(0, 0, 2, 0, 0), "TGA truncated: the header needs 18 bytes");
        // Colour-mapped with 2 bits a pixel: TwelveMonkeys would throw an AssertionError.
        byte[] twoBit = tgaHeader(1, 2, 2, 2, 0);
        twoBit[1] = 1;
        twoBit[5] = 4;
        twoBit[7] = 24;
        assertFailsSaying("two-bit.tga", concat(twoBit, new byte[12 + 40]), "2 bits per pixel");
    }

    /** A valid 64x48 file in each format, with noise so compressed data is large enough to cut. */
    static Stream<Arguments> validFiles() {
        Random random = new Random(7);
        int[] noise = new int[64 * 48];
        for (int i = 0; i < noise.length; i++) {
            noise[i] = 0xFF000000 | random.nextInt(0x1000000);
        }
        BiFunction<Integer, int[], BufferedImage> image = (type, argb) -> {
            BufferedImage result = new BufferedImage(64, 48, type);
            result.setRGB(0, 0, 64, 48, argb, 0, 64);
            return result;
        };
        BufferedImage indexed = new BufferedImage(64, 48, BufferedImage.TYPE_BYTE_INDEXED);
        indexed.setRGB(0, 0, 64, 48, noise, 0, 64);
        return Stream.of(
                Arguments.of("PNG", "noise.png", encode(image.apply(BufferedImage.TYPE_INT_ARGB, noise), "png")),
                Arguments.of("JPEG", "noise.jpg", encode(image.apply(BufferedImage.TYPE_INT_RGB, noise), "jpeg")),
                Arguments.of("BMP", "noise.bmp", encode(image.apply(BufferedImage.TYPE_3BYTE_BGR, noise), "bmp")),
                Arguments.of("GIF", "noise.gif", encode(indexed, "gif")),
                Arguments.of("TGA", "noise.tga", tga(noise, 64, 48, false, true)),
                Arguments.of("PPM", "noise.ppm", ppm("P6\n64 48\n255\n", 255, TestImages.samples(noise, 3))),
                Arguments.of("PAM", "noise.pam", pam("WIDTH 64\nHEIGHT 48\nDEPTH 4\nMAXVAL 255\n", 1,
                        TestImages.samples(noise, 4))),
                Arguments.of("plain PPM", "noise-plain.ppm", TestImages.plain("P3\n64 48\n255\n",
                        TestImages.samples(noise, 3))),
                Arguments.of("plain PGM", "noise.pgm", TestImages.plain("P2\n64 48\n255\n",
                        TestImages.samples(noise, 1))),
                Arguments.of("plain PBM", "noise.pbm", TestImages.plain("P1\n64 48\n",
                        Arrays.stream(TestImages.samples(noise, 1)).map(v -> v & 1).toArray())));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("validFiles")
    void truncatedDataIsReportedWithTheFormat(String format, String fileName, byte[] valid) {
        assertEquals(64, TextureReader.read(write(dir, fileName, valid)).width(), "the untruncated file reads");
        for (double kept : new double[] {0.6, 0.95}) {
            byte[] cut = Arrays.copyOf(valid, (int) (valid.length * kept));
            assertFailsSaying("cut-" + kept + "-" + fileName, cut, format);
        }
    }

    @Test
    void tinyTgaWithShortDataIsTruncatedNotPaddedWithBlack() {
        // 2x1 24-bit needs 6 bytes of pixels; 5 are there. Raw and run-length (one raw packet of 2).
        assertFailsSaying("short.tga", concat(tgaHeader(2, 2, 1, 24, 0), new byte[5]), "TGA truncated");
        assertFailsSaying("short-rle.tga", concat(tgaHeader(10, 2, 1, 24, 0), bytes(0x01, 1, 2, 3, 4, 5)),
                "TGA truncated");
    }

    // --- sizes ---------------------------------------------------------------------------------

    /** Files whose headers claim a given size, with little or no pixel data after them. */
    static Stream<Arguments> claimedSizes() {
        return Stream.of(
                Arguments.of("huge.png", (BiFunction<Integer, Integer, byte[]>) TestImages::pngClaiming),
                Arguments.of("huge.jpg", (BiFunction<Integer, Integer, byte[]>) TestImages::jpegClaiming),
                Arguments.of("huge.bmp", (BiFunction<Integer, Integer, byte[]>) TestImages::bmpClaiming),
                Arguments.of("huge.gif", (BiFunction<Integer, Integer, byte[]>) TestImages::gifClaiming),
                Arguments.of("huge.tga", (BiFunction<Integer, Integer, byte[]>) (w, h) -> tgaHeader(2, w, h, 24, 0)),
                Arguments.of("huge.ppm", (BiFunction<Integer, Integer, byte[]>) (w, h) ->
                        ppm("P6\n" + w + " " + h + "\n255\n", 255)),
                Arguments.of("huge.pam", (BiFunction<Integer, Integer, byte[]>) (w, h) ->
                        pam("WIDTH " + w + "\nHEIGHT " + h + "\nDEPTH 3\nMAXVAL 255\n", 1)),
                Arguments.of("huge-plain.ppm", (BiFunction<Integer, Integer, byte[]>) (w, h) ->
                        TestImages.plain("P3\n" + w + " " + h + "\n255\n", 1, 2, 3)),
                Arguments.of("huge.pgm", (BiFunction<Integer, Integer, byte[]>) (w, h) ->
                        TestImages.plain("P2\n" + w + " " + h + "\n255\n", 1)),
                Arguments.of("huge.pbm", (BiFunction<Integer, Integer, byte[]>) (w, h) ->
                        TestImages.plain("P1\n" + w + " " + h + "\n", 1)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("claimedSizes")
    void oversizedImagesAreRejectedFromTheHeader(String fileName, BiFunction<Integer, Integer, byte[]> claiming) {
        int over = Texture.MAX_SIDE + 1;
        // Rejected by the header check: only it says "at most 16384" (decoding first would fail otherwise).
        assertFailsSaying("wide-" + fileName, claiming.apply(over, 10), over + "x10", "at most 16384");
        assertFailsSaying("tall-" + fileName, claiming.apply(10, 60000), "10x60000", "at most 16384");
    }

    @Test
    void declaredSizeBeyondTheDataFailsBeforeAllocating() {
        // 16384 x 16384 would take a gigabyte of texels; the file has six bytes of pixels.
        String side = Texture.MAX_SIDE + " " + Texture.MAX_SIDE;
        assertFailsSaying("big.ppm", ppm("P6\n" + side + "\n255\n", 255, 1, 2, 3, 4, 5, 6), "truncated");
        assertFailsSaying("big-plain.ppm", TestImages.plain("P3\n" + side + "\n255\n", 1, 2, 3), "plain PPM truncated",
                "needs at least 1610612735 bytes");
        assertFailsSaying("big.pbm", TestImages.plain("P1\n" + side + "\n", 1, 0), "plain PBM truncated",
                "needs at least 268435456 bytes");
        assertFailsSaying("big.tga", concat(tgaHeader(10, Texture.MAX_SIDE, Texture.MAX_SIDE, 24, 0),
                new byte[100]), "truncated");
    }

    @Test
    void emptyImagesAreRejected() {
        assertFailsSaying("zero.ppm", ppm("P6\n0 5\n255\n", 255), "empty image (0x5)");
        assertFailsSaying("zero.tga", concat(tgaHeader(2, 4, 0, 24, 0), new byte[40]), "empty image (4x0)");
    }

    @Test
    void aCmykJpegIsRefusedRatherThanShownInWrongColours() throws IOException {
        // #3366CC written as CMYK by ImageMagick (convert -size 16x16 xc:'#3366CC' -colorspace CMYK):
        // decoded without its profile it came out #7CA9E7.
        Path file = dir.resolve("cmyk.jpg");
        try (java.io.InputStream in = getClass().getResourceAsStream("cmyk-3366cc.jpg")) {
            Files.copy(in, file);
        }
        assertFailsSaying(file, "a CMYK JPEG", "convert it to RGB first");
    }
}
