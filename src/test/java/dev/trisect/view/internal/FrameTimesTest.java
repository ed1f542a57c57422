package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import org.junit.jupiter.api.Test;

/** The frame-time graph's data: stages that add up to the whole frame, the last five seconds, every path's time. */
class FrameTimesTest {
    @Test
    void stagesAddUpToTheFrameAndOtherTakesTheRest() {
        FrameTimes t = new FrameTimes();
        t.add(new double[] {1, 2, 3, 4, 0.5, 6, 1.5}, 20);
        double[] row = t.snapshot()[0];
        assertEquals(FrameTimes.STAGES.length, row.length);
        assertEquals(2, row[FrameTimes.STAGES.length - 1], 1e-12, "other: what no stage claims");
        double sum = 0;
        for (double v : row) {
            sum += v;
        }
        assertEquals(20, sum, 1e-12);
    }

    @Test
    void keepsTheLastFramesOldestFirst() {
        FrameTimes t = new FrameTimes();
        for (int i = 0; i < FrameTimes.CAPACITY + 7; i++) {
            t.add(new double[] {i, 0, 0, 0, 0, 0, 0}, i);
        }
        double[][] s = t.snapshot();
        assertEquals(FrameTimes.CAPACITY, s.length);
        assertEquals(7, s[0][0]);
        assertEquals(FrameTimes.CAPACITY + 6, s[s.length - 1][0]);
    }

    @Test
    void theLoopRecordsEveryStageAndEachPathsTime() throws Exception {
        ViewState state = new ViewState(DemoScenes.floor());
        state.viewSize(160, 90);
        state.toolsOpen(true);
        state.settings(ViewSettings.defaults().withRender(ViewSettings.defaults().render().withBorders(true)));
        TripleBuffer buffers = new TripleBuffer();
        RenderLoop loop = new RenderLoop(state, buffers, () -> { }, 1);
        Thread t = new Thread(loop, "test-render");
        t.start();
        try {
            for (int poll = 0; poll < 1500 && (state.frameTimes.added() < 12 || state.pathMs() == null); poll++) {
                Thread.sleep(20);
            }
        } finally {
            loop.stop();
            t.join(5000);
        }
        double[][] frames = state.frameTimes.snapshot();
        assertTrue(frames.length >= 12);
        boolean compared = false;
        for (double[] f : frames) {
            for (double v : f) {
                assertTrue(v >= 0);
            }
            assertTrue(f[3] > 0, "raster takes time every frame");
            assertTrue(f[4] > 0, "so does the overlay, with borders on");
            compared |= f[5] > 0;
        }
        assertTrue(compared, "frames that measure show the comparison's cost");
        double[] paths = state.pathMs();
        assertNotNull(paths);
        for (double p : paths) {
            assertTrue(p > 0, "all three paths timed on the measured frame");
        }
    }
}
