package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.render.Framebuffer;
import java.lang.ref.WeakReference;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A view made small again gives back its large frames in a still view too: it drew one frame at the new
 * size and idled, so the other two frame slots kept frames of the old size (12 bytes a pixel each) and
 * the per-pixel frame of the developer tools stayed (36 bytes a pixel) after they closed — 60 MB of a
 * 1920x1080 window, until something moved.
 */
class ResizeReleaseTest {
    /** Waits (bounded, polling) until the loop has drawn {@code frames} frames in all. */
    private static void awaitFrames(ViewState state, long frames) throws InterruptedException {
        for (int poll = 0; poll < 15000 && state.progress().frames() < frames; poll++) {
            Thread.sleep(2);
        }
        assertTrue(state.progress().frames() >= frames, "the loop draws");
    }

    @Test
    void aViewMadeSmallLetsItsLargeFramesGo() throws Exception {
        ViewState state = new ViewState(DemoScenes.floor());
        state.viewSize(800, 500);
        TripleBuffer buffers = new TripleBuffer();
        List<WeakReference<Framebuffer>> large = new ArrayList<>();
        FrameSlot[] showing = new FrameSlot[1];
        // The event thread's part: each frame published is acquired, as a paint does.
        Runnable paint = () -> {
            showing[0] = buffers.acquire(showing[0]);
            if (showing[0] != null && showing[0].is(800, 500)
                    && large.stream().noneMatch(r -> r.get() == showing[0].frame)) {
                large.add(new WeakReference<>(showing[0].frame));
            }
        };
        RenderLoop loop = new RenderLoop(state, buffers, paint, 1);
        Thread t = new Thread(loop, "test-render");
        // The tools open: frames keep coming (their live chart), each slot gets a large frame, and the
        // per-pixel frame is drawn for the comparison.
        state.toolsOpen(true);
        t.start();
        try {
            for (int poll = 0; poll < 15000 && (large.size() < 3 || state.measurement() == null); poll++) {
                Thread.sleep(2);
            }
            assertEquals(3, large.size(), "three frame slots drawn large");
            state.toolsOpen(false);
            state.viewSize(80, 50);
            // The small frames: until the loop idles (a still view), bounded.
            long drawn;
            do {
                drawn = state.progress().frames();
                Thread.sleep(300);
            } while (state.progress().frames() != drawn);
            assertTrue(showing[0].is(80, 50), "the small frame is on screen");
            assertNull(loop.drawer().reference(), "the per-pixel frame goes with the tools");
        } finally {
            loop.stop();
            t.join(10_000);
        }
        for (int i = 0; i < 20 && large.stream().anyMatch(r -> r.get() != null); i++) {
            System.gc();
            Thread.sleep(20);
        }
        assertEquals(0, large.stream().filter(r -> r.get() != null).count(), "large frames still held");
    }
}
