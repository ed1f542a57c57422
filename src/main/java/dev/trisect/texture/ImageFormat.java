package dev.trisect.texture;

import java.util.Locale;

/**
 * The image file formats {@link TextureReader} reads, recognised by their first bytes. TGA has no magic
 * number, so a file is taken as TGA only when nothing else matches and its name ends in {@code .tga}.
 */
enum ImageFormat {
    PNG("PNG", "png"),
    JPEG("JPEG", "jpeg"),
    BMP("BMP", "bmp"),
    GIF("GIF", "gif"),
    TGA("TGA", null),
    PPM("PPM", null),
    /** Binary greymap {@code P5} and bitmap {@code P4}. */
    PGM("PGM", null),
    PBM("PBM", null),
    PAM("PAM", null),
    /** Plain (ASCII) Netpbm: bitmap {@code P1}, greymap {@code P2}, pixmap {@code P3}. */
    PLAIN_PBM("plain PBM", null),
    PLAIN_PGM("plain PGM", null),
    PLAIN_PPM("plain PPM", null);

    /** What every "unsupported format" message lists. */
    static final String SUPPORTED = "PNG, JPEG, BMP, GIF, TGA (named *.tga), PBM, PGM and PPM, plain or binary "
            + "(P1 to P6), and PAM (P7, tuple type RGB, RGB_ALPHA, GRAYSCALE, GRAYSCALE_ALPHA, BLACKANDWHITE or "
            + "BLACKANDWHITE_ALPHA)";

    /** Enough leading bytes to recognise every format (and to hold a whole TGA header). */
    static final int HEAD_BYTES = 18;

    /** The name used in messages. */
    final String label;
    /** The javax.imageio format name of the JDK's own reader, or null where Trisect decodes it otherwise. */
    final String imageIoName;

    ImageFormat(String label, String imageIoName) {
        this.label = label;
        this.imageIoName = imageIoName;
    }

    /**
     * The format of a file from its first bytes (up to {@link #HEAD_BYTES}) and its name, or null when
     * it is none of the supported ones.
     */
    static ImageFormat detect(byte[] head, int length, String fileName) {
        if (startsWith(head, length, 0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A)) {
            return PNG;
        }
        if (startsWith(head, length, 0xFF, 0xD8, 0xFF)) {
            return JPEG;
        }
        if (startsWith(head, length, 'G', 'I', 'F', '8')) {
            return GIF;
        }
        if (startsWith(head, length, 'B', 'M')) {
            return BMP;
        }
        if (length >= 3 && head[0] == 'P' && isWhitespace(head[2])) {
            switch (head[1]) {
                case '1':
                    return PLAIN_PBM;
                case '2':
                    return PLAIN_PGM;
                case '3':
                    return PLAIN_PPM;
                case '4':
                    return PBM;
                case '5':
                    return PGM;
                case '6':
                    return PPM;
                case '7':
                    return PAM;
                default:
                    break;
            }
        }
        if (fileName.toLowerCase(Locale.ROOT).endsWith(".tga")) {
            return TGA;
        }
        return null;
    }

    /**
     * For a file that is not supported but is a Netpbm file of another kind (a float map, {@code PF} or
     * {@code Pf}), the magic number to name in the message; otherwise null.
     */
    static String otherNetpbmMagic(byte[] head, int length) {
        if (length >= 3 && head[0] == 'P' && "Ff".indexOf(head[1]) >= 0 && isWhitespace(head[2])) {
            return "P" + (char) head[1];
        }
        return null;
    }

    /** Netpbm's whitespace: space, tab, CR, LF, vertical tab and form feed. */
    static boolean isWhitespace(int b) {
        return b == ' ' || b == '\t' || b == '\r' || b == '\n' || b == 0x0B || b == '\f';
    }

    private static boolean startsWith(byte[] head, int length, int... magic) {
        if (length < magic.length) {
            return false;
        }
        for (int i = 0; i < magic.length; i++) {
            if ((head[i] & 0xFF) != magic[i]) {
                return false;
            }
        }
        return true;
    }
}
