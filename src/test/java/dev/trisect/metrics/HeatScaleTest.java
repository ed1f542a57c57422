package dev.trisect.metrics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.texture.internal.BitmapFont;
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
        assertEquals(0xFFFFFFFF, argb[8 * w + 8 + 149], "and ends white");
        int white = 0;
        for (int y = 18; y < 40; y++) {
            for (int x = 0; x < w; x++) {
                white += argb[y * w + x] == 0xFFFFFFFF ? 1 : 0;
            }
        }
        assertTrue(white > 100, "labels under the bar: " + white);
        int[] tiny = new int[10 * 10];
        HeatMap.drawLegend(tiny, 10, 10, HeatScale.linear(2));
        assertEquals(0, tiny[0], "no legend where there is no room for one");
    }

    @Test
    void theImagesLegendSaysWhatTheViewSays() {
        // The view and docs/demo.md label the top "≥ 2 px"; the image's legend once read "2+ PX".
        int w = 240;
        int h = 80;
        int[] argb = new int[w * h];
        HeatMap.drawLegend(argb, w, h, HeatScale.linear(2));
        String top = "\u2265 2 px";
        int x = 8 + 150 - BitmapFont.textWidth(top, 1);
        int[] expected = new int[w * h];
        BitmapFont.drawText(expected, w, h, x, 18, top, 1, 0xFFFFFFFF);
        int inked = 0;
        for (int y = 18; y < 18 + BitmapFont.GLYPH_HEIGHT; y++) {
            for (int i = x - BitmapFont.CELL_WIDTH; i < 8 + 150; i++) {
                boolean white = argb[y * w + i] == 0xFFFFFFFF;
                assertEquals(expected[y * w + i] == 0xFFFFFFFF, white, "pixel " + i + "," + y + " of \"" + top + "\"");
                inked += white ? 1 : 0;
            }
        }
        assertTrue(inked > 30, "the label is drawn: " + inked);
        for (double t : new double[] {0.1, 2, 17.5, 1000, 1e308, 4.9e-324}) {
            for (HeatScale scale : new HeatScale[] {HeatScale.log(t), HeatScale.linear(t)}) {
                for (HeatScale.Label l : scale.labels()) {
                    assertTrue(l.text().chars().allMatch(c -> BitmapFont.hasGlyph((char) c)),
                            "drawn as written, no \"?\": " + l.text());
                }
            }
        }
    }

    /** The legend of a heat map image: text 14 px high on a panel, and what black and grey mean. */
    @Test
    void theImagesLegendIsAPanelWithReadableTextAndTheColoursThatAreNotErrors() {
        int w = 640;
        int h = 360;
        int[] argb = new int[w * h];
        java.util.Arrays.fill(argb, 0xFFFFFFFF);
        HeatMap.drawLegend(argb, w, h, HeatScale.linear(2));
        // The rows the white title text inks, on the panel: its glyphs are 7 font pixels at scale 2.
        int top = -1;
        int bottom = -1;
        int background = 0;
        int black = 0;
        int grey = 0;
        for (int y = 0; y < 120; y++) {
            for (int x = 8; x < 300; x++) {
                int c = argb[y * w + x];
                background += c == HeatMap.LEGEND_BACKGROUND ? 1 : 0;
                black += c == HeatMap.UNCOVERED_ARGB ? 1 : 0;
                grey += c == HeatMap.UNDEFINED_ARGB ? 1 : 0;
            }
        }
        // The title ("LINEAR DISPLACEMENT") is the third line: find its inked rows left of the bar's labels.
        for (int y = 40; y < 90; y++) {
            boolean inked = false;
            for (int x = 8; x < 8 + BitmapFont.textWidth("LINEAR", 2); x++) {
                inked |= argb[y * w + x] == 0xFFFFFFFF;
            }
            if (inked) {
                top = top < 0 ? y : top;
                bottom = y;
            }
        }
        assertTrue(top > 0 && bottom - top + 1 >= 12, "text at least 12 px high: rows " + top + ".." + bottom);
        assertTrue(background > 5000, "on a panel of its own colour: " + background);
        assertTrue(black > 50 && grey > 50, "swatches for not drawn (black) and not comparable (grey): " + black
                + ", " + grey);
    }

    @Test
    void theFittedTopIsTheLargestDisplacement() {
        float[] d = {0.25f, Float.NaN, 1.5f, 0, Float.POSITIVE_INFINITY, 0.75f};
        assertEquals(1.5, HeatScale.log(2).fitted(d).maxPixels(), 0.0);
        assertTrue(HeatScale.log(2).fitted(d).logarithmic());
        assertEquals(1, HeatScale.linear(2).fitted(new float[] {0, Float.NaN}).maxPixels(), 0.0,
                "nothing off: any top shows it");
        assertEquals(HeatScale.LEAST_FITTED_TOP, HeatScale.linear(2).fitted(new float[] {1e-9f}).maxPixels(), 0.0);
    }

    @Test
    void aLogLegendLabelsEveryDecadeAndItsTopIsAFloor() {
        var log = HeatScale.log(2).labels();
        assertEquals(HeatScale.DECADES + 1, log.size());
        assertEquals("0.0002", log.get(0).text());
        assertEquals("0.02", log.get(2).text());
        assertEquals("\u2265 2 px", log.get(HeatScale.DECADES).text(), "values above the top take its colour");
        var linear = HeatScale.linear(2).labels();
        assertEquals(java.util.List.of("0", "1", "\u2265 2 px"), linear.stream().map(HeatScale.Label::text).toList());
    }

    @Test
    void legendLabelsNeverRunIntoEachOther() {
        for (double top : new double[] {0.1, 2, 17.5, 1000, 1e308, Double.MAX_VALUE, 4.9e-324, 1e-320}) {
            for (int barW : new int[] {120, 200, 220}) {
              for (HeatScale scale : new HeatScale[] {HeatScale.log(top), HeatScale.linear(top)}) {
                var placed = HeatScale.layout(scale.labels(), barW, t -> 7 * t.length(), 6);
                for (int i = 1; i < placed.size(); i++) {
                    int prevEnd = placed.get(i - 1).x() + 7 * placed.get(i - 1).text().length();
                    assertTrue(placed.get(i).x() >= prevEnd + 6, placed + " on " + barW + " px");
                }
                assertTrue(placed.size() == 1 || placed.get(0).x() == 0, "the bottom at the bar's left: " + placed);
                assertTrue(placed.get(placed.size() - 1).text().startsWith("\u2265"));
                assertTrue(placed.get(placed.size() - 1).x() >= 0, "the top label fits the bar: " + placed);
              }
            }
        }
        assertEquals(5, HeatScale.layout(HeatScale.log(2).labels(), 260, t -> 6 * t.length(), 6).size(),
                "all five fit on the view's legend");
    }

    @Test
    void numbersStayShortAtTheEndsOfTheDoubles() {
        assertEquals("1e308", HeatScale.number(1e308));
        assertEquals("1.8e308", HeatScale.number(Double.MAX_VALUE));
        assertEquals("4.94e-324", HeatScale.number(4.9e-324));
        assertEquals("0.0002", HeatScale.number(2e-4));
        assertEquals("2e-5", HeatScale.number(2e-5));
        assertEquals("0.002", HeatScale.number(0.002));
        assertEquals("17.5", HeatScale.number(17.5));
        assertEquals("99999", HeatScale.number(99999));
        assertEquals("1e5", HeatScale.number(1e5));
        assertEquals(java.util.List.of("0", "\u2265 4.94e-324 px"),
                HeatScale.linear(4.9e-324).labels().stream().map(HeatScale.Label::text).toList(),
                "half the smallest double rounds to 0: no second 0 in the middle");
        assertEquals("\u2265 1e308 px", HeatScale.log(1e308).labels().get(4).text());
    }
}
