package dev.trisect.texture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.CRC32;
import java.util.zip.Deflater;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;

/** Builds image files for the reader tests, byte by byte where the test must know exactly what is in them. */
final class TestImages {
    /** A 3x2 pattern (not a power of two), row 0 at the top, with partial and zero alpha. */
    static final int[] PATTERN = {
        0xFFFF0000, 0x8000FF00, 0x000000FF,
        0xFFFFFFFF, 0xFF123456, 0x40ABCDEF,
    };
    static final int PATTERN_WIDTH = 3;
    static final int PATTERN_HEIGHT = 2;

    private TestImages() {
    }

    /** {@link #PATTERN} with every alpha forced to opaque, for formats without alpha. */
    static int[] opaquePattern() {
        int[] opaque = PATTERN.clone();
        for (int i = 0; i < opaque.length; i++) {
            opaque[i] |= 0xFF000000;
        }
        return opaque;
    }

    static BufferedImage patternImage(int type) {
        BufferedImage image = new BufferedImage(PATTERN_WIDTH, PATTERN_HEIGHT, type);
        image.setRGB(0, 0, PATTERN_WIDTH, PATTERN_HEIGHT, PATTERN, 0, PATTERN_WIDTH);
        return image;
    }

    static Path write(Path dir, String fileName, byte[] bytes) {
        try {
            return Files.write(dir.resolve(fileName), bytes);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** An image encoded by javax.imageio in the given format ("png", "jpeg", "bmp", "gif"). */
    static byte[] encode(BufferedImage image, String format) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            if (!ImageIO.write(image, format, out)) {
                fail("no " + format + " writer for image type " + image.getType());
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toByteArray();
    }

    /** A GIF, interlaced (the JDK writer's default) or not. */
    static byte[] encodeGif(BufferedImage image, boolean interlaced) {
        ImageWriter writer = ImageIO.getImageWritersByFormatName("gif").next();
        ImageWriteParam param = writer.getDefaultWriteParam();
        param.setProgressiveMode(interlaced ? ImageWriteParam.MODE_DEFAULT : ImageWriteParam.MODE_DISABLED);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (ImageOutputStream stream = ImageIO.createImageOutputStream(out)) {
            writer.setOutput(stream);
            writer.write(null, new IIOImage(image, null, null), param);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } finally {
            writer.dispose();
        }
        return out.toByteArray();
    }

    /** A binary PPM (P6): the header text then the samples, 1 byte each below maxval 256, else 2 (big-endian). */
    static byte[] ppm(String header, int maxval, int... samples) {
        return netpbm(header, maxval < 256 ? 1 : 2, samples);
    }

    /** A PAM (P7) given its header lines (without P7 and ENDHDR) and its samples. */
    /** A plain (ASCII) Netpbm file: the header, then the samples in decimal, a space between, 16 a line. */
    static byte[] plain(String header, int... samples) {
        StringBuilder text = new StringBuilder(header);
        for (int i = 0; i < samples.length; i++) {
            text.append(samples[i]).append(i % 16 == 15 ? '\n' : ' ');
        }
        return text.toString().getBytes(java.nio.charset.StandardCharsets.US_ASCII);
    }

    static byte[] pam(String headerLines, int bytesPerSample, int... samples) {
        return netpbm("P7\n" + headerLines + "ENDHDR\n", bytesPerSample, samples);
    }

    private static byte[] netpbm(String header, int bytesPerSample, int... samples) {
        byte[] text = header.getBytes(StandardCharsets.ISO_8859_1);
        ByteBuffer out = ByteBuffer.allocate(text.length + samples.length * bytesPerSample);
        out.put(text);
        for (int sample : samples) {
            if (bytesPerSample == 2) {
                out.put((byte) (sample >> 8));
            }
            out.put((byte) sample);
        }
        return out.array();
    }

    /** The samples of ARGB texels in file order: R, G, B, and with 4 channels A after them. */
    static int[] samples(int[] argb, int channels) {
        int[] samples = new int[argb.length * channels];
        for (int i = 0; i < argb.length; i++) {
            for (int c = 0; c < channels; c++) {
                // R, G, B are bits 16, 8, 0; alpha (c = 3) is bits 24.
                samples[channels * i + c] = argb[i] >>> (c == 3 ? 24 : 16 - 8 * c) & 0xFF;
            }
        }
        return samples;
    }

    /** An 18-byte TGA header with no image id and no colour map. */
    static byte[] tgaHeader(int imageType, int width, int height, int bitsPerPixel, int descriptor) {
        ByteBuffer header = ByteBuffer.allocate(18).order(ByteOrder.LITTLE_ENDIAN);
        header.put(2, (byte) imageType);
        header.putShort(12, (short) width);
        header.putShort(14, (short) height);
        header.put(16, (byte) bitsPerPixel);
        header.put(17, (byte) descriptor);
        return header.array();
    }

    /**
     * An uncompressed true-colour TGA of the given texels (row 0 at the top), stored bottom-up or
     * top-down, 24 bits (BGR) or 32 bits (BGRA with 8 alpha bits).
     */
    static byte[] tga(int[] argb, int width, int height, boolean topDown, boolean alpha) {
        int bytes = alpha ? 4 : 3;
        int descriptor = (topDown ? 0x20 : 0) | (alpha ? 8 : 0);
        ByteBuffer out = ByteBuffer.allocate(18 + argb.length * bytes);
        out.put(tgaHeader(2, width, height, bytes * 8, descriptor));
        for (int row = 0; row < height; row++) {
            int y = topDown ? row : height - 1 - row;
            for (int x = 0; x < width; x++) {
                int texel = argb[y * width + x];
                out.put((byte) texel).put((byte) (texel >> 8)).put((byte) (texel >> 16));
                if (alpha) {
                    out.put((byte) (texel >>> 24));
                }
            }
        }
        return out.array();
    }

    static byte[] concat(byte[]... parts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (byte[] part : parts) {
            out.writeBytes(part);
        }
        return out.toByteArray();
    }

    static byte[] bytes(int... values) {
        byte[] out = new byte[values.length];
        for (int i = 0; i < values.length; i++) {
            out[i] = (byte) values[i];
        }
        return out;
    }

    /**
     * A PNG written by hand, for the variants ImageIO's writer does not produce (low bit depths,
     * transparency chunks): one IDAT, no filtering.
     *
     * @param rows   each row's packed samples, without the filter byte
     * @param chunks extra chunks before IDAT, each as type (4 characters) followed by its data
     */
    static byte[] png(int width, int height, int bitDepth, int colourType, byte[][] rows, byte[]... chunks) {
        ByteArrayOutputStream raw = new ByteArrayOutputStream();
        for (byte[] row : rows) {
            raw.write(0); // filter type None
            raw.writeBytes(row);
        }
        Deflater deflater = new Deflater();
        deflater.setInput(raw.toByteArray());
        deflater.finish();
        ByteArrayOutputStream compressed = new ByteArrayOutputStream();
        byte[] buffer = new byte[4096];
        while (!deflater.finished()) {
            compressed.write(buffer, 0, deflater.deflate(buffer));
        }
        deflater.end();
        ByteBuffer header = ByteBuffer.allocate(13).putInt(width).putInt(height);
        header.put((byte) bitDepth).put((byte) colourType).put(new byte[3]);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(bytes(0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A));
        out.writeBytes(pngChunk(concat("IHDR".getBytes(StandardCharsets.US_ASCII), header.array())));
        for (byte[] chunk : chunks) {
            out.writeBytes(pngChunk(chunk));
        }
        out.writeBytes(pngChunk(concat("IDAT".getBytes(StandardCharsets.US_ASCII), compressed.toByteArray())));
        out.writeBytes(pngChunk("IEND".getBytes(StandardCharsets.US_ASCII)));
        return out.toByteArray();
    }

    /** Length, type and data, CRC: {@code typeAndData} is the chunk type's 4 bytes followed by its data. */
    private static byte[] pngChunk(byte[] typeAndData) {
        CRC32 crc = new CRC32();
        crc.update(typeAndData);
        return ByteBuffer.allocate(typeAndData.length + 8).putInt(typeAndData.length - 4).put(typeAndData)
                .putInt((int) crc.getValue()).array();
    }

    /** A PNG chunk's type and data, for {@link #png}. */
    static byte[] chunk(String type, int... data) {
        return concat(type.getBytes(StandardCharsets.US_ASCII), bytes(data));
    }

    /** A PNG whose IHDR claims the given size (CRC fixed up), with no pixel data that could match it. */
    static byte[] pngClaiming(int width, int height) {
        byte[] png = encode(patternImage(BufferedImage.TYPE_INT_RGB), "png");
        ByteBuffer buffer = ByteBuffer.wrap(png); // big-endian, as PNG
        // Signature (8), IHDR length (4), "IHDR" (4), then width and height; the CRC covers type and data.
        buffer.putInt(16, width);
        buffer.putInt(20, height);
        CRC32 crc = new CRC32();
        crc.update(png, 12, 4 + 13);
        buffer.putInt(12 + 4 + 13, (int) crc.getValue());
        return png;
    }

    /** A JPEG whose baseline frame header (SOF0) claims the given size. */
    static byte[] jpegClaiming(int width, int height) {
        byte[] jpeg = encode(patternImage(BufferedImage.TYPE_INT_RGB), "jpeg");
        for (int i = 2; i + 8 < jpeg.length; i++) {
            if ((jpeg[i] & 0xFF) == 0xFF && (jpeg[i + 1] & 0xFF) == 0xC0) {
                ByteBuffer buffer = ByteBuffer.wrap(jpeg);
                buffer.putShort(i + 5, (short) height);
                buffer.putShort(i + 7, (short) width);
                return jpeg;
            }
        }
        throw new AssertionError("no SOF0 marker in the test JPEG");
    }

    /**
     * A BMP whose headers claim the given size, consistently (the JDK reader checks the pixel bytes
     * against the declared file size), with only the 3x2 image's pixel data after them.
     */
    static byte[] bmpClaiming(int width, int height) {
        byte[] bmp = encode(patternImage(BufferedImage.TYPE_3BYTE_BGR), "bmp");
        ByteBuffer buffer = ByteBuffer.wrap(bmp).order(ByteOrder.LITTLE_ENDIAN);
        assertEquals(40, buffer.getInt(14), "expected a BITMAPINFOHEADER");
        int offset = buffer.getInt(10);
        long rowBytes = ((long) width * 3 + 3) / 4 * 4;
        buffer.putInt(2, (int) Math.min(0xFFFFFFFFL, offset + rowBytes * height)); // file size, unsigned
        buffer.putInt(18, width);
        buffer.putInt(22, height);
        buffer.putInt(34, 0); // image size: 0 is allowed for BI_RGB
        return bmp;
    }

    /** The start of a GIF, up to the first image descriptor, with both screen and image of the given size. */
    static byte[] gifClaiming(int width, int height) {
        ByteBuffer out = ByteBuffer.allocate(6 + 7 + 6 + 10 + 1).order(ByteOrder.LITTLE_ENDIAN);
        out.put("GIF89a".getBytes(StandardCharsets.US_ASCII));
        out.putShort((short) width).putShort((short) height);
        out.put((byte) 0x80).put((byte) 0).put((byte) 0); // a global colour table of 2 entries
        out.put(bytes(0, 0, 0, 255, 255, 255));
        out.put((byte) 0x2C).putShort((short) 0).putShort((short) 0).putShort((short) width).putShort((short) height);
        out.put((byte) 0);
        out.put((byte) 2); // LZW minimum code size; the image data itself is missing
        return out.array();
    }

    /** Texels as hex, for failure messages. */
    static String hex(int[] argb) {
        StringBuilder text = new StringBuilder();
        for (int texel : argb) {
            text.append(String.format("%08X ", texel));
        }
        return text.toString().trim();
    }

    static void assertTexels(int[] expected, int width, int height, Texture texture) {
        assertEquals(width + "x" + height, texture.width() + "x" + texture.height(), "size");
        assertEquals(hex(expected), hex(texture.argb()), "texels, row 0 at the top");
    }
}
