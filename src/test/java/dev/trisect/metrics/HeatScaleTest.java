package dev.trisect.metrics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Linear and logarithmic heat map scales, and the legend drawn into heat map images. */
class HeatScaleTest {
    @Test
    void aLogScaleTellsHalfAPixelFromAThousand() {
        HeatScale lin = HeatScale.linear(1000);
        HeatScale log = HeatScale.log(1000);
        assertEquals(HeatMap.colour(0, lin), HeatMap.colour(0.5, lin), "linear to 1000 px: 0.5 px is lost");
        assertNotEquals(HeatMap.colour(0, log), HeatMap.colour(0.5, log), "log: 0.5 px reads");
        assertNotEquals(HeatMap.colour(0.5, log), HeatMap.colour(5, log));
        assertNotEquals(HeatMap.colour(100, log), HeatMap.colour(1000, log));
        assertEquals(0xFFFFFFFF, HeatMap.colour(1000, log));
        assertEquals(0.75, log.fraction(100), 1e-12, "each decade is a quarter of the bar");
        assertEquals(0.1, log.minPixels(), 1e-12);
        assertEquals(0, log.fraction(0));
        assertEquals(1, log.fraction(1e9));
        assertTrue(Double.isNaN(log.fraction(Double.NaN)));
    }

    @Test
    void fractionAndPixelsAtAreInverse() {
        for (HeatScale s : new HeatScale[] {HeatScale.linear(2), HeatScale.log(2), HeatScale.log(1000)}) {
            for (double f = 0.05; f <= 1; f += 0.05) {
                assertEquals(f, s.fraction(s.pixelsAt(f)), 1e-9, s.describe());
            }
        }
        assertEquals("linear 0-2 px", HeatScale.linear(2).describe());
        assertEquals("log 0.0002-2 px", HeatScale.log(2).describe());
        assertThrows(IllegalArgumentException.class, () -> HeatScale.log(0));
    }

    @Test
    void linearScaleColoursAreTheOriginalOnes() {
        for (double v : new double[] {0, 0.1, 0.7, 1.3, 2, 5}) {
            assertEquals(HeatMap.colour(v, 2.0), HeatMap.colour(v, HeatScale.linear(2)), "at " + v);
        }
    }

    @Test
    void theLegendIsDrawnIntoTheImage() {
        int w = 240;
        int h = 80;
        int[] argb = new int[w * h];
        HeatMap.drawLegend(argb, w, h, HeatScale.log(1000));
        assertEquals(HeatMap.colour(0, 1), argb[8 * w + 8], "the bar starts at the ramp's first colour");
        assertEquals(0xFFFFFFFF, argb[8 * w + 8 + 199], "and ends white");
        int white = 0;
        for (int y = 21; y < 40; y++) {
            for (int x = 0; x < w; x++) {
                white += argb[y * w + x] == 0xFFFFFFFF ? 1 : 0;
            }
        }
        assertTrue(white > 100, "labels under the bar: " + white);
        int[] tiny = new int[10 * 10];
        HeatMap.drawLegend(tiny, 10, 10, HeatScale.linear(2));
        assertEquals(0, tiny[0], "no legend where there is no room for one");
    }
}
