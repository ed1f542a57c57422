package dev.trisect.texture;

import static dev.trisect.texture.TestImages.PATTERN;
import static dev.trisect.texture.TestImages.PATTERN_HEIGHT;
import static dev.trisect.texture.TestImages.PATTERN_WIDTH;
import static dev.trisect.texture.TestImages.assertTexels;
import static dev.trisect.texture.TestImages.bytes;
import static dev.trisect.texture.TestImages.chunk;
import static dev.trisect.texture.TestImages.concat;
import static dev.trisect.texture.TestImages.encode;
import static dev.trisect.texture.TestImages.encodeGif;
import static dev.trisect.texture.TestImages.opaquePattern;
import static dev.trisect.texture.TestImages.pam;
import static dev.trisect.texture.TestImages.png;
import static dev.trisect.texture.TestImages.patternImage;
import static dev.trisect.texture.TestImages.ppm;
import static dev.trisect.texture.TestImages.samples;
import static dev.trisect.texture.TestImages.tga;
import static dev.trisect.texture.TestImages.tgaHeader;
import static dev.trisect.texture.TestImages.write;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Transparency;
import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.ComponentColorModel;
import java.awt.image.DataBuffer;
import java.awt.image.IndexColorModel;
import java.awt.image.WritableRaster;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/** Every supported format reads back to the texels that were written, row 0 at the top. */
class TextureReaderFormatsTest {
    @TempDir
    Path dir;

    private Texture read(String fileName, byte[] bytes) {
        return TextureReader.read(write(dir, fileName, bytes));
    }

    // --- javax.imageio formats -------------------------------------------------------------------

    @Test
    void pngKeepsColourAndAlphaExactly() {
        Texture texture = read("rgba.png", encode(patternImage(BufferedImage.TYPE_INT_ARGB), "png"));
        assertTexels(PATTERN, PATTERN_WIDTH, PATTERN_HEIGHT, texture);
    }

    @Test
    void textureIsNamedAfterThePathAsGiven() {
        Path file = write(dir, "named.png", encode(patternImage(BufferedImage.TYPE_INT_RGB), "png"));
        assertEquals(file.toString(), TextureReader.read(file).name());
    }

    @Test
    void greyPngKeepsItsStoredValues() {
        // Java's own getRGB would turn grey 128 into 188 (it takes grey as linear light).
        BufferedImage grey = new BufferedImage(3, 1, BufferedImage.TYPE_BYTE_GRAY);
        grey.getRaster().setSamples(0, 0, 3, 1, 0, new int[] {0, 128, 255});
        Texture texture = read("grey.png", encode(grey, "png"));
        assertTexels(new int[] {0xFF000000, 0xFF808080, 0xFFFFFFFF}, 3, 1, texture);
    }

    @Test
    void greyAlphaPngKeepsGreyAndAlpha() {
        ComponentColorModel model = new ComponentColorModel(ColorSpace.getInstance(ColorSpace.CS_GRAY), true, false,
                Transparency.TRANSLUCENT, DataBuffer.TYPE_BYTE);
        WritableRaster raster = model.createCompatibleWritableRaster(2, 1);
        raster.setPixels(0, 0, 2, 1, new int[] {10, 255, 128, 100});
        Texture texture = read("grey-alpha.png", encode(new BufferedImage(model, raster, false, null), "png"));
        assertTexels(new int[] {0xFF0A0A0A, 0x64808080}, 2, 1, texture);
    }

    @Test
    void sixteenBitPngIsScaledToEightBits() {
        ComponentColorModel model = new ComponentColorModel(ColorSpace.getInstance(ColorSpace.CS_sRGB), false, false,
                Transparency.OPAQUE, DataBuffer.TYPE_USHORT);
        WritableRaster raster = model.createCompatibleWritableRaster(2, 1);
        raster.setPixels(0, 0, 2, 1, new int[] {65535, 0x8000, 0, 257 * 0x12, 257 * 0x34, 0x7F7F});
        Texture texture = read("deep.png", encode(new BufferedImage(model, raster, false, null), "png"));
        assertTexels(new int[] {0xFFFF8000, 0xFF12347F}, 2, 1, texture);
    }

