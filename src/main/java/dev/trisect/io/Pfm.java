package dev.trisect.io;

import dev.trisect.base.InputException;
import dev.trisect.math.Viewport;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Pattern;

/**
 * Portable float maps (PFM), the format of Trisect's UV output (see the rendering conventions).
 *
 * <p>A PFM file is an ASCII header — {@code PF} (3 channels) or {@code Pf} (1 channel), the width and
 * height, and a scale whose sign gives the byte order (negative: little-endian, positive: big-endian),
 * each followed by one whitespace character — then 32-bit IEEE floats, pixel by pixel with the channels
 * together, rows from the <em>bottom</em> of the image to the top. Trisect's arrays have row 0 at the
 * top; these methods flip rows on the way in and out.
 */
public final class Pfm {
    /** Longest header token accepted, in characters; a longer one means the file is not a PFM. */
    private static final int MAX_TOKEN = 32;
    private static final Pattern SIZE = Pattern.compile("[1-9][0-9]{0,9}");
    private static final Pattern NUMBER =
            Pattern.compile("[-+]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?");

    /**
     * A float image read from a PFM file.
     *
     * @param width    width in pixels
     * @param height   height in pixels
     * @param channels floats per pixel: 3 ({@code PF}) or 1 ({@code Pf})
     * @param data     {@code channels * width * height} floats, row 0 at the <em>top</em>, pixel (x, y)'s
     *                 channels at {@code channels * (y * width + x)}; for Trisect's UV output
     *                 {@code [s, t, id]} as in the conventions
     */
    public record Image(int width, int height, int channels, float[] data) {
        /** The data widened to doubles (exactly), in the layout of {@link #data()}, for the metrics. */
        public double[] widened() {
            double[] d = new double[data.length];
            for (int i = 0; i < data.length; i++) {
                d[i] = data[i];
            }
            return d;
        }
    }

    private Pfm() {
    }

    /**
     * Writes a 3-channel UV buffer as the conventions prescribe: header {@code "PF\n<w> <h>\n-1.0\n"},
     * then little-endian floats, rows bottom to top. The file appears complete or not at all.
     *
     * @param out    the file to write
     * @param width  width in pixels, at least 1
     * @param height height in pixels, at least 1
     * @param uv3    {@code 3 * width * height} floats, row 0 at the top (for example {@code [s, t, id]}
     *               per pixel); not modified
     * @throws InputException "out.pfm: cannot write: reason" when the file cannot be written
     * @throws IllegalArgumentException when the size is not positive or does not match the array
     */
    public static void write(Path out, int width, int height, float[] uv3) {
        try (OutputBatch batch = new OutputBatch()) {
            write(batch, out, width, height, uv3);
            batch.commit();
        }
    }

    /**
     * As {@link #write(Path, int, int, float[])}, but as part of {@code batch}: the file appears only
     * when the batch is committed.
     */
    public static void write(OutputBatch batch, Path out, int width, int height, float[] uv3) {
        write(batch, out, width, height, uv3.length, k -> uv3[k]);
    }

    /**
     * Writes a 3-channel UV buffer held in doubles (as a {@code Framebuffer} holds it), each value
     * rounded to the nearest float: the same bytes as {@link #write(OutputBatch, Path, int, int, float[])}
     * gives for the rounded array.
     */
    public static void write(OutputBatch batch, Path out, int width, int height, double[] uv3) {
        write(batch, out, width, height, uv3.length, k -> (float) uv3[k]);
    }

    /** The float to store at index k of a row-major buffer (row 0 at the top). */
    @FunctionalInterface
    private interface FloatAt {
        float at(int k);
    }

    private static void write(OutputBatch batch, Path out, int width, int height, int length, FloatAt value) {
        if (width < 1 || height < 1 || 3L * width * height != length) {
            throw new IllegalArgumentException(
                    "image size " + width + "x" + height + " does not match " + length + " values (3 a pixel)");
        }
        batch.write(out, stream -> writeData(stream, width, height, value));
    }

    private static void writeData(OutputStream stream, int width, int height, FloatAt value) throws IOException {
        stream.write(("PF\n" + width + " " + height + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII));
        int rowValues = 3 * width;
        ByteBuffer row = ByteBuffer.allocate(4 * rowValues).order(ByteOrder.LITTLE_ENDIAN);
        for (int y = height - 1; y >= 0; y--) {
            row.clear();
            for (int k = y * rowValues, end = k + rowValues; k < end; k++) {
                row.putFloat(value.at(k));
            }
            stream.write(row.array());
        }
    }

