package dev.trisect.metrics;

import dev.trisect.texture.internal.BitmapFont;
import java.util.ArrayList;
import java.util.List;

/**
 * Draws a displacement image (pixels, as filled by
 * {@link ImageComparison#compare(int, int, int[], double[], int[], double[], float[])}) as colours.
 *
 * <p>The ramp runs from a dark blue at 0 through blue, purple, red, orange and yellow to white at
 * {@code maxPixels} and above. Its relative luminance rises strictly from each of its
 * {@value #RAMP_SIZE} entries to the next, so brighter always means further off, also in grey scale and
 * for colour-blind readers. It starts well above black (a contrast of 1.6:1 by WCAG 2's formula; the
 * dark indigo it started from before, 1.17:1, read as black on screen), so that a perfect pixel is
 * told from one that nothing drew. Values map linearly: entry {@code round(value / maxPixels * (RAMP_SIZE - 1))},
 * clamped.
 *
 * <p>Pixels without a displacement (NaN) are drawn {@link #UNDEFINED_ARGB}, a neutral dark grey that the
 * ramp never produces; where UV buffers are given, pixels that neither render covers are drawn
 * {@link #UNCOVERED_ARGB}, black. All output is opaque.
 */
public final class HeatMap {
    /** Number of distinct colours in the ramp. */
    public static final int RAMP_SIZE = 256;
    /** Colour of a pixel whose displacement is undefined (NaN) but which a render covers: dark grey. */
    public static final int UNDEFINED_ARGB = 0xFF484848;
    /** Colour of a pixel that neither render covers (when coverage is known): black. */
    public static final int UNCOVERED_ARGB = 0xFF000000;

    /** Key colours at ramp entries; the entries between are interpolated linearly in sRGB. */
    private static final int[] KEY_INDEX = {0, 40, 85, 125, 170, 212, 255};
    private static final int[] KEY_RGB = {
        0x1E2878, // dark blue
        0x2832C8, // blue
        0x9632C8, // purple
        0xE63246, // red
        0xFA8C14, // orange
        0xF5E132, // yellow
        0xFFFFFF, // white
    };
    private static final int[] RAMP = buildRamp();

    /**
     * One key colour of the ramp for a legend: the ramp is (to within rounding) the linear sRGB
     * interpolation between successive stops, and {@code colour(pixels, maxPixels) == argb} exactly.
     *
     * @param pixels displacement in pixels at which the ramp has this colour
     * @param argb   the opaque colour
     */
    public record LegendStop(double pixels, int argb) {
    }

    private HeatMap() {
    }

    /**
     * The colour of one displacement value.
     *
     * @param value     displacement in pixels; NaN gives {@link #UNDEFINED_ARGB}, values at or below 0
     *                  the first ramp colour, values at or above {@code maxPixels} white
     * @param maxPixels displacement in pixels drawn white; finite and positive
     * @return opaque ARGB
     */
    public static int colour(double value, double maxPixels) {
        double scale = scale(maxPixels);
        return Double.isNaN(value) ? UNDEFINED_ARGB : RAMP[rampIndex(value, scale)];
    }

    /**
     * The ramp's key colours, from 0 to {@code maxPixels} pixels, for labelling a legend.
     *
     * @param maxPixels displacement in pixels drawn white; finite and positive
     * @return the stops in increasing order of displacement, the first at 0 and the last at
     *         {@code maxPixels} (white); unmodifiable
     */
    public static List<LegendStop> legendStops(double maxPixels) {
        scale(maxPixels);
        List<LegendStop> stops = new ArrayList<>(KEY_INDEX.length);
        for (int index : KEY_INDEX) {
            stops.add(new LegendStop(maxPixels * index / (RAMP_SIZE - 1), RAMP[index]));
        }
        return List.copyOf(stops);
    }

    /** The colour of one displacement on a linear or logarithmic scale; NaN gives {@link #UNDEFINED_ARGB}. */
    public static int colour(double value, HeatScale scale) {
        return Double.isNaN(value) ? UNDEFINED_ARGB : RAMP[(int) Math.round(scale.fraction(value) * (RAMP_SIZE - 1))];
    }

