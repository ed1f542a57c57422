package dev.trisect.view.internal;

import static dev.trisect.GuiTests.waitFor;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Transform;
import dev.trisect.mesh.Primitives;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.texture.ProceduralTextures;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/**
 * Frames only when needed: the render loop draws a still scene once and then idles, and draws again
 * for each change (scene, settings, size, camera) or while something animates; the cap bounds the
 * frame rate. Counts frames, never times them (the cap and the steps are checked on a stepped clock).
 */
class FrameDemandTest {
    private static long frames(ViewState state) {
        return state.progress().frames();
    }

    /** A loop's frames stay at {@code n} for a while: it idles. */
    private static void idlesAt(ViewState state, long n, String when) throws InterruptedException {
        // The loop publishes progress right after a frame; any frame drawn meanwhile would show here.
        Thread.sleep(250);
        assertEquals(n, frames(state), "no frames " + when);
    }

    @Test
    void aStillSceneIsDrawnOnceAndEachChangeOnceMore() throws Exception {
        Scene scene = new Scene();
        SceneObject box = new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.crate(64)));
        scene.add(box);
        ViewState state = new ViewState(scene, Camera.looking(new dev.trisect.math.Vec3(0, 2, 4),
                dev.trisect.math.Vec3.ZERO));
        state.viewSize(64, 48);
        // No looking for changes while idle (it looked every 10 ms): each change below must wake the loop
        // itself, or its frame never comes and the wait times out. Stopping must wake it too.
        state.demand.idleLook = Long.MAX_VALUE / 4;
        AtomicBoolean animate = new AtomicBoolean();
        AtomicInteger hooks = new AtomicInteger();
        RenderLoop loop = new RenderLoop(state, new TripleBuffer(), () -> { }, 1);
        loop.listener(new RenderLoop.LoopListener() {
            @Override
            public void frameDone(FrameReport report) {
            }

            @Override
            public void problem(String message) {
                throw new AssertionError(message);
            }

            @Override
            public boolean update(double seconds, long frame) {
                hooks.incrementAndGet();
                return animate.get();
            }
        });
        Thread t = new Thread(loop, "test-render");
        t.start();
        try {
            waitFor("the first frame", () -> frames(state) >= 1);
            idlesAt(state, 1, "while nothing changes");
            assertEquals(1, hooks.get(), "the hook runs before frames drawn, only");

            box.setTransform(Transform.translation(0.5, 0, 0));
            waitFor("a frame for the moved object", () -> frames(state) >= 2);
            idlesAt(state, 2, "after the moved object's frame");

            state.updateSettings(s -> s.withRenderScale(0.5));
            waitFor("a frame for the new settings", () -> frames(state) >= 3);
            idlesAt(state, 3, "after the new settings' frame");

            state.camera(Camera.looking(new dev.trisect.math.Vec3(1, 2, 4), dev.trisect.math.Vec3.ZERO));
            waitFor("a frame for the new camera", () -> frames(state) >= 4);
            state.viewSize(80, 60);
            waitFor("a frame for the new size", () -> frames(state) >= 5);
            scene.add(new SceneObject(Primitives.box(1, 1, 1), Material.colour(0xFF0000)));
            waitFor("a frame for the added object", () -> frames(state) >= 6);
            idlesAt(state, 6, "after the added object's frame");

            // A hook that animates keeps frames coming; when it stops, so do they.
            animate.set(true);
            state.demand.request();
            waitFor("frames while the hook animates", () -> frames(state) >= 12);
            animate.set(false);
            long stopped = frames(state);
            Thread.sleep(100);
            long settled = frames(state);
            assertTrue(settled <= stopped + 2, "at most the frames under way when the hook stopped");
            idlesAt(state, settled, "once the hook stops animating");

            // A reason registered from outside (the developer tools' live graph) keeps them coming too.
            state.demand.keepDrawing("graph", true);
            waitFor("frames while a reason is registered", () -> frames(state) >= settled + 5);
            state.demand.keepDrawing("graph", false);
            long last = frames(state);
            idlesAt(state, last, "once the reason is gone");
            state.input.press(InputState.FORWARD);
            waitFor("a frame for a key", () -> frames(state) > last);
            state.input.release(InputState.FORWARD);
        } finally {
            loop.stop();
            t.join(5000);
        }
        assertTrue(!t.isAlive(), "an idle loop stops when asked, without a look to wait for");
    }

    /**
     * A clock that moves only when read (a microsecond a reading) and when the loop waits (by the
     * wait): the pace and the steps it gives are then exact, however fast the machine runs.
     */
    private static final class SteppedClock implements FrameClock {
        private final AtomicLong now = new AtomicLong(1_000_000_000L);

        @Override
        public long nanos() {
            return now.addAndGet(1_000);
        }

        @Override
        public void park(long nanos) {
            now.addAndGet(nanos);
        }
    }

    /**
     * Frames that keep coming (an animation) start at least 1/cap apart, and the update hooks' steps
     * add up to the time between them: both read from the loop's clock, a stepped one here, so the
     * test times nothing.
     */
    @Test
    void animatedFramesKeepToTheCapAndTheStepsAddUpToTheClock() throws Exception {
        ViewState state = new ViewState(dev.trisect.content.DemoScenes.floor());
        state.viewSize(32, 24);
        state.maxFrameRate(20);
        SteppedClock clock = new SteppedClock();
        state.demand.clock = clock;
        state.demand.keepDrawing("test", true);
        List<double[]> calls = new CopyOnWriteArrayList<>();
        RenderLoop loop = new RenderLoop(state, new TripleBuffer(), () -> { }, 1);
        loop.listener(new RenderLoop.LoopListener() {
            @Override
            public void frameDone(FrameReport report) {
                loop.framePainted(report.frame());
            }

            @Override
            public void problem(String message) {
                throw new AssertionError(message);
            }

            @Override
            public boolean update(double seconds, long frame) {
                calls.add(new double[] {seconds, frame, clock.nanos()});
                return false;
            }
        });
        Thread t = new Thread(loop, "test-render");
        t.start();
        try {
            waitFor("thirty frames", () -> calls.size() >= 30);
        } finally {
            loop.stop();
            t.join(5000);
        }
        List<double[]> c = List.copyOf(calls);
        double sum = 0;
        for (int i = 1; i < c.size(); i++) {
            double step = c.get(i)[0];
            assertTrue(step >= 1 / 20.0, "frame " + (long) c.get(i)[1] + " came " + step + " s after the one before, under a cap of 20");
            assertTrue(step < 1 / 20.0 + 0.001, "step " + step + ": the loop waited longer than the cap asks");
            assertEquals(c.get(i - 1)[1] + 1, c.get(i)[1], "one call per frame, numbered in order");
            sum += step;
        }
        double elapsed = (c.get(c.size() - 1)[2] - c.get(0)[2]) / 1e9;
        // Each step is read a few clock readings (microseconds) before its hook reads the clock.
        assertEquals(elapsed, sum, 1e-4, c.size() + " steps against the clock");
    }

    @Test
    void aFrameTimeTargetRaisesTheCapToItsRate() {
        ViewState state = new ViewState(dev.trisect.content.DemoScenes.floor());
        state.maxFrameRate(60);
        assertEquals(60, FrameDemand.cap(state), 0.0);
        // Auto at 10 ms under the screen's 60 Hz cap could never show the 100 fps it aims for.
        state.budget(new ViewState.Budget(true, 10));
        assertEquals(100, FrameDemand.cap(state), 1e-9);
        state.budget(new ViewState.Budget(true, 40));
        assertEquals(60, FrameDemand.cap(state), 0.0, "a slower target keeps the cap");
        state.maxFrameRate(0);
        assertEquals(0, FrameDemand.cap(state), 0.0, "no cap stays none");
    }
}
