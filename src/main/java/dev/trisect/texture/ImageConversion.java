package dev.trisect.texture;

import java.awt.AlphaComposite;
import java.awt.Graphics2D;
import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;
import java.awt.image.ComponentColorModel;
import java.awt.image.ComponentSampleModel;
import java.awt.image.DataBuffer;
import java.awt.image.DataBufferByte;
import java.awt.image.DataBufferInt;
import java.awt.image.IndexColorModel;
import java.awt.image.Raster;

/**
 * Turns a decoded {@link BufferedImage} into non-premultiplied ARGB texels, row 0 at the top, a row of
 * samples at a time rather than a {@code getRGB} call per pixel.
 *
 * <p>Grey images are taken as they are stored: PNG, JPEG and Netpbm grey samples are display values like
 * RGB ones, but Java tags them with its linear grey colour space, and its own conversion (getRGB, and
 * drawImage for grey with alpha) then brightens them, grey 128 becoming 188.
 */
final class ImageConversion {
    private ImageConversion() {
    }

    /** The texels of {@code image}, {@code width * height} ARGB ints. */
    static int[] toArgb(BufferedImage image) {
        ColorModel model = image.getColorModel();
        Raster raster = image.getRaster();
        if (model instanceof IndexColorModel indexed && raster.getNumBands() == 1
                && raster.getSampleModel().getSampleSize(0) <= 16) {
            return fromIndexed(raster, indexed);
        }
        if (model instanceof ComponentColorModel && isPlainComponents(model, raster)) {
            return fromComponents(raster, model);
        }
        return byDrawing(image);
    }

    /** Palette images (GIF, 8-bit PNG and BMP): a lookup per texel; palette alpha kept. */
    private static int[] fromIndexed(Raster raster, IndexColorModel model) {
        int[] palette = new int[1 << raster.getSampleModel().getSampleSize(0)];
        for (int i = 0; i < palette.length; i++) {
            palette[i] = model.getRGB(i); // indices past the palette's end come back as IndexColorModel gives them
        }
        int width = raster.getWidth();
        int height = raster.getHeight();
        int[] argb = new int[width * height];
        int[] row = new int[width];
        for (int y = 0; y < height; y++) {
            raster.getSamples(raster.getMinX(), raster.getMinY() + y, width, 1, 0, row);
            for (int x = 0; x < width; x++) {
                argb[y * width + x] = palette[row[x]];
            }
        }
        return argb;
    }

    /**
     * Whether the samples can be read straight: integer samples of at most 16 bits, not premultiplied,
     * in sRGB (3 colour samples) or grey (1), with or without a trailing alpha sample.
     */
    private static boolean isPlainComponents(ColorModel model, Raster raster) {
        int type = model.getTransferType();
        if (type != DataBuffer.TYPE_BYTE && type != DataBuffer.TYPE_USHORT || model.isAlphaPremultiplied()) {
            return false;
        }
        ColorSpace space = model.getColorSpace();
        int colours = model.getNumColorComponents();
        boolean known = space.isCS_sRGB() && colours == 3 || space.getType() == ColorSpace.TYPE_GRAY && colours == 1;
        if (!known || raster.getNumBands() != model.getNumComponents()) {
            return false;
        }
        for (int band = 0; band < model.getNumComponents(); band++) {
            if (model.getComponentSize(band) > 16) {
                return false;
            }
        }
        return true;
    }

    private static int[] fromComponents(Raster raster, ColorModel model) {
        int width = raster.getWidth();
        int height = raster.getHeight();
        int colours = model.getNumColorComponents();
        int bands = model.getNumComponents();
        int[] argb = new int[width * height];
        int[] sample = new int[4];
        if (isInterleavedBytes(raster, model)) {
            // The common case (PNG, JPEG, BMP, TGA: 8-bit samples side by side): read the bytes directly.
            ComponentSampleModel layout = (ComponentSampleModel) raster.getSampleModel();
            byte[] data = ((DataBufferByte) raster.getDataBuffer()).getData();
            int[] offsets = layout.getBandOffsets();
            int pixelStride = layout.getPixelStride();
            int scanlineStride = layout.getScanlineStride();
            int origin = raster.getDataBuffer().getOffset()
                    + (raster.getMinY() - raster.getSampleModelTranslateY()) * scanlineStride
                    + (raster.getMinX() - raster.getSampleModelTranslateX()) * pixelStride;
            for (int y = 0; y < height; y++) {
                int pixel = origin + y * scanlineStride;
                for (int x = 0; x < width; x++, pixel += pixelStride) {
                    for (int band = 0; band < bands; band++) {
                        sample[band] = data[pixel + offsets[band]] & 0xFF;
                    }
                    argb[y * width + x] = pack(sample, colours, bands);
                }
            }
            return argb;
        }
        int[][] rows = new int[bands][width];
        int[][] toByte = new int[bands][];
        for (int band = 0; band < bands; band++) {
            toByte[band] = scaleTable(model.getComponentSize(band));
        }
        for (int y = 0; y < height; y++) {
            for (int band = 0; band < bands; band++) {
                raster.getSamples(raster.getMinX(), raster.getMinY() + y, width, 1, band, rows[band]);
            }
            for (int x = 0; x < width; x++) {
                for (int band = 0; band < bands; band++) {
                    sample[band] = toByte[band][rows[band][x]];
                }
                argb[y * width + x] = pack(sample, colours, bands);
            }
        }
        return argb;
    }

    /** 8-bit samples, interleaved in one byte array: the layout the direct path understands. */
    private static boolean isInterleavedBytes(Raster raster, ColorModel model) {
        if (!(raster.getSampleModel() instanceof ComponentSampleModel layout)
                || !(raster.getDataBuffer() instanceof DataBufferByte buffer) || buffer.getNumBanks() != 1) {
            return false;
        }
        for (int band = 0; band < model.getNumComponents(); band++) {
            if (model.getComponentSize(band) != 8 || layout.getBankIndices()[band] != 0) {
                return false;
            }
        }
        return true;
    }

    /** One ARGB texel from 0..255 samples: grey or R, G, B, then alpha if there is one. */
    private static int pack(int[] sample, int colours, int bands) {
        int r = sample[0];
        int g = colours == 3 ? sample[1] : r;
        int b = colours == 3 ? sample[2] : r;
        int a = bands > colours ? sample[colours] : 0xFF;
        return a << 24 | r << 16 | g << 8 | b;
    }

    /** Maps {@code bits}-bit samples to 0..255, rounding to nearest. */
    private static int[] scaleTable(int bits) {
        int max = (1 << bits) - 1;
        int[] table = new int[max + 1];
        for (int v = 0; v <= max; v++) {
            table[v] = (int) ((v * 255L + max / 2) / max);
        }
        return table;
    }

    /** Anything else (packed RGB, 16-bit BMP, ICC colour spaces): Java2D converts it in one blit. */
    private static int[] byDrawing(BufferedImage image) {
        BufferedImage argb = new BufferedImage(image.getWidth(), image.getHeight(), BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = argb.createGraphics();
        try {
            g.setComposite(AlphaComposite.Src); // copy alpha as it is rather than blending onto nothing
            g.drawImage(image, 0, 0, null);
        } finally {
            g.dispose();
        }
        // A fresh TYPE_INT_ARGB image has one bank, no offset and a stride of its width: the texels as they are.
        return ((DataBufferInt) argb.getRaster().getDataBuffer()).getData();
    }
}
