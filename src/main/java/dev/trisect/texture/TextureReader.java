package dev.trisect.texture;

import com.twelvemonkeys.imageio.plugins.tga.TGAImageReaderSpi;
import dev.trisect.base.InputException;
import java.awt.image.BufferedImage;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.FileImageInputStream;
import javax.imageio.stream.ImageInputStream;

/**
 * Reads texture image files: PNG, JPEG, BMP, GIF (first frame), TGA, binary PBM, PGM and PPM
 * ({@code P4}, {@code P5}, {@code P6}; 8 or 16 bits a sample), plain (ASCII) PBM, PGM and PPM
 * ({@code P1}, {@code P2}, {@code P3}, as tutorials and ray tracers write them; any maxval up to 65535)
 * and PAM ({@code P7}, tuple types {@code RGB}, {@code RGB_ALPHA}, {@code GRAYSCALE},
 * {@code GRAYSCALE_ALPHA}, {@code BLACKANDWHITE} and {@code BLACKANDWHITE_ALPHA}).
 *
 * <p>The format is recognised from the file's first bytes, not its name, except TGA, which has no magic
 * number and is recognised by the name ending in {@code .tga}. PNG, JPEG, BMP and GIF are decoded by the
 * JDK's javax.imageio readers, TGA by TwelveMonkeys', the Netpbm formats by Trisect itself (the
 * README's list of what is written here says why). Every Netpbm format has the same limits and
 * messages: a sample above maxval is an error, not a colour.
 *
 * <p>Every problem is reported as an {@link InputException} (unreadable input, exit status 1) with a
 * one-line message that starts with the file name: a missing file, a directory, a file that cannot be
 * read, an unsupported format, corrupt or truncated data, or an image wider or taller than
 * {@link Texture#MAX_SIDE} texels. The size is checked from the header, before any pixel is decoded.
 * A JPEG the decoder only warns about (damaged or missing scan data, which it fills with grey) counts
 * as corrupt.
 */
public final class TextureReader {
    private TextureReader() {
    }

    /**
     * Reads an image file into a texture: ARGB texels, row 0 at the top of the image, alpha as stored
     * (fully opaque where the format has none), colour channels not premultiplied. The texture is named
     * after the path as given.
     *
     * @param file an image file on the default file system
     * @return the texture, named after the file
     * @throws InputException for anything wrong with the file, its message naming the file
     */
    public static Texture read(Path file) {
        String name = file.toString();
        byte[] head = new byte[ImageFormat.HEAD_BYTES];
        int headLength = readHead(file, name, head);
        Path fileName = file.getFileName();
        ImageFormat format = ImageFormat.detect(head, headLength, fileName == null ? "" : fileName.toString());
        if (format == null) {
            String netpbm = ImageFormat.otherNetpbmMagic(head, headLength);
            throw error(name, (netpbm != null ? "unsupported Netpbm variant " + netpbm
                    : "unrecognised image format") + " (supported: " + ImageFormat.SUPPORTED + ")");
        }
        try {
            return switch (format) {
                case PPM, PGM, PBM, PAM, PLAIN_PBM, PLAIN_PGM, PLAIN_PPM -> PnmDecoder.read(file, name, format);
                case TGA -> readTga(file, name, head, headLength);
                default -> readWithImageIo(file, name, format);
            };
        } catch (InputException e) {
            throw e;
        } catch (IOException | RuntimeException | AssertionError e) {
            if (causedByMemory(e)) {
                // javax.imageio's PNG reader wraps an OutOfMemoryError in an IIOException.
                throw outOfMemory(name, format);
            }
            // Decoders signal damaged data with all sorts of exceptions, unchecked ones included, and
            // TwelveMonkeys with an AssertionError where it meets what it did not expect.
            throw new InputException(name + ": cannot decode the " + format.label + " data: corrupt, truncated "
                    + "or an unsupported variant (" + describe(e) + ")", e);
        } catch (OutOfMemoryError e) {
            // The size check passed, so this is a large but valid image: say so rather than crash.
            throw outOfMemory(name, format);
        }
    }

    private static InputException outOfMemory(String name, ImageFormat format) {
        return error(name, "not enough memory to decode this " + format.label + " image (give Java more with "
                + "-Xmx, e.g. java -Xmx4g -jar trisect.jar, or use a smaller texture)");
    }