    /** Hand-built PNGs: the low bit depths and transparency chunks ImageIO's writer never produces. */
    static Stream<Arguments> handBuiltPngs() {
        byte[][] twoBitGrey = {bytes(0b00_11_01_10)}; // 0, 3, 1, 2 of 3
        byte[][] fourBitIndices = {bytes(0x01, 0x20)}; // 0, 1, 2, 0
        byte[] palette = chunk("PLTE", 10, 20, 30, 200, 100, 50, 0, 255, 0);
        return Stream.of(
                Arguments.of("2-bit grey", png(4, 1, 2, 0, twoBitGrey),
                        new int[] {0xFF000000, 0xFFFFFFFF, 0xFF555555, 0xFFAAAAAA}),
                Arguments.of("4-bit palette, first entry half transparent",
                        png(4, 1, 4, 3, fourBitIndices, palette, chunk("tRNS", 128)),
                        new int[] {0x800A141E, 0xFFC86432, 0xFF00FF00, 0x800A141E}),
                Arguments.of("8-bit grey, 50 transparent", png(2, 1, 8, 0, new byte[][] {bytes(50, 51)},
                        chunk("tRNS", 0, 50)), new int[] {0x00323232, 0xFF333333}),
                Arguments.of("16-bit RGB, (1, 2, 3) transparent", png(2, 1, 16, 2,
                        new byte[][] {bytes(0, 1, 0, 2, 0, 3, 0xFF, 0xFF, 0, 0, 0, 0)}, chunk("tRNS", 0, 1, 0, 2, 0, 3)),
                        new int[] {0x00000000, 0xFFFF0000}));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("handBuiltPngs")
    void pngVariantsReadExactly(String variant, byte[] png, int[] expected) {
        assertTexels(expected, expected.length, 1, read("variant.png", png));
    }

    @Test
    void jpegReadsBackWithinTolerance() {
        // Flat 16x16 blocks keep the JPEG error small away from block edges.
        int[] colours = {0xFFC03020, 0xFF20A040, 0xFF2040C0, 0xFFE0E0E0};
        BufferedImage image = new BufferedImage(32, 32, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 32; y++) {
            for (int x = 0; x < 32; x++) {
                image.setRGB(x, y, colours[(y / 16) * 2 + x / 16]);
            }
        }
        Texture texture = read("blocks.jpg", encode(image, "jpeg"));
        assertEquals(32, texture.width());
        assertEquals(32, texture.height());
        for (int block = 0; block < 4; block++) {
            int centre = texture.argb()[((block / 2) * 16 + 8) * 32 + (block % 2) * 16 + 8];
            assertEquals(0xFF, centre >>> 24, "JPEG is opaque");
            for (int shift = 0; shift <= 16; shift += 8) {
                int expected = colours[block] >> shift & 0xFF;
                int actual = centre >> shift & 0xFF;
                assertTrue(Math.abs(expected - actual) <= 12, String.format("block %d channel %d: %02X vs %02X",
                        block, shift, expected, actual));
            }
        }
    }

    @Test
    void bmpReadsExactly() {
        Texture texture = read("plain.bmp", encode(patternImage(BufferedImage.TYPE_3BYTE_BGR), "bmp"));
        assertTexels(opaquePattern(), PATTERN_WIDTH, PATTERN_HEIGHT, texture);
    }

    @ParameterizedTest(name = "interlaced {0}")
    @ValueSource(booleans = {false, true})
    void gifReadsItsPaletteAndTransparentIndex(boolean interlaced) {
        // 3x6: the JDK's GIF reader mis-decodes interlaced GIFs under 5 rows, a JDK bug outside this test.
        int[] palette = {0xFF102030, 0xFFFF8000, 0xFF00FF00, 0xFF0000FF};
        IndexColorModel model = new IndexColorModel(2, 4, palette, 0, true, 3, DataBuffer.TYPE_BYTE);
        BufferedImage image = new BufferedImage(3, 6, BufferedImage.TYPE_BYTE_INDEXED, model);
        int[] indices = {0, 1, 2, 3, 2, 1, 1, 1, 0, 2, 3, 0, 0, 0, 0, 3, 3, 3};
        image.getRaster().setSamples(0, 0, 3, 6, 0, indices);
        Texture texture = read("indexed.gif", encodeGif(image, interlaced));
        int[] expected = new int[indices.length];
        for (int i = 0; i < indices.length; i++) {
            // Index 3 is transparent: alpha 0, the palette's RGB kept.
            expected[i] = indices[i] == 3 ? palette[3] & 0x00FFFFFF : palette[indices[i]];
        }
        assertTexels(expected, 3, 6, texture);
    }

    @Test
    void formatComesFromTheContentNotTheName() {
        Texture texture = read("really-a-png.bmp", encode(patternImage(BufferedImage.TYPE_INT_ARGB), "png"));
        assertTexels(PATTERN, PATTERN_WIDTH, PATTERN_HEIGHT, texture);
    }

    // --- TGA -------------------------------------------------------------------------------------

    @ParameterizedTest(name = "top-down {0}")
    @ValueSource(booleans = {false, true})
    void tgaTrueColourInEitherRowOrder(boolean topDown) {
        Texture texture = read("rgb.tga", tga(PATTERN, PATTERN_WIDTH, PATTERN_HEIGHT, topDown, false));
        assertTexels(opaquePattern(), PATTERN_WIDTH, PATTERN_HEIGHT, texture);
    }

    @ParameterizedTest(name = "top-down {0}")
    @ValueSource(booleans = {false, true})
    void tgaWithAlphaKeepsIt(boolean topDown) {
        Texture texture = read("rgba.TGA", tga(PATTERN, PATTERN_WIDTH, PATTERN_HEIGHT, topDown, true));
        assertTexels(PATTERN, PATTERN_WIDTH, PATTERN_HEIGHT, texture);
    }

    @Test
    void tgaRunLengthEncoded() {
        // 8x2 bottom-up: the bottom row is one run of eight blue texels, the top row eight raw grey ones.
        int[] expected = new int[16];
        byte[] raw = new byte[1 + 8 * 3];
        raw[0] = 0x07;
        for (int x = 0; x < 8; x++) {
            int grey = 10 + 30 * x;
            expected[x] = 0xFF000000 | grey * 0x010101;
            raw[1 + 3 * x] = raw[2 + 3 * x] = raw[3 + 3 * x] = (byte) grey;
            expected[8 + x] = 0xFF0000FF;
        }
        Texture texture = read("rle.tga", concat(tgaHeader(10, 8, 2, 24, 0), bytes(0x87, 255, 0, 0), raw));
        assertTexels(expected, 8, 2, texture);
    }

    @Test
    void tinyTgaSmallerThanAFooterReads() {
        // 21 bytes: TwelveMonkeys alone fails on it (TgaInput works around that).
        Texture texture = read("one.tga", tga(new int[] {0xFF336699}, 1, 1, false, false));
        assertTexels(new int[] {0xFF336699}, 1, 1, texture);
    }

    @Test
    void tinyRunLengthTgaReads() {
        Texture texture = read("one-run.tga", concat(tgaHeader(10, 2, 2, 32, 0x28), bytes(0x83, 1, 2, 3, 0x80)));
        assertTexels(new int[] {0x80030201, 0x80030201, 0x80030201, 0x80030201}, 2, 2, texture);
    }

    // --- PPM and PAM -----------------------------------------------------------------------------

    @Test
    void ppmEightBit() {
        Texture texture = read("plain.ppm", ppm("P6\n3 2\n255\n", 255, samples(PATTERN, 3)));
        assertTexels(opaquePattern(), PATTERN_WIDTH, PATTERN_HEIGHT, texture);
    }

    @Test
    void ppmHeaderWithCommentsAndOddWhitespace() {
        Texture texture = read("comments.ppm",
                ppm("P6 # made by hand\n# another comment\n3\t2\r\n#\n255\n", 255, samples(PATTERN, 3)));
        assertTexels(opaquePattern(), PATTERN_WIDTH, PATTERN_HEIGHT, texture);
    }

    @ParameterizedTest(name = "maxval {0}")
    @CsvSource(delimiter = '|', value = {
        // 16 bits: 0x8000 -> 127.5 rounds up to 0x80; 0x1234 -> 18.1; 257 -> 1; 0x7F7F -> 127.
        "65535|65535 32768 0 4660 257 32639|FFFF8000 FF12017F",
        // Odd maxval, still two bytes a sample: 500 -> 127.5 rounds to 128, 1 -> 0.255 rounds to 0.
        "1000|1000 500 1|FFFF8000",
        "15|15 7 0|FFFF7700"})
    void ppmSamplesAreScaledFromMaxvalToEightBits(int maxval, String samples, String expected) {
        int[] values = Arrays.stream(samples.split(" ")).mapToInt(Integer::parseInt).toArray();
        int[] texels = Arrays.stream(expected.split(" ")).mapToInt(hex -> Integer.parseUnsignedInt(hex, 16)).toArray();
        Texture texture = read("scaled.ppm", ppm("P6\n" + texels.length + " 1\n" + maxval + "\n", maxval, values));
        assertTexels(texels, texels.length, 1, texture);
    }

    @Test
    void pamRgb() {
        Texture texture = read("rgb.pam",
                pam("WIDTH 3\nHEIGHT 2\nDEPTH 3\nMAXVAL 255\nTUPLTYPE RGB\n", 1, samples(PATTERN, 3)));
        assertTexels(opaquePattern(), PATTERN_WIDTH, PATTERN_HEIGHT, texture);
    }

    @Test
    void pamRgbAlpha() {
        Texture texture = read("rgba.pam",
                pam("WIDTH 3\nHEIGHT 2\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\n", 1, samples(PATTERN, 4)));
        assertTexels(PATTERN, PATTERN_WIDTH, PATTERN_HEIGHT, texture);
    }

    @Test
    void pamRgbAlphaSixteenBit() {
        Texture texture = read("deep.pam", pam("WIDTH 1\nHEIGHT 1\nDEPTH 4\nMAXVAL 65535\nTUPLTYPE RGB_ALPHA\n", 2,
                0xFFFF, 0, 0x8000, 0x4040));
        assertTexels(new int[] {0x40FF0080}, 1, 1, texture);
    }

    @Test
    void pamHeaderTheTwelveMonkeysParserRejects() {
        // Several spaces and tabs between keyword and value, comments, CRLF, and no TUPLTYPE (optional).
        Texture texture = read("loose.pam", pam("# hand made\r\nWIDTH   3\r\n\tHEIGHT\t2\nDEPTH 4 \nMAXVAL  255\n", 1,
                samples(PATTERN, 4)));
        assertTexels(PATTERN, PATTERN_WIDTH, PATTERN_HEIGHT, texture);
    }

    @Test
    void largestAllowedSideReads() {
        int[] samples = new int[Texture.MAX_SIDE * 3];
        Texture texture = read("wide.ppm", ppm("P6\n" + Texture.MAX_SIDE + " 1\n255\n", 255, samples));
        assertEquals(Texture.MAX_SIDE, texture.width());
    }
}
