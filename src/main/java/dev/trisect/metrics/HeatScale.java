package dev.trisect.metrics;

import java.util.ArrayList;
import java.util.List;
import java.util.function.ToIntFunction;

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

    /** The least top {@link #fitted} gives, pixels: below it every pixel looks exact anyway. */
    public static final double LEAST_FITTED_TOP = 0.001;

    /** This scale (linear or log) with another top, pixels. */
    public HeatScale withTop(double top) {
        return new HeatScale(logarithmic, top);
    }

    /**
     * The scale's kind with its top at the largest displacement of an image, so that the worst pixel is
     * white and the ramp spans what is there: the heat map's default top (the view's, unless the user
     * sets one, and {@code compare --heatmap}'s without {@code --heatmap-max}). At least
     * {@link #LEAST_FITTED_TOP}; 1 px when no displacement is defined or none is above 0.
     *
     * @param displacement displacements in pixels, NaN where undefined
     */
    public HeatScale fitted(float[] displacement) {
        float max = 0;
        for (float d : displacement) {
            // NaN fails both comparisons, so undefined pixels are passed over.
            if (d > max && d < Float.POSITIVE_INFINITY) {
                max = d;
            }
        }
        return withTop(max > 0 ? Math.max(LEAST_FITTED_TOP, max) : 1);
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

    /** A label of the legend's bar: at {@code fraction} (0..1) of its width. */
    public record Label(double fraction, String text) {
    }

    /** A label placed on a bar: its left edge, pixels from the bar's left edge. */
    public record Placed(int x, String text) {
    }

    /**
     * The legend's labels: on a logarithmic scale one at every decade, on a linear one its ends and
     * middle; the top reads "≥ top px", since every displacement above it has the top's colour.
     */
    public List<Label> labels() {
        List<Label> out = new ArrayList<>();
        int marks = logarithmic ? DECADES : 2;
        String previous = null;
        for (int k = 0; k <= marks; k++) {
            double f = (double) k / marks;
            // The top is the scale's own maximum; a mark in between that rounds to the one before it (or
            // to 0 at the bottom of the doubles, as 4.9e-324 / 2 does) says nothing and is left out.
            double value = k == marks ? maxPixels : pixelsAt(f);
            String text = number(value);
            if (k == marks) {
                out.add(new Label(f, "\u2265 " + text + " px"));
            } else if (k == 0 || (value != 0 && !text.equals(previous))) {
                out.add(new Label(f, text));
            }
            previous = text;
        }
        return out;
    }

    /**
     * Places labels on a bar {@code barW} pixels wide so that none runs into another: the first starts
     * at the bar's left edge, the last ends at its right edge, each other is centred on its place and
     * left out where it would come within {@code gap} pixels of a label kept before it or of the last.
     */
    public static List<Placed> layout(List<Label> labels, int barW, ToIntFunction<String> width, int gap) {
        List<Placed> out = new ArrayList<>();
        if (labels.isEmpty()) {
            return out;
        }
        Label last = labels.get(labels.size() - 1);
        int lastX = barW - width.applyAsInt(last.text());
        int end = Integer.MIN_VALUE;
        for (int i = 0; i < labels.size() - 1; i++) {
            Label l = labels.get(i);
            int w = width.applyAsInt(l.text());
            int x = i == 0 ? 0 : (int) Math.round(l.fraction() * barW - w / 2.0);
            if (x >= end + gap && x + w + gap <= lastX) {
                out.add(new Placed(x, l.text()));
                end = x + w;
            }
        }
        out.add(new Placed(lastX, last.text()));
        return out;
    }

    /**
     * A short number for labels: up to 3 significant digits, without an exponent from 0.0001 to
     * 99,999, and as {@code 1e308} or {@code 4.94e-324} beyond, so that labels stay short at any
     * {@code --heatmap-max}.
     */
    public static String number(double v) {
        if (v == 0) {
            return "0";
        }
        java.math.BigDecimal d = new java.math.BigDecimal(v).round(new java.math.MathContext(3)).stripTrailingZeros();
        double a = Math.abs(v);
        if (a >= 1e-4 && a < 1e5) {
            return a >= 100 ? String.format(Locale.ROOT, "%.0f", v) : d.toPlainString();
        }
        int exponent = d.precision() - d.scale() - 1;
        return d.movePointLeft(exponent).toPlainString() + "e" + exponent;
    }
}
