package dev.trisect.io;

import dev.trisect.base.InputException;
import java.awt.image.BufferedImage;
import java.awt.image.DataBuffer;
import java.awt.image.DataBufferInt;
import java.awt.image.DirectColorModel;
import java.awt.image.Raster;
import java.awt.image.SinglePixelPackedSampleModel;
import java.awt.image.WritableRaster;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.Locale;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

/**
 * Writes colour images: ARGB {@code int[]}, {@code width * height}, row 0 at the top. PNG and PPM
 * store 8-bit RGB without the alpha channel (renders are opaque, and PPM has none); PAM stores it (a
 * texture's alpha, for export).
 */
public final class ImageFiles {
    private static final int RED = 0xFF0000;
    private static final int GREEN = 0x00FF00;
    private static final int BLUE = 0x0000FF;

    private ImageFiles() {
    }

    /**
     * Writes an image in the format its file name's extension names (case-insensitive): {@code .png}
     * (8-bit RGB PNG), {@code .ppm} (binary PPM, P6, maximum value 255) or {@code .pam} (PAM, P7, tuple
     * type RGB_ALPHA, maximum value 255: the alpha kept). The file appears complete or
     * not at all, and an existing file is replaced only once the new one is fully written.
     *
     * @param out    the file to write
     * @param width  image width in pixels, at least 1
     * @param height image height in pixels, at least 1
     * @param argb   {@code width * height} pixels, ARGB, row 0 at the top; not modified
     * @throws InputException a usage error for any other extension; an unreadable-input error
     *                        ("out.png: cannot write: reason") when the file cannot be written
     * @throws IllegalArgumentException when the size is not positive or does not match the array
     */
    public static void write(Path out, int width, int height, int[] argb) {
        try (OutputBatch batch = new OutputBatch()) {
            write(batch, out, width, height, argb);
            batch.commit();
        }
    }

    /**
     * As {@link #write(Path, int, int, int[])}, but as part of {@code batch}: the file appears only when
     * the batch is committed.
     */
    public static void write(OutputBatch batch, Path out, int width, int height, int[] argb) {
        if (width < 1 || height < 1 || (long) width * height != argb.length) {
            throw new IllegalArgumentException(
                    "image size " + width + "x" + height + " does not match " + argb.length + " pixels");
        }
        String name = String.valueOf(out.getFileName()).toLowerCase(Locale.ROOT);
        if (name.endsWith(".png")) {
            batch.write(out, stream -> writePng(stream, width, height, argb));
        } else if (name.endsWith(".ppm")) {
            batch.write(out, stream -> writePpm(stream, width, height, argb));
        } else if (name.endsWith(".pam")) {
            batch.write(out, stream -> writePam(stream, width, height, argb));
        } else {
            throw InputException.usage(out + ": unsupported output format (use .png, .ppm or .pam)");
        }
    }

    private static void writePng(OutputStream stream, int width, int height, int[] argb) throws IOException {
        // A BufferedImage that views the caller's array: no per-pixel copy.
        DataBufferInt buffer = new DataBufferInt(argb, argb.length);
        SinglePixelPackedSampleModel layout =
                new SinglePixelPackedSampleModel(DataBuffer.TYPE_INT, width, height, new int[] {RED, GREEN, BLUE});
        WritableRaster raster = Raster.createWritableRaster(layout, buffer, null);
        BufferedImage image = new BufferedImage(new DirectColorModel(24, RED, GREEN, BLUE), raster, false, null);

        Iterator<ImageWriter> writers = ImageIO.getImageWritersByFormatName("png");
        if (!writers.hasNext()) {
            throw new IOException("no PNG writer available");
        }
        ImageWriter writer = writers.next();
        // An in-memory cache: ImageIO's default would spill to a file in java.io.tmpdir.
        try (ImageOutputStream output = new MemoryCacheImageOutputStream(stream)) {
            writer.setOutput(output);
            writer.write(image);
        } finally {
            writer.dispose();
        }
    }

    /** A PAM (Netpbm P7) of tuple type RGB_ALPHA, maxval 255: the colours with their alpha, row 0 at the top. */
    private static void writePam(OutputStream stream, int width, int height, int[] argb) throws IOException {
        writeNetpbm(stream, "P7\nWIDTH " + width + "\nHEIGHT " + height + "\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n",
                4, width, height, argb);
    }

    private static void writePpm(OutputStream stream, int width, int height, int[] argb) throws IOException {
        writeNetpbm(stream, "P6\n" + width + " " + height + "\n255\n", 3, width, height, argb);
    }

    /** A Netpbm header, then per pixel red, green, blue and, with 4 {@code channels}, alpha, a byte each. */
    private static void writeNetpbm(OutputStream stream, String header, int channels, int width, int height, int[] argb)
            throws IOException {
        stream.write(header.getBytes(StandardCharsets.US_ASCII));
        byte[] row = new byte[channels * width];
        for (int y = 0; y < height; y++) {
            int pixel = y * width;
            for (int i = 0; i < row.length; i += channels, pixel++) {
                int colour = argb[pixel];
                row[i] = (byte) (colour >> 16);
                row[i + 1] = (byte) (colour >> 8);
                row[i + 2] = (byte) colour;
                if (channels == 4) {
                    row[i + 3] = (byte) (colour >>> 24);
                }
            }
            stream.write(row);
        }
    }
}
