package dev.trisect.metrics;

import java.util.Locale;

/**
 * How a displacement maps onto the heat map's ramp: linearly from 0 to {@code maxPixels}, or
 * logarithmically from {@code maxPixels / 10^decades} to {@code maxPixels}, so that 0.5 px and
 * 1,000 px errors are both readable in one image.
 *
 * @param logarithmic log scale (else linear)
 * @param maxPixels   displacement drawn at the top of the ramp (white), pixels; finite and positive
 */
public record HeatScale(boolean logarithmic, double maxPixels) {
    /** Decades a logarithmic scale spans below its top. */
    public static final int DECADES = 4;

    public HeatScale {
        if (!(maxPixels > 0) || maxPixels == Double.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("maxPixels must be finite and positive, got " + maxPixels);
        }
    }

    public static HeatScale linear(double maxPixels) {
        return new HeatScale(false, maxPixels);
    }

    public static HeatScale log(double maxPixels) {
        return new HeatScale(true, maxPixels);
    }

    /** Bottom of a logarithmic scale, pixels: anything at or below it gets the first colour. */
    public double minPixels() {
        return logarithmic ? maxPixels / Math.pow(10, DECADES) : 0;
    }

    /** Where a displacement lies on the scale, 0..1 (clamped; NaN stays NaN). */
    public double fraction(double pixels) {
        if (Double.isNaN(pixels)) {
            return Double.NaN;
        }
        double f;
        if (logarithmic) {
            f = pixels <= minPixels() ? 0 : Math.log(pixels / minPixels()) / (DECADES * Math.log(10));
        } else {
            f = pixels / maxPixels;
        }
        return Math.max(0, Math.min(1, f));
    }

    /** The displacement at a fraction of the scale, pixels: the inverse of {@link #fraction}. */
    public double pixelsAt(double fraction) {
        return logarithmic ? minPixels() * Math.pow(10, DECADES * fraction) : maxPixels * fraction;
    }

    /** A label such as {@code "linear 0-2 px"} or {@code "log 0.0002-2 px"}. */
    public String describe() {
        return (logarithmic ? "log " : "linear ") + number(minPixels()) + "-" + number(maxPixels) + " px";
    }

    /** A short number for labels: up to 3 significant digits, no exponent for everyday sizes. */
    public static String number(double v) {
        if (v == 0) {
            return "0";
        }
        String s = v >= 100 ? String.format(Locale.ROOT, "%.0f", v)
                : new java.math.BigDecimal(v).round(new java.math.MathContext(3)).stripTrailingZeros().toPlainString();
        return s;
    }
}
