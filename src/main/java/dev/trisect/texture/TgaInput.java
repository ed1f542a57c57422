package dev.trisect.texture;

import dev.trisect.base.InputException;
import dev.trisect.base.internal.Counts;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import javax.imageio.stream.ImageInputStream;
import javax.imageio.stream.MemoryCacheImageInputStream;

/**
 * The TGA header, read by Trisect before TwelveMonkeys' TGA reader sees the file: it gives the size
 * check and clear messages for what that reader would reject obscurely, and works around its
 * small-file bug (see {@link #open}).
 */
final class TgaInput {
    private static final int HEADER_BYTES = 18;
    /** TGA 2.0 footer length: the reader looks for one this far before the end of the file. */
    private static final int FOOTER_BYTES = 26;

    private final String name;
    private final int imageType;
    private final int width;
    private final int height;
    private final int bytesPerPixel;
    private final long pixelDataOffset;

    private TgaInput(String name, byte[] h) {
        this.name = name;
        int idLength = h[0] & 0xFF;
        int colourMapType = h[1] & 0xFF;
        this.imageType = h[2] & 0xFF;
        int colourMapLength = u16(h, 5);
        int colourMapEntryBits = h[7] & 0xFF;
        this.width = u16(h, 12);
        this.height = u16(h, 14);
        int bitsPerPixel = h[16] & 0xFF;
        int descriptor = h[17] & 0xFF;
        if (colourMapType > 1) {
            throw error("corrupt header: colour map type " + colourMapType + " (must be 0 or 1)");
        }
        if (imageType == 0) {
            throw error("the file holds no image data (image type 0)");
        }
        boolean known = imageType == 1 || imageType == 2 || imageType == 3 || imageType == 9 || imageType == 10
                || imageType == 11;
        if (!known) {
            throw error("unsupported image type " + imageType + " (supported: colour-mapped, true-colour and "
                    + "grey-scale, raw or run-length encoded: types 1, 2, 3, 9, 10, 11)");
        }
        if (bitsPerPixel != 8 && bitsPerPixel != 15 && bitsPerPixel != 16 && bitsPerPixel != 24
                && bitsPerPixel != 32) {
            // Checked here because TwelveMonkeys throws an AssertionError for some other depths.
            throw error("unsupported or corrupt header: " + bitsPerPixel + " bits per pixel (TGA uses 8, 15, 16, "
                    + "24 or 32)");
        }
        if ((descriptor & 0x10) != 0) {
            // TwelveMonkeys 3.13.1 rejects it with "Unsupported origin"; say so plainly.
            throw error("unsupported: pixels stored right to left (image descriptor bit 4)");
        }
        this.bytesPerPixel = (bitsPerPixel + 7) / 8;
        long colourMapBytes = colourMapType == 1 ? (long) colourMapLength * ((colourMapEntryBits + 7) / 8) : 0;
        this.pixelDataOffset = HEADER_BYTES + idLength + colourMapBytes;
    }

    /**
     * Parses and checks the 18-byte header (size included) from the first bytes of the file.
     *
     * @throws InputException for a short, corrupt, unsupported or too large image
     */
    static TgaInput parse(String name, byte[] head, int length) {
        if (length < HEADER_BYTES) {
            throw TextureReader.error(name, "TGA truncated: the header needs " + HEADER_BYTES + " bytes, the file has "
                    + length);
        }
        TgaInput tga = new TgaInput(name, head);
        TextureReader.checkSize(name, "TGA", tga.width, tga.height);
        return tga;
    }

    /**
     * A stream for the TwelveMonkeys reader. That reader (3.13.1) probes for a TGA 2.0 footer by seeking
     * to 26 bytes before the end after it has consumed the header and colour map; in a smaller file the
     * seek lands before what it has consumed and fails (a 1x1 TGA, 21 or 22 bytes, cannot be read).
     * Such a file is small, so it is read into memory and given a zero tail that holds no footer. The
     * reader would decode that tail as pixels if the real data were short, so completeness is checked
     * here first (exactly for raw data, by walking the packets for run-length data).
     */
    ImageInputStream open(Path file) throws IOException {
        long size = Files.size(file);
        // A lower bound on the pixel data, checked before the reader allocates the whole image.
        long pixels = (long) width * height;
        long minimum = imageType < 9 ? pixels * bytesPerPixel : (pixels + 127) / 128 * (1 + bytesPerPixel);
        if (size - pixelDataOffset < minimum) {
            throw error("truncated: the pixel data needs at least " + Counts.of(minimum, "byte") + ", the file has "
                    + Math.max(0, size - pixelDataOffset) + " after the header");
        }
        if (size >= pixelDataOffset + FOOTER_BYTES) {
            return TextureReader.openStream(file);
        }
        byte[] data = Files.readAllBytes(file);
        if (imageType >= 9 && !runsComplete(data)) {
            throw error("truncated: the pixel data runs past the end of the file");
        }
        return new MemoryCacheImageInputStream(new ByteArrayInputStream(Arrays.copyOf(data,
                data.length + FOOTER_BYTES)));
    }

    /** Whether the run-length packets in {@code data} cover every pixel without running past its end. */
    private boolean runsComplete(byte[] data) {
        long pixels = (long) width * height;
        long position = pixelDataOffset;
        long done = 0;
        // Each packet: a count byte, then one pixel to repeat or that many raw pixels.
        while (done < pixels) {
            if (position >= data.length) {
                return false;
            }
            int packet = data[(int) position] & 0xFF;
            int count = (packet & 0x7F) + 1;
            position += 1 + (long) ((packet & 0x80) != 0 ? 1 : count) * bytesPerPixel;
            done += count;
        }
        return position <= data.length;
    }

    private static int u16(byte[] b, int offset) {
        return (b[offset] & 0xFF) | (b[offset + 1] & 0xFF) << 8;
    }

    private InputException error(String what) {
        return TextureReader.error(name, "TGA " + what);
    }
}