    /**
     * Reads a PFM file of either byte order, 3 channels ({@code PF}) or 1 ({@code Pf}). The scale's
     * magnitude is not applied: the floats are returned as stored. The data must be exactly
     * {@code 4 * channels * width * height} bytes.
     *
     * @param in the file to read
     * @return the image, row 0 at the top
     * @throws InputException a one-line message starting with the path when the file cannot be read,
     *                        its header is malformed or its data is short or too long
     */
    public static Image read(Path in) {
        if (Files.isDirectory(in)) {
            throw new InputException(in + ": cannot read: it is a directory");
        }
        // A pipe or device could block forever or never end; only regular files are read.
        if (Files.exists(in) && !Files.isRegularFile(in)) {
            throw new InputException(in + ": cannot read: is not a regular file");
        }
        try (InputStream stream = new BufferedInputStream(Files.newInputStream(in), 1 << 16)) {
            Header header = new Header(in, stream);
            int channels = header.magic();
            int width = header.size("width");
            int height = header.size("height");
            ByteOrder order = header.byteOrder();
            // Checked before multiplying: a UV output is a frame, at most Viewport.MAX_SIDE on a side.
            if (width > Viewport.MAX_SIDE || height > Viewport.MAX_SIDE) {
                throw malformed(in, "the image is " + width + "x" + height + " pixels; at most "
                        + Viewport.MAX_SIDE + " on a side is allowed");
            }
            long expected = 4L * channels * width * height;
            long available = Files.size(in) - header.consumed;
            if (available != expected) {
                throw malformed(in, "PFM data is " + (available < expected ? "short" : "too long") + ": "
                        + width + "x" + height + " with " + channels + " channel" + (channels == 1 ? "" : "s")
                        + " needs " + expected + " bytes after the header, the file has " + available);
            }
            return new Image(width, height, channels, readData(in, stream, width, height, channels, order));
        } catch (IOException e) {
            throw new InputException(in + ": cannot read: " + OutputFiles.reason(e, null), e);
        }
    }

    private static float[] readData(Path in, InputStream stream, int width, int height, int channels,
                                    ByteOrder order) throws IOException {
        int rowFloats = channels * width;
        float[] data = new float[rowFloats * height];
        byte[] row = new byte[4 * rowFloats];
        for (int y = height - 1; y >= 0; y--) {
            if (stream.readNBytes(row, 0, row.length) != row.length) {
                // The size was checked; only a file shrinking under us gets here.
                throw malformed(in, "PFM data ends early");
            }
            ByteBuffer.wrap(row).order(order).asFloatBuffer().get(data, y * rowFloats, rowFloats);
        }
        return data;
    }

    private static InputException malformed(Path in, String what) {
        return new InputException(in + ": " + what);
    }

    /** Reads the header's whitespace-separated tokens, counting the bytes it consumes. */
    private static final class Header {
        private final Path in;
        private final InputStream stream;
        private long consumed;

        Header(Path in, InputStream stream) {
            this.in = in;
            this.stream = stream;
        }

        /** Channels named by the magic number: the first two bytes, then one whitespace byte. */
        int magic() throws IOException {
            int p = next();
            int f = next();
            int space = next();
            if (p == 'P' && (f == 'F' || f == 'f') && isSpace(space)) {
                return f == 'F' ? 3 : 1;
            }
            throw malformed(in, "not a PFM file (" + (p < 0 ? "it is empty)" : "it does not start with PF or Pf)"));
        }

        int size(String what) throws IOException {
            String token = token(what);
            if (!SIZE.matcher(token).matches() || Long.parseLong(token) > Integer.MAX_VALUE) {
                throw malformed(in, "bad PFM header: " + what + " '" + printable(token)
                        + "' is not a positive integer");
            }
            return Integer.parseInt(token);
        }

        ByteOrder byteOrder() throws IOException {
            String token = token("scale");
            double scale = NUMBER.matcher(token).matches() ? Double.parseDouble(token) : Double.NaN;
            if (!Double.isFinite(scale) || scale == 0) {
                throw malformed(in, "bad PFM header: scale '" + printable(token) + "' is not a non-zero number");
            }
            return scale < 0 ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN;
        }

        /** The next token; the single whitespace byte after it is consumed too. */
        private String token(String what) throws IOException {
            int c = next();
            while (isSpace(c)) {
                c = next();
            }
            StringBuilder token = new StringBuilder();
            while (c >= 0 && !isSpace(c)) {
                if (token.length() == MAX_TOKEN) {
                    throw malformed(in, "bad PFM header: the " + what + " is too long");
                }
                token.append((char) c);
                c = next();
            }
            if (c < 0) {
                throw malformed(in, "bad PFM header: the file ends in or before the " + what);
            }
            return token.toString();
        }

        private int next() throws IOException {
            int c = stream.read();
            if (c >= 0) {
                consumed++;
            }
            return c;
        }

        private static boolean isSpace(int c) {
            return c == ' ' || c == '\n' || c == '\r' || c == '\t';
        }

        /** A header token as it may appear in a one-line message. */
        private static String printable(String token) {
            StringBuilder out = new StringBuilder(token.length());
            for (int i = 0; i < token.length(); i++) {
                char c = token.charAt(i);
                out.append(c >= 0x20 && c < 0x7F ? c : '?');
            }
            return out.toString();
        }
    }
}