    private static boolean causedByMemory(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t instanceof OutOfMemoryError) {
                return true;
            }
        }
        return false;
    }

    /** An unreadable-input error whose message is {@code name: what}. */
    static InputException error(String name, String what) {
        return new InputException(name + ": " + what);
    }

    /**
     * Rejects an image whose header gives no texels or more than {@link Texture#MAX_SIDE} on a side,
     * before anything is allocated for it.
     */
    static void checkSize(String name, String format, long width, long height) {
        if (width < 1 || height < 1) {
            throw error(name, "the " + format + " header gives an empty image (" + width + "x" + height + ")");
        }
        if (width > Texture.MAX_SIDE || height > Texture.MAX_SIDE) {
            throw error(name, "the image is " + width + "x" + height + " texels; at most " + Texture.MAX_SIDE
                    + " on a side is allowed");
        }
    }

    /**
     * The operating system's reason why {@code file}'s attributes cannot be read, in lower case
     * ("too many levels of symbolic links", "permission denied").
     */
    static String whyUnreachable(Path file) {
        try {
            Files.readAttributes(file, java.nio.file.attribute.BasicFileAttributes.class);
            return "it could not be reached";
        } catch (AccessDeniedException e) {
            return "permission denied (a folder on its path cannot be searched)";
        } catch (java.nio.file.FileSystemException e) {
            String reason = e.getReason();
            if (reason == null || reason.isEmpty()) {
                return "it could not be reached";
            }
            return Character.toLowerCase(reason.charAt(0)) + reason.substring(1);
        } catch (IOException e) {
            return "it could not be reached";
        }
    }

    /** Checks the file can be read and returns how many of its first bytes went into {@code head}. */
    private static int readHead(Path file, String name, byte[] head) {
        if (Files.notExists(file)) {
            throw error(name, "no such file");
        }
        if (Files.isDirectory(file)) {
            throw error(name, "is a directory, not an image file");
        }
        if (!Files.exists(file)) {
            // Neither there nor known to be missing: ask the system why (a loop of symbolic links, a
            // folder that cannot be searched).
            throw error(name, "cannot be read: " + whyUnreachable(file));
        }
        if (!Files.isRegularFile(file)) {
            // A pipe or device could block forever or never end.
            throw error(name, "cannot read: is not a regular file");
        }
        int length;
        try (InputStream in = Files.newInputStream(file)) {
            length = in.readNBytes(head, 0, head.length);
        } catch (AccessDeniedException e) {
            throw new InputException(name + ": cannot be read: permission denied", e);
        } catch (NoSuchFileException e) {
            throw new InputException(name + ": no such file", e);
        } catch (IOException e) {
            throw new InputException(name + ": cannot be read: " + describe(e), e);
        }
        if (length == 0) {
            throw error(name, "is empty");
        }
        return length;
    }

    private static Texture readTga(Path file, String name, byte[] head, int headLength) throws IOException {
        TgaInput tga = TgaInput.parse(name, head, headLength);
        // The reader is created directly so it is always the one TgaInput works around.
        ImageReader reader = new TGAImageReaderSpi().createReaderInstance(null);
        try (ImageInputStream in = tga.open(file)) {
            return decode(reader, in, name, ImageFormat.TGA);
        } finally {
            reader.dispose();
        }
    }

    private static Texture readWithImageIo(Path file, String name, ImageFormat format) throws IOException {
        Iterator<ImageReader> readers = ImageIO.getImageReadersByFormatName(format.imageIoName);
        if (!readers.hasNext()) {
            throw error(name, "this Java runtime has no " + format.label + " decoder");
        }
        ImageReader reader = readers.next();
        try (ImageInputStream in = openStream(file)) {
            return decode(reader, in, name, format);
        } finally {
            reader.dispose();
        }
    }

    /**
     * A seekable stream on the file for javax.imageio, buffered where a registered provider offers
     * one (TwelveMonkeys does; the JDK's plain FileImageInputStream reads unbuffered and decodes PNG
     * about 15% slower).
     */
    static ImageInputStream openStream(Path file) throws IOException {
        ImageInputStream in = ImageIO.createImageInputStream(file.toFile());
        return in != null ? in : new FileImageInputStream(file.toFile());
    }

    /** Checks the size from the header, then decodes the first image. */
    private static Texture decode(ImageReader reader, ImageInputStream in, String name, ImageFormat format)
            throws IOException {
        List<String> warnings = new ArrayList<>();
        reader.addIIOReadWarningListener((source, warning) -> warnings.add(warning));
        reader.setInput(in);
        checkSize(name, format.label, reader.getWidth(0), reader.getHeight(0));
        if (format == ImageFormat.JPEG && channels(reader) == 4) {
            // The JDK decodes CMYK and YCCK JPEGs without their colour profile, so #3366CC came out
            // as #7CA9E7: refused rather than shown in wrong colours.
            throw error(name, "a CMYK JPEG (4 colour channels), which cannot be shown in its true colours: "
                    + "convert it to RGB first (e.g. convert in.jpg -colorspace sRGB out.png)");
        }
        BufferedImage image = reader.read(0);
        // The JPEG decoder only warns about damaged or missing scan data and fills the gap with grey.
        if (format == ImageFormat.JPEG && !warnings.isEmpty()) {
            throw error(name, "corrupt or truncated JPEG data (" + oneLine(warnings.get(0)) + ")");
        }
        return new Texture(name, image.getWidth(), image.getHeight(), ImageConversion.toArgb(image));
    }

    /** The number of colour channels the image's standard metadata gives (0 if it gives none). */
    private static int channels(ImageReader reader) throws IOException {
        javax.imageio.metadata.IIOMetadata metadata = reader.getImageMetadata(0);
        if (metadata == null || !metadata.isStandardMetadataFormatSupported()) {
            return 0;
        }
        org.w3c.dom.Node root = metadata.getAsTree(javax.imageio.metadata.IIOMetadataFormatImpl.standardMetadataFormatName);
        for (org.w3c.dom.Node n = root.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (!n.getNodeName().equals("Chroma")) {
                continue;
            }
            for (org.w3c.dom.Node c = n.getFirstChild(); c != null; c = c.getNextSibling()) {
                if (c.getNodeName().equals("NumChannels")) {
                    String value = ((org.w3c.dom.Element) c).getAttribute("value").trim();
                    // The value is a list of integers; its first is the count.
                    try {
                        return Integer.parseInt(value.split("\\s+")[0]);
                    } catch (NumberFormatException e) {
                        return 0;
                    }
                }
            }
        }
        return 0;
    }

    /** An exception as a short phrase for a one-line message. */
    private static String describe(Throwable e) {
        if (e instanceof EOFException) {
            return "unexpected end of file";
        }
        String message = e.getMessage();
        return message == null || message.isBlank() ? e.getClass().getSimpleName() : oneLine(message);
    }

    private static String oneLine(String text) {
        String line = text.strip().replaceAll("\\s+", " ");
        return line.length() > 200 ? line.substring(0, 200) + "..." : line;
    }
}
