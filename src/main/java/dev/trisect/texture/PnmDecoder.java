package dev.trisect.texture;

import dev.trisect.base.InputException;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Reads binary PBM, PGM and PPM ({@code P4}, {@code P5}, {@code P6}) and PAM ({@code P7}, tuple types
 * {@code RGB}, {@code GRAYSCALE} and {@code BLACKANDWHITE}, each also with {@code _ALPHA}), 8 or 16 bits
 * a sample (any maxval 1..65535), and plain (ASCII) PBM, PGM and PPM ({@code P1}, {@code P2},
 * {@code P3}), as the Netpbm specifications describe them. A grey sample g is the colour (g, g, g); a
 * bitmap's 1 is black in PBM and white in PAM's {@code BLACKANDWHITE}, as the specifications say.
 *
 * <p>Trisect decodes these itself rather than through TwelveMonkeys' PNM plugin. Its PAM header parser
 * (3.13.1) rejects valid headers: more than one space between keyword and value, and a missing
 * (optional) {@code TUPLTYPE}. For the plain formats it keeps a sample above maxval as its low byte (300
 * becomes 44) instead of refusing it, refuses a {@code #} comment among the samples (Netpbm's own
 * programs accept one), reports a short file as a bare end of file, and hands a PGM over as a linear
 * grey image whose colours, read as sRGB, come out brighter than the file says (128 as 188). The
 * formats are simple enough that one small reader with the same limits and messages for all of them
 * is clearer than patching around another.
 */
final class PnmDecoder {
    /** A header longer than this is taken as a corrupt file rather than read on and on. */
    private static final int MAX_HEADER_BYTES = 1 << 16;
    /**
     * A header number above this is refused as it is read: far above any valid size or maxval, far
     * below overflow. (Saturating it instead put a number the file does not hold in the message.)
     */
    private static final long NUMBER_CAP = 1_000_000_000_000L;

    private final InputStream in;
    private final String name;
    private final String label;
    /** Bytes consumed so far. */
    private long position;

    private PnmDecoder(InputStream in, String name, String label) {
        this.in = in;
        this.name = name;
        this.label = label;
    }

    /** The header fields that matter; {@code channels}: 1 grey or bits, 2 grey and alpha, 3 RGB, 4 RGB and alpha. */
    private record Header(long width, long height, int maxval, int channels) {
        int bytesPerSample() {
            return maxval < 256 ? 1 : 2;
        }
    }

    /** Reads a whole PBM, PGM, PPM (binary or plain) or PAM file (format as detected from its magic number). */
    static Texture read(Path file, String name, ImageFormat format) throws IOException {
        long fileSize = Files.size(file);
        try (InputStream raw = Files.newInputStream(file)) {
            PnmDecoder decoder = new PnmDecoder(new BufferedInputStream(raw, 1 << 16), name, format.label);
            Header header = switch (format) {
                case PPM -> decoder.readPpmHeader('6', 3);
                case PGM -> decoder.readPpmHeader('5', 1);
                case PBM -> decoder.readPbmHeader('4');
                case PAM -> decoder.readPamHeader();
                case PLAIN_PBM -> decoder.readPbmHeader('1');
                case PLAIN_PGM -> decoder.readPpmHeader('2', 1);
                default -> decoder.readPpmHeader('3', 3);
            };
            boolean plain = format == ImageFormat.PLAIN_PBM || format == ImageFormat.PLAIN_PGM
                    || format == ImageFormat.PLAIN_PPM;
            TextureReader.checkSize(name, format.label, header.width, header.height);
            // Checked before allocating the texels, so a truncated file claiming a large size fails fast.
            // A plain sample takes at least one byte, and but for bits one separator too; a binary bitmap's
            // rows are packed 8 texels a byte.
            long samples = header.width * header.height * header.channels;
            long needed = format == ImageFormat.PBM ? (header.width + 7) / 8 * header.height
                    : !plain ? samples * header.bytesPerSample()
                    : format == ImageFormat.PLAIN_PBM ? samples : 2 * samples - 1;
            long available = fileSize - decoder.position;
            if (available < needed) {
                throw decoder.error("truncated: the pixel data needs " + (plain ? "at least " : "") + needed
                        + " bytes, the file has " + available + " after the header");
            }
            return plain ? new PlainSamples(decoder.in, header.maxval, format == ImageFormat.PLAIN_PBM,
                    decoder::error).texture(name, (int) header.width, (int) header.height, header.channels)
                    : format == ImageFormat.PBM ? decoder.readBits(header) : decoder.readPixels(header);
        }
    }

    /** The header of {@code P5}, {@code P6} (binary), {@code P2} or {@code P3} (plain): width, height and maxval. */
    private Header readPpmHeader(char magic, int channels) throws IOException {
        expectMagic(magic);
        long width = readNumber("width");
        long height = readNumber("height");
        long maxval = readNumber("maxval");
        // readNumber consumed the single whitespace byte that separates maxval from the pixels.
        return new Header(width, height, checkMaxval(maxval), channels);
    }

