package dev.trisect.texture;

import dev.trisect.base.InputException;
import java.io.IOException;
import java.io.InputStream;
import java.util.function.Function;

/**
 * The raster of a plain (ASCII) Netpbm file, after its header: decimal samples separated by
 * whitespace, as the Netpbm specifications of PBM, PGM and PPM describe them. A {@code #} starts a
 * comment to the end of the line wherever whitespace may be (as Netpbm's own readers take it). In a
 * bitmap ({@code P1}) every sample is one character, {@code 1} black and {@code 0} white, and
 * whitespace between them is optional. Anything after the last sample is ignored, as Netpbm does.
 *
 * <p>Each problem is one line naming the texel: a sample above maxval, a character that is not a
 * digit, the data ending early.
 */
final class PlainSamples {
    /** Digits are accumulated up to this, far above any maxval (65535), then only counted. */
    private static final int SATURATED = 1_000_000;

    private final InputStream in;
    private final int maxval;
    private final boolean bitmap;
    private final Function<String, InputException> error;
    private int x;
    private int y;
    private int height;

    /**
     * @param in     the file, positioned just after the header
     * @param maxval the largest sample, 1..65535 (1 for a bitmap)
     * @param bitmap whether this is a {@code P1} bitmap (one character a sample, 1 black)
     * @param error  makes the one-line error for a problem: it prefixes the file and format
     */
    PlainSamples(InputStream in, int maxval, boolean bitmap, Function<String, InputException> error) {
        this.in = in;
        this.maxval = maxval;
        this.bitmap = bitmap;
        this.error = error;
    }

    /** Reads {@code width x height} texels of {@code channels} (1: grey or bits, 3: RGB) samples each. */
    Texture texture(String name, int width, int height, int channels) throws IOException {
        this.height = height;
        int[] toByte = PnmDecoder.scaleTable(maxval);
        if (bitmap) {
            toByte = new int[] {255, 0};
        }
        int[] argb = new int[width * height];
        for (y = 0; y < height; y++) {
            for (x = 0; x < width; x++) {
                int r = toByte[sample()];
                int g = channels == 1 ? r : toByte[sample()];
                int b = channels == 1 ? r : toByte[sample()];
                argb[y * width + x] = 0xFF000000 | r << 16 | g << 8 | b;
            }
        }
        return new Texture(name, width, height, argb);
    }

    /** The next sample, 0..maxval. */
    private int sample() throws IOException {
        int c = skipSpace();
        if (bitmap) {
            if (c != '0' && c != '1') {
                throw notASample(c);
            }
            return c - '0';
        }
        if (c < '0' || c > '9') {
            throw notASample(c);
        }
        int value = 0;
        int digits = 0;
        for (; c >= '0' && c <= '9'; c = in.read()) {
            value = Math.min(SATURATED, value * 10 + (c - '0'));
            digits++;
        }
        if (c != -1 && c != '#' && !ImageFormat.isWhitespace(c)) {
            throw notASample(c);
        }
        if (c == '#') {
            skipComment();
        }
        if (value > maxval) {
            throw error.apply("corrupt pixel data: sample " + (value < SATURATED ? String.valueOf(value)
                    : "of " + digits + " digits") + " at texel (" + x + ", " + y + ") is above maxval " + maxval);
        }
        return value;
    }

    /** The first character that is neither whitespace nor in a comment. */
    private int skipSpace() throws IOException {
        int c = in.read();
        while (ImageFormat.isWhitespace(c) || c == '#') {
            if (c == '#') {
                skipComment();
            }
            c = in.read();
        }
        if (c == -1) {
            throw error.apply("truncated: the pixel data ends in row " + y + " of " + height);
        }
        return c;
    }

    private void skipComment() throws IOException {
        int c;
        do {
            c = in.read();
        } while (c != '\n' && c != '\r' && c != -1);
    }

    private InputException notASample(int c) {
        String shown = c >= 0x20 && c < 0x7F ? String.valueOf((char) c) : String.format("\\x%02X", c);
        return error.apply("corrupt pixel data: '" + shown + "' at texel (" + x + ", " + y + ") where "
                + (bitmap ? "a bit (0 or 1)" : "a decimal sample") + " should be");
    }
}