    /**
     * Draws a displacement image on a linear or logarithmic scale, as
     * {@link #render(float[], double[], double[], int, int, double, int[])} does on a linear one.
     */
    public static void render(float[] displacement, double[] uvTest, double[] uvReference, int width, int height,
                              HeatScale scale, int[] argbOut) {
        if (!scale.logarithmic()) {
            render(displacement, uvTest, uvReference, width, height, scale.maxPixels(), argbOut);
            return;
        }
        render(displacement, uvTest, uvReference, width, height, 1.0, argbOut);
        for (int i = 0; i < displacement.length; i++) {
            if (!Float.isNaN(displacement[i])) {
                argbOut[i] = colour(displacement[i], scale);
            }
        }
    }

    /** Background of the legend's panel: a dark slate, told from black ("not drawn") and the grey. */
    public static final int LEGEND_BACKGROUND = 0xFF1C2430;

    /**
     * Draws the scale's legend into an image, on a panel in its top-left corner: a bar of the ramp with
     * its labels ({@link HeatScale#labels}), the scale named, and a swatch each for "not drawn" (black)
     * and "not comparable" (grey). The text is 14 px high (the built-in font at scale 2) where the image
     * is at least 480 x 240 px, else 7 px (the panel would cover most of a smaller image); no legend
     * where even that has no room.
     */
    public static void drawLegend(int[] argb, int width, int height, HeatScale scale) {
        int s = width >= 480 && height >= 240 ? 2 : 1;
        int barW = Math.min(150 * s, width - 16);
        int line = BitmapFont.CELL_HEIGHT * s + 2 * s;
        int barH = 6 * s;
        if (barW < 20 || height < 24 + barH + 4 * line) {
            return;
        }
        int x = 8;
        int y = 8;
        String title = (scale.logarithmic() ? "LOG" : "LINEAR") + " DISPLACEMENT";
        String[] swatches = {"NOT DRAWN", "NOT COMPARABLE"};
        int swatch = BitmapFont.GLYPH_HEIGHT * s;
        int textW = Math.max(BitmapFont.textWidth(title, s), swatch + 2 * s + BitmapFont.textWidth(swatches[1], s));
        fill(argb, width, height, x - 6, y - 6, x + Math.max(barW, textW) + 6, y + barH + 4 * s + 3 * line + 4,
                LEGEND_BACKGROUND);
        for (int i = 0; i < barW; i++) {
            int c = RAMP[(int) Math.round((double) i / (barW - 1) * (RAMP_SIZE - 1))];
            fill(argb, width, height, x + i, y, x + i + 1, y + barH, c);
        }
        // A label per decade (log) or the ends and middle (linear), the top marked as a floor ("≥"), in
        // the view's words: the font has the "≥" for that (only its capitals show "px" as "PX").
        int labels = y + barH + 4 * s;
        for (HeatScale.Placed p : HeatScale.layout(scale.labels(), barW, t -> BitmapFont.textWidth(t, s), 6 * s)) {
            BitmapFont.drawText(argb, width, height, x + p.x(), labels, p.text(), s, 0xFFFFFFFF);
        }
        BitmapFont.drawText(argb, width, height, x, labels + line, title, s, 0xFFFFFFFF);
        int[] colours = {UNCOVERED_ARGB, UNDEFINED_ARGB};
        for (int k = 0; k < 2; k++) {
            int sy = labels + (2 + k) * line;
            // A white frame round each swatch, so that black shows on the dark panel.
            fill(argb, width, height, x, sy, x + swatch, sy + swatch, 0xFFFFFFFF);
            fill(argb, width, height, x + s, sy + s, x + swatch - s, sy + swatch - s, colours[k]);
            BitmapFont.drawText(argb, width, height, x + swatch + 2 * s, sy, swatches[k], s, 0xFFFFFFFF);
        }
    }

    private static void fill(int[] argb, int width, int height, int x0, int y0, int x1, int y1, int colour) {
        for (int y = Math.max(0, y0); y < Math.min(height, y1); y++) {
            for (int x = Math.max(0, x0); x < Math.min(width, x1); x++) {
                argb[y * width + x] = colour;
            }
        }
    }

