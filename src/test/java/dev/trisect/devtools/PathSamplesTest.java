package dev.trisect.devtools;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The per-path bars read the median and spread of several comparisons, not one sample. */
class PathSamplesTest {
    @Test
    void oneSlowSampleMovesNeitherTheMedianNorHidesInTheSpread() {
        PathSamples s = new PathSamples();
        // The spans path once read 116 ms against its usual 5-16 ms: one slow frame among ordinary ones.
        double[][] timings = {{40, 20, 30, 8}, {42, 21, 29, 9}, {41, 19, 31, 116}, {39, 20, 30, 10}, {40, 22, 28, 9}};
        for (double[] t : timings) {
            s.offer(t);
        }
        assertEquals(5, s.count());
        assertEquals(9, s.median(3), "the median of 8, 9, 9, 10, 116");
        assertEquals(8, s.min(3));
        assertEquals(116, s.max(3), "the spread shows the slow one");
        assertEquals("9.0 ms (8.0\u2013116.0)", TimingSection.PathBars.text(s, 3));
        assertEquals(40, s.median(0));
    }

    @Test
    void theSameTimingsReadTwiceCountOnceAndAnotherSceneClearsThem() {
        PathSamples s = new PathSamples();
        double[] t = {1, 2, 3, 4};
        s.offer(t);
        s.offer(t);
        assertEquals(1, s.count(), "refreshed between comparisons: one sample");
        assertEquals("4.0 ms", TimingSection.PathBars.text(s, 3));
        for (int i = 0; i < 20; i++) {
            s.offer(new double[] {i, i, i, i});
        }
        assertEquals(PathSamples.CAPACITY, s.count(), "the last few only");
        assertEquals(19 - PathSamples.CAPACITY + 1, s.min(0));
        s.offer(null);
        assertEquals(0, s.count());
    }
}