    /** The header of a bitmap, {@code P1} (plain) or {@code P4} (binary): width and height; its samples are bits. */
    private Header readPbmHeader(char magic) throws IOException {
        expectMagic(magic);
        long width = readNumber("width");
        long height = readNumber("height");
        return new Header(width, height, 1, 1);
    }

    private Header readPamHeader() throws IOException {
        expectMagic('7');
        String rest = readLine();
        if (rest == null || !rest.isBlank()) {
            throw error("corrupt header: the P7 line must have nothing after P7");
        }
        long width = -1;
        long height = -1;
        long depth = -1;
        long maxval = -1;
        String tupleType = null;
        while (true) {
            String line = readLine();
            if (line == null) {
                throw error("truncated header: no ENDHDR line");
            }
            line = line.strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String[] parts = line.split("[ \\t\\x0B\\f\\r]+", 2);
            String keyword = parts[0];
            String value = parts.length > 1 ? parts[1] : "";
            switch (keyword) {
                case "ENDHDR" -> {
                    return pamHeader(width, height, depth, maxval, tupleType);
                }
                // A size given twice is a corrupt header, not the last one silently taken.
                case "WIDTH" -> width = once(keyword, width, value);
                case "HEIGHT" -> height = once(keyword, height, value);
                case "DEPTH" -> depth = once(keyword, depth, value);
                case "MAXVAL" -> maxval = once(keyword, maxval, value);
                // The specification joins repeated TUPLTYPE lines with a space.
                case "TUPLTYPE" -> tupleType = tupleType == null ? value : tupleType + " " + value;
                default -> throw error("corrupt header: unknown PAM header line '" + printable(line) + "'");
            }
        }
    }

    private Header pamHeader(long width, long height, long depth, long maxval, String tupleType) {
        String[] required = {"WIDTH", "HEIGHT", "DEPTH", "MAXVAL"};
        long[] values = {width, height, depth, maxval};
        for (int i = 0; i < required.length; i++) {
            if (values[i] < 0) {
                throw error("corrupt header: no " + required[i] + " line");
            }
        }
        // TUPLTYPE is optional; without it, depth 1 to 4 can only sensibly be these.
        String[] byDepth = {null, "GRAYSCALE", "GRAYSCALE_ALPHA", "RGB", "RGB_ALPHA"};
        String type = tupleType != null ? tupleType : depth >= 1 && depth <= 4 ? byDepth[(int) depth] : null;
        if (type == null) {
            throw error("unsupported: DEPTH " + depth + " without a TUPLTYPE (supported: DEPTH 1 to 4, taken as "
                    + "GRAYSCALE, GRAYSCALE_ALPHA, RGB and RGB_ALPHA)");
        }
        int channels;
        switch (type) {
            case "GRAYSCALE", "BLACKANDWHITE" -> channels = 1;
            case "GRAYSCALE_ALPHA", "BLACKANDWHITE_ALPHA" -> channels = 2;
            case "RGB" -> channels = 3;
            case "RGB_ALPHA" -> channels = 4;
            default -> throw error("unsupported tuple type '" + printable(type) + "' (supported: RGB, RGB_ALPHA, "
                    + "GRAYSCALE, GRAYSCALE_ALPHA, BLACKANDWHITE and BLACKANDWHITE_ALPHA)");
        }
        if (depth != channels) {
            throw error("corrupt header: tuple type " + type + " needs DEPTH " + channels + ", the header says "
                    + depth);
        }
        if (type.startsWith("BLACKANDWHITE") && maxval != 1) {
            throw error("corrupt header: tuple type " + type + " needs MAXVAL 1, the header says " + maxval);
        }
        return new Header(width, height, checkMaxval(maxval), channels);
    }

    private int checkMaxval(long maxval) {
        if (maxval < 1 || maxval > 65535) {
            throw error("corrupt header: maxval " + maxval + " is outside 1..65535");
        }
        return (int) maxval;
    }

    private Texture readPixels(Header header) throws IOException {
        int width = (int) header.width;
        int height = (int) header.height;
        int bytesPerSample = header.bytesPerSample();
        int[] toByte = scaleTable(header.maxval);
        byte[] row = new byte[width * header.channels * bytesPerSample];
        int[] argb = new int[width * height];
        int[] sample = new int[4];
        for (int y = 0; y < height; y++) {
            if (in.readNBytes(row, 0, row.length) < row.length) {
                throw error("truncated: the pixel data ends in row " + y + " of " + height);
            }
            int i = 0;
            for (int x = 0; x < width; x++) {
                for (int c = 0; c < header.channels; c++) {
                    int value = bytesPerSample == 1 ? row[i] & 0xFF : (row[i] & 0xFF) << 8 | row[i + 1] & 0xFF;
                    i += bytesPerSample;
                    if (value > header.maxval) {
                        throw error("corrupt pixel data: sample " + value + " at texel (" + x + ", " + y
                                + ") is above maxval " + header.maxval);
                    }
                    sample[c] = toByte[value];
                }
                argb[y * width + x] = header.channels >= 3
                        ? (header.channels == 4 ? sample[3] : 255) << 24 | sample[0] << 16 | sample[1] << 8 | sample[2]
                        : (header.channels == 2 ? sample[1] : 255) << 24 | sample[0] * 0x010101;
            }
        }
        return new Texture(name, width, height, argb);
    }