    /**
     * Draws a displacement image; every NaN pixel is drawn {@link #UNDEFINED_ARGB}.
     *
     * @param displacement {@code width * height} displacements in pixels, row 0 at the top, NaN where
     *                     undefined
     * @param width        image width in pixels
     * @param height       image height in pixels
     * @param maxPixels    displacement in pixels drawn white; finite and positive
     * @param argbOut      {@code width * height} pixels to fill, row 0 at the top
     */
    public static void render(float[] displacement, int width, int height, double maxPixels, int[] argbOut) {
        render(displacement, null, null, width, height, maxPixels, argbOut);
    }

    /**
     * Draws a displacement image, telling uncovered pixels from undefined ones: a NaN pixel is drawn
     * {@link #UNCOVERED_ARGB} (black) where neither given UV buffer covers it (id 0), else
     * {@link #UNDEFINED_ARGB}. Pass the same buffer twice to use one render's coverage only.
     *
     * @param displacement {@code width * height} displacements in pixels, row 0 at the top, NaN where
     *                     undefined
     * @param uvTest       the test render's UV buffer ({@code 3 * width * height}, id in every third
     *                     float), or null
     * @param uvReference  the reference render's UV buffer, or null; with both null this is
     *                     {@link #render(float[], int, int, double, int[])}
     * @param width        image width in pixels
     * @param height       image height in pixels
     * @param maxPixels    displacement in pixels drawn white; finite and positive
     * @param argbOut      {@code width * height} pixels to fill, row 0 at the top
     */
    public static void render(float[] displacement, double[] uvTest, double[] uvReference, int width, int height,
                              double maxPixels, int[] argbOut) {
        double scale = scale(maxPixels);
        long pixels = (long) width * height;
        if (width < 1 || height < 1 || displacement.length != pixels || argbOut.length != pixels
                || uvTest != null && uvTest.length != 3 * pixels
                || uvReference != null && uvReference.length != 3 * pixels) {
            throw new IllegalArgumentException("array lengths do not match a " + width + "x" + height + " image");
        }
        boolean coverageKnown = uvTest != null || uvReference != null;
        for (int i = 0; i < displacement.length; i++) {
            float value = displacement[i];
            if (!Float.isNaN(value)) {
                argbOut[i] = RAMP[rampIndex(value, scale)];
            } else if (!coverageKnown || covers(uvTest, i) || covers(uvReference, i)) {
                argbOut[i] = UNDEFINED_ARGB;
            } else {
                argbOut[i] = UNCOVERED_ARGB;
            }
        }
    }

    private static boolean covers(double[] uv, int pixel) {
        return uv != null && uv[3 * pixel + 2] != 0;
    }

    /** Ramp entries per pixel of displacement, after checking {@code maxPixels}. */
    private static double scale(double maxPixels) {
        if (!(maxPixels > 0) || maxPixels == Double.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("maxPixels must be finite and positive, got " + maxPixels);
        }
        return (RAMP_SIZE - 1) / maxPixels;
    }

    /** The ramp entry of a non-NaN value: rounded, clamped to the ramp. */
    private static int rampIndex(double value, double scale) {
        double position = value * scale + 0.5;
        if (!(position >= 1)) {
            return 0;
        }
        return position >= RAMP_SIZE - 1 ? RAMP_SIZE - 1 : (int) position;
    }

    private static int[] buildRamp() {
        int[] ramp = new int[RAMP_SIZE];
        for (int key = 0; key + 1 < KEY_INDEX.length; key++) {
            int from = KEY_INDEX[key];
            int to = KEY_INDEX[key + 1];
            for (int i = from; i <= to; i++) {
                double u = (double) (i - from) / (to - from);
                int rgb = 0;
                for (int shift = 16; shift >= 0; shift -= 8) {
                    int a = KEY_RGB[key] >> shift & 0xFF;
                    int b = KEY_RGB[key + 1] >> shift & 0xFF;
                    rgb |= (int) (a + (b - a) * u + 0.5) << shift;
                }
                ramp[i] = 0xFF000000 | rgb;
            }
        }
        return ramp;
    }
}
