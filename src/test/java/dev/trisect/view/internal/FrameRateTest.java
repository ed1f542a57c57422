package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The frame rate the status bar and the developer tools show, on a made-up clock. */
class FrameRateTest {
    private static final long MS = 1_000_000L;

    /** Shows frames every {@code stepMs} from {@code fromMs} for {@code count} frames; returns the last rate. */
    private static double run(FrameRate rate, long fromMs, long stepMs, int count, double atLeast) {
        double fps = rate.fps();
        for (int i = 0; i < count; i++) {
            fps = rate.frameShown((fromMs + i * stepMs) * MS);
            assertTrue(fps >= atLeast, "frame " + i + " from " + fromMs + " ms: " + fps + " fps");
        }
        return fps;
    }

    @Test
    void framesEvenlySpacedGiveTheirRate() {
        FrameRate rate = new FrameRate();
        run(rate, 0, 20, 51, 0);
        assertEquals(50, rate.fps(), 1e-9, "50 frames a second, 20 ms apart");
        run(rate, 1040, 40, 25, 0);
        assertEquals(25, rate.fps(), 1e-9, "then 25");
    }

    @Test
    void aPauseIsNotCountedAsASlowSecond() {
        FrameRate rate = new FrameRate();
        run(rate, 0, 10, 150, 0);
        assertEquals(100, rate.fps(), 1e-9);
        // Frozen (or minimized) for 5 s, after 0.49 s of the second in progress; the loop says so each turn.
        for (long t = 1500; t < 6500; t += 15) {
            rate.pause();
        }
        // Drawing resumes at 100 frames a second: the rate never reads the pause as frames missing
        // (it read 9 fps for a second: 50 frames over 5.5 s), and is renewed a second on.
        double fps = run(rate, 6500, 10, 120, 99.99);
        assertEquals(100, fps, 1e-9);
    }

    @Test
    void noRateBeforeTheFirstWholeSecond() {
        FrameRate rate = new FrameRate();
        assertEquals(0, run(rate, 0, 10, 100, 0), "99 intervals, 0.99 s: not yet a whole second");
        assertEquals(100, rate.frameShown(1000 * MS), 1e-9);
    }
}
