package dev.trisect.metrics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class HeatMapTest {
    private static final int WHITE = 0xFFFFFFFF;

    @ParameterizedTest
    @ValueSource(doubles = {1, 2.5, 0.25})
    void luminanceRisesAlongTheRamp(double max) {
        double previous = -1;
        Set<Integer> colours = new HashSet<>();
        for (int step = 0; step <= 20_000; step++) {
            int argb = HeatMap.colour(max * 1.2 * step / 20_000, max);
            double luminance = luminance(argb);
            assertTrue(luminance >= previous, "luminance falls at step " + step);
            if (colours.add(argb)) {
                // A new colour is strictly brighter than all before it.
                assertTrue(luminance > previous, "two colours with equal luminance at step " + step);
            }
            previous = luminance;
        }
        assertEquals(HeatMap.RAMP_SIZE, colours.size());
    }

    @Test
    void endsOfTheRamp() {
        int zero = HeatMap.colour(0, 2);
        assertNotEquals(HeatMap.UNCOVERED_ARGB, zero, "a perfect pixel must not look uncovered");
        assertTrue(luminance(zero) < 0.05, "the ramp starts dark");
        // WCAG 2 contrast (L1 + 0.05) / (L2 + 0.05): the old start, 0x101040, was 1.17:1 against black and
        // read as "nothing drawn" on screen.
        double contrast = (luminance(zero) + 0.05) / (luminance(HeatMap.UNCOVERED_ARGB) + 0.05);
        assertTrue(contrast >= 1.5, "an exact pixel is told from one nothing drew: contrast " + contrast);
        assertEquals(zero, HeatMap.colour(-3, 2));
        assertEquals(WHITE, HeatMap.colour(2, 2));
        assertEquals(WHITE, HeatMap.colour(50, 2));
        assertEquals(WHITE, HeatMap.colour(Double.POSITIVE_INFINITY, 2));
        assertNotEquals(WHITE, HeatMap.colour(1.9, 2));
    }

    @Test
    void undefinedIsANeutralGreyTheRampNeverGives() {
        int grey = HeatMap.colour(Double.NaN, 1);
        assertEquals(HeatMap.UNDEFINED_ARGB, grey);
        assertEquals(grey >> 16 & 0xFF, grey & 0xFF);
        assertEquals(grey >> 8 & 0xFF, grey & 0xFF);
        for (int i = 0; i < HeatMap.RAMP_SIZE; i++) {
            int colour = HeatMap.colour(i / (HeatMap.RAMP_SIZE - 1.0), 1);
            assertNotEquals(grey, colour);
            assertNotEquals(HeatMap.UNCOVERED_ARGB, colour);
        }
    }

    @Test
    void legendStopsAgreeWithColour() {
        double max = 3;
        List<HeatMap.LegendStop> stops = HeatMap.legendStops(max);
        assertTrue(stops.size() >= 5);
        assertEquals(0, stops.get(0).pixels());
        assertEquals(max, stops.get(stops.size() - 1).pixels());
        assertEquals(WHITE, stops.get(stops.size() - 1).argb());
        for (int i = 0; i < stops.size(); i++) {
            HeatMap.LegendStop stop = stops.get(i);
            assertEquals(HeatMap.colour(stop.pixels(), max), stop.argb(), "stop " + i);
            if (i > 0) {
                HeatMap.LegendStop before = stops.get(i - 1);
                assertTrue(stop.pixels() > before.pixels());
                // Between stops, colour() is the linear interpolation of the two, to within rounding.
                double mid = (before.pixels() + stop.pixels()) / 2;
                int expected = lerp(before.argb(), stop.argb(), 0.5);
                int actual = HeatMap.colour(mid, max);
                for (int shift = 0; shift <= 16; shift += 8) {
                    int e = expected >> shift & 0xFF;
                    int a = actual >> shift & 0xFF;
                    assertTrue(Math.abs(e - a) <= 4, "channel at " + mid + ": " + a + " vs " + e);
                }
            }
        }
    }

    @Test
    void renderUsesTheRampAndMarksUndefinedAndUncoveredPixels() {
        float nan = Float.NaN;
        float[] displacement = {0, 0.5f, 1, 7, nan, nan, nan, -1};
        double[] uvTest = new double[24];
        double[] uvReference = new double[24];
        uvTest[3 * 4 + 2] = 5; // pixel 4 covered by the test only
        uvReference[3 * 5 + 2] = 5; // pixel 5 by the reference only; pixel 6 by neither
        int[] out = new int[8];

        HeatMap.render(displacement, uvTest, uvReference, 4, 2, 1, out);

        int zero = HeatMap.colour(0, 1);
        int grey = HeatMap.UNDEFINED_ARGB;
        int[] expected = {zero, HeatMap.colour(0.5, 1), WHITE, WHITE, grey, grey, HeatMap.UNCOVERED_ARGB, zero};
        assertArrayEquals(expected, out);

        HeatMap.render(displacement, 4, 2, 1, out);
        expected[6] = grey; // coverage unknown: every NaN is "undefined"
        assertArrayEquals(expected, out);
    }

    @Test
    void badArgumentsAreRejected() {
        int[] out = new int[4];
        float[] d = new float[4];
        assertThrows(IllegalArgumentException.class, () -> HeatMap.colour(1, 0));
        assertThrows(IllegalArgumentException.class, () -> HeatMap.colour(1, Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> HeatMap.legendStops(Double.POSITIVE_INFINITY));
        assertThrows(IllegalArgumentException.class, () -> HeatMap.render(d, 2, 3, 1, out));
        assertThrows(IllegalArgumentException.class, () -> HeatMap.render(d, new double[6], null, 2, 2, 1, out));
    }

    /** Relative luminance (Rec. 709 weights on linearised sRGB), 0..1. */
    private static double luminance(int argb) {
        return 0.2126 * linear(argb >> 16 & 0xFF) + 0.7152 * linear(argb >> 8 & 0xFF) + 0.0722 * linear(argb & 0xFF);
    }

    private static double linear(int channel) {
        double c = channel / 255.0;
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }

    private static int lerp(int a, int b, double u) {
        int rgb = 0;
        for (int shift = 0; shift <= 16; shift += 8) {
            int ca = a >> shift & 0xFF;
            int cb = b >> shift & 0xFF;
            rgb |= (int) Math.round(ca + (cb - ca) * u) << shift;
        }
        return 0xFF000000 | rgb;
    }
}