    /** A binary bitmap's texels: rows of 8 texels a byte, the first in the high bit, 1 black and 0 white. */
    private Texture readBits(Header header) throws IOException {
        int width = (int) header.width;
        int height = (int) header.height;
        byte[] row = new byte[(width + 7) / 8];
        int[] argb = new int[width * height];
        for (int y = 0; y < height; y++) {
            if (in.readNBytes(row, 0, row.length) < row.length) {
                throw error("truncated: the pixel data ends in row " + y + " of " + height);
            }
            for (int x = 0; x < width; x++) {
                boolean black = (row[x >> 3] >> (7 - (x & 7)) & 1) != 0;
                argb[y * width + x] = black ? 0xFF000000 : 0xFFFFFFFF;
            }
        }
        return new Texture(name, width, height, argb);
    }

    /** Maps samples 0..maxval to 0..255, rounding to nearest. */
    static int[] scaleTable(int maxval) {
        int[] table = new int[maxval + 1];
        for (int v = 0; v <= maxval; v++) {
            table[v] = (int) ((v * 255L + maxval / 2) / maxval);
        }
        return table;
    }

    private void expectMagic(char kind) throws IOException {
        if (next() != 'P' || next() != kind) {
            throw error("corrupt header: expected the magic number P" + kind);
        }
    }

    /**
     * Reads a decimal header number after whitespace and {@code #} comments, and the one whitespace
     * byte that must end it.
     */
    private long readNumber(String what) throws IOException {
        int b = next();
        while (ImageFormat.isWhitespace(b) || b == '#') {
            if (b == '#') {
                do {
                    b = next();
                } while (b != '\n' && b != '\r' && b != -1);
            }
            b = next();
        }
        if (b < '0' || b > '9') {
            throw error(b == -1 ? "truncated header: no " + what
                    : "corrupt header: expected a number for the " + what);
        }
        long value = 0;
        while (b >= '0' && b <= '9') {
            value = capped(value * 10 + (b - '0'), what);
            b = next();
        }
        if (!ImageFormat.isWhitespace(b)) {
            throw error(b == -1 ? "truncated header after the " + what
                    : "corrupt header: the " + what + " must be followed by whitespace");
        }
        return value;
    }

    /** A PAM header number, given for the first time ({@code before} is -1 until it is). */
    private long once(String keyword, long before, String value) {
        if (before >= 0) {
            throw error("corrupt header: " + keyword + " is given twice");
        }
        return parseHeaderNumber(keyword, value);
    }

    private long parseHeaderNumber(String keyword, String value) {
        if (value.isEmpty() || !value.chars().allMatch(ch -> ch >= '0' && ch <= '9')) {
            throw error("corrupt header: " + keyword + " '" + printable(value) + "' is not a number");
        }
        long result = 0;
        for (int i = 0; i < value.length(); i++) {
            result = capped(result * 10 + (value.charAt(i) - '0'), keyword);
        }
        return result;
    }

    private long capped(long value, String what) {
        if (value > NUMBER_CAP) {
            throw error("corrupt header: the " + what + " is more than " + NUMBER_CAP);
        }
        return value;
    }

    /** A header line up to {@code \n} (a trailing {@code \r} kept for strip()), or null at end of file. */
    private String readLine() throws IOException {
        StringBuilder line = new StringBuilder();
        int b = next();
        if (b == -1) {
            return null;
        }
        while (b != '\n' && b != -1) {
            line.append((char) b);
            b = next();
        }
        return line.toString();
    }

    /** The next header byte, or -1 at end of file; a header that goes on too long is corrupt. */
    private int next() throws IOException {
        if (position >= MAX_HEADER_BYTES) {
            throw error("corrupt header: longer than " + MAX_HEADER_BYTES + " bytes");
        }
        int b = in.read();
        if (b != -1) {
            position++;
        }
        return b;
    }

    /** Header text made safe for a one-line message. */
    private static String printable(String text) {
        String shown = text.length() > 40 ? text.substring(0, 40) + "..." : text;
        return shown.replaceAll("[^\\x20-\\x7E]", "?");
    }

    private InputException error(String what) {
        return TextureReader.error(name, label + " " + what);
    }
}
