package dev.trisect.pipeline;

import dev.trisect.render.RenderSettings;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Viewport;
import dev.trisect.raster.Commands;
import dev.trisect.render.Framebuffer;
import dev.trisect.texture.Texture;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicIntegerArray;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The worker pool's contract (issue 14, item 1): every index once; a failure of any task on any
 * thread — an out-of-memory error included — ends the run on all threads and is rethrown on the
 * calling thread, which always returns; the helper threads survive it, parked, and the pool draws the
 * next run; a closed pool says so. Timeouts guard against the hang this replaces.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class WorkerPoolTest {
    /** A frame without lines. */
    private static final Commands[] NO_LINES = {};
    /** The pool's helper threads, found by name. */
    private static List<Thread> helpers(String name) {
        List<Thread> found = new ArrayList<>();
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t.getName().startsWith(name + "-")) {
                found.add(t);
            }
        }
        return found;
    }

    /** Waits until every helper of the pool is parked between runs (alive, waiting, not running a task). */
    private static void assertHelpersParked(String name, int count) throws InterruptedException {
        List<Thread> hs = helpers(name);
        assertEquals(count, hs.size(), "helper threads of " + name);
        for (Thread t : hs) {
            // Bounded waiting, not timing: up to 10,000 polls 1 ms apart.
            for (int poll = 0; poll < 10_000 && t.getState() != Thread.State.WAITING; poll++) {
                Thread.sleep(1);
            }
            assertTrue(t.isAlive(), t.getName() + " is alive");
            assertEquals(Thread.State.WAITING, t.getState(), t.getName() + " parked between runs");
        }
    }

    @Test
    void aHelperThatCannotStartStopsTheOnesStartedBeforeIt() throws InterruptedException {
        // The third of five helpers fails to start, as a start does when the system is out of threads:
        // the constructor rethrows, and the two started before it end instead of waiting for work for good.
        List<Thread> made = new ArrayList<>();
        OutOfMemoryError refused = new OutOfMemoryError("unable to create native thread (simulated)");
        OutOfMemoryError e = assertThrows(OutOfMemoryError.class, () -> new WorkerPool(6, "pool-test-start",
                (r, n) -> {
                    Thread t = made.size() == 2 ? new Thread(r, n) {
                        @Override
                        public synchronized void start() {
                            throw refused;
                        }
                    } : new Thread(r, n);
                    made.add(t);
                    return t;
                }));
        assertSame(refused, e);
        assertEquals(5, made.size());
        for (Thread t : made) {
            t.join(10_000);
            assertTrue(!t.isAlive(), t.getName() + " ended");
        }
    }

    @Test
    void everyIndexRunsOnceOnAnyThreadCount() {
        for (int threads = 1; threads <= 4; threads++) {
            try (WorkerPool pool = new WorkerPool(threads, "pool-test-count")) {
                for (int count : new int[] {0, 1, 2, 3, 7, 1000}) {
                    AtomicIntegerArray runs = new AtomicIntegerArray(Math.max(1, count));
                    pool.run(count, (thread, index) -> runs.incrementAndGet(index));
                    for (int i = 0; i < count; i++) {
                        assertEquals(1, runs.get(i), "index " + i + " of " + count + " on " + threads + " threads");
                    }
                }
            }
        }
    }

    @Test
    void anOutOfMemoryErrorOnAHelperEndsTheRunAndIsRethrownAsItself() throws InterruptedException {
        String name = "pool-test-oom";
        try (WorkerPool pool = new WorkerPool(3, name)) {
            OutOfMemoryError oom = new OutOfMemoryError("Java heap space (thrown by the test)");
            AtomicInteger started = new AtomicInteger();
            AtomicInteger startedAfterFailure = new AtomicInteger();
            AtomicInteger failedAt = new AtomicInteger(-1);
            OutOfMemoryError thrown = assertThrows(OutOfMemoryError.class, () -> pool.run(10_000, (thread, index) -> {
                started.incrementAndGet();
                // After the pool recorded the failure, not after the test's own flag: between the flag and
                // the throw's record a loaded machine may deschedule the failing helper, and the others rightly
                // take more tasks in that gap (seen: 4).
                if (pool.failed()) {
                    startedAfterFailure.incrementAndGet();
                }
                sleep();
                if (thread != 0 && failedAt.compareAndSet(-1, index)) {
                    throw oom;
                }
            }));
            assertSame(oom, thrown, "the failure itself, not a wrapper");
            assertTrue(failedAt.get() >= 0, "a helper threw");
            // Tasks that had already looked for a failure before it was recorded may still start:
            // at most one per other thread.
            assertTrue(startedAfterFailure.get() <= 2, "tasks taken after the failure: " + startedAfterFailure);
            assertTrue(started.get() < 10_000, "the run stopped early: " + started);
            assertHelpersParked(name, 2);
            assertNextRunIsWhole(pool);
        }
    }

    @Test
    void aRuntimeExceptionOnTheCallingThreadIsRethrownAfterTheHelpersStop() throws InterruptedException {
        String name = "pool-test-caller";
        try (WorkerPool pool = new WorkerPool(2, name)) {
            IllegalArgumentException boom = new IllegalArgumentException("boom");
            AtomicInteger active = new AtomicInteger();
            AtomicInteger activeAtReturn = new AtomicInteger(-1);
            RuntimeException thrown = assertThrows(RuntimeException.class, () -> {
                try {
                    pool.run(1000, (thread, index) -> {
                        active.incrementAndGet();
                        try {
                            sleep();
                            if (thread == 0) {
                                throw boom;
                            }
                        } finally {
                            active.decrementAndGet();
                        }
                    });
                } finally {
                    activeAtReturn.set(active.get());
                }
            });
            assertSame(boom, thrown);
            assertEquals(0, activeAtReturn.get(), "no task still running when run returns");
            assertHelpersParked(name, 1);
            assertNextRunIsWhole(pool);
        }
    }

    @Test
    void errorsStayErrorsAndTheFirstFailureWins() {
        try (WorkerPool pool = new WorkerPool(3, "pool-test-errors")) {
            StackOverflowError deep = new StackOverflowError("thrown by the test");
            assertSame(deep, assertThrows(StackOverflowError.class, () -> pool.run(100, (thread, index) -> {
                throw deep;
            })));
            // Every thread fails: one of their failures is rethrown, the others are dropped.
            RuntimeException e = assertThrows(RuntimeException.class, () -> pool.run(100, (thread, index) -> {
                sleep();
                throw new IllegalStateException("from thread " + thread);
            }));
            assertTrue(e.getMessage().startsWith("from thread "), e.getMessage());
            assertNextRunIsWhole(pool);
        }
    }

    @Test
    void anInterruptedCallerStillWaitsForItsHelpersAndKeepsTheInterrupt() {
        try (WorkerPool pool = new WorkerPool(3, "pool-test-interrupt")) {
            AtomicInteger done = new AtomicInteger();
            Thread.currentThread().interrupt();
            try {
                pool.run(30, (thread, index) -> {
                    sleep();
                    done.incrementAndGet();
                });
                assertTrue(Thread.currentThread().isInterrupted(), "the interrupt is kept");
            } finally {
                Thread.interrupted();
            }
            assertEquals(30, done.get());
        }
    }

    @Test
    void aClosedPoolSaysSo() {
        for (int threads : new int[] {1, 2}) {
            WorkerPool pool = new WorkerPool(threads, "pool-test-closed");
            pool.run(3, (thread, index) -> {
            });
            pool.close();
            pool.close();
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> pool.run(3, (thread, index) -> {
            }));
            assertTrue(e.getMessage().contains("closed"), e.getMessage());
        }
    }

    @Test
    void aRendererRecoversFromAFailedFrameAndRefusesWorkAfterClose() {
        SceneAsset scene = DemoScenes.boxes();
        Texture[] good = scene.textureArray();
        // A missing texture is refused before the frame starts (Draws.add names the material); the pool's
        // own tests above cover failures inside the tasks.
        Texture[] broken = good.clone();
        broken[broken.length - 1] = null;
        var vp = scene.camera().viewProjection(new Viewport(160, 120));
        RenderSettings s = RenderSettings.defaults().withBorders(true);
        Framebuffer expected = new Framebuffer(160, 120);
        try (FrameRenderer fresh = new FrameRenderer(1)) {
            fresh.render(scene.mesh(), good, vp, s, expected);
        }
        FrameRenderer r = new FrameRenderer(3);
        for (int i = 0; i < 3; i++) {
            IllegalArgumentException missing = assertThrows(IllegalArgumentException.class,
                    () -> r.render(scene.mesh(), broken, vp, s, new Framebuffer(160, 120)));
            assertTrue(missing.getMessage().contains("is null"), missing.getMessage());
            Framebuffer after = new Framebuffer(160, 120);
            r.render(scene.mesh(), good, vp, s, after);
            assertArrayEquals(expected.colour(), after.colour(), "the frame after a failed one is right");
        }
        r.close();
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> r.render(scene.mesh(), good, vp, s, new Framebuffer(160, 120)));
        assertTrue(e.getMessage().contains("closed"), e.getMessage());
    }

    @Test
    void aFailureInsideABandPassEndsItAndTheNextPassIsRight() throws InterruptedException {
        // Three chunks of one triangle each, filled with the overlay: the middle chunk's triangle names
        // a material with no texture, which fails inside the band tasks on whichever thread takes them.
        Texture grey = new Texture("grey", 2, 2, new int[] {0xFF808080, 0xFF808080, 0xFF808080, 0xFF808080});
        Texture[] textures = {grey};
        int w = 64;
        int h = 48;
        Chunks chunks = new Chunks();
        chunks.ensure(3);
        RenderSettings s = RenderSettings.defaults().withBorders(true);
        String name = "pool-test-bands";
        try (WorkerPool pool = new WorkerPool(3, name)) {
            BandPass bands = new BandPass(3);
            Outlines outlines = new Outlines(3);
            Framebuffer expected = null;
            for (int frame = 0; frame < 4; frame++) {
                boolean broken = frame % 2 == 0;
                for (int c = 0; c < 3; c++) {
                    Chunk chunk = chunks.get(c);
                    chunk.clear();
                    double x = 4 + 20 * c;
                    chunk.out.add(x, 2, 1, 0, 0, x + 16, 40, 1, 2, 0, x, 44, 1, 0, 2, c,
                            broken && c == 1 ? 5 : 0);
                    chunk.commands.add(Commands.TRIANGLE, 0, chunk.out.firstRow(0), chunk.out.endRow(0));
                    chunk.bin(h);
                }
                Framebuffer fb = new Framebuffer(w, h);
                if (broken) {
                    assertThrows(ArrayIndexOutOfBoundsException.class,
                            () -> bands.draw(fb, chunks, 3, textures, null, null, s, null, outlines, NO_LINES, 0, pool));
                    assertHelpersParked(name, 2);
                } else {
                    BandPass.Result result = bands.draw(fb, chunks, 3, textures, null, null, s, null, outlines, NO_LINES, 0, pool);
                    assertTrue(result.pixels() > 0);
                    if (expected == null) {
                        expected = fb;
                    } else {
                        assertArrayEquals(expected.colour(), fb.colour(), "the pass after a failed one is whole");
                    }
                }
            }
        }
    }

    private static void assertNextRunIsWhole(WorkerPool pool) {
        AtomicIntegerArray runs = new AtomicIntegerArray(500);
        pool.run(500, (thread, index) -> runs.incrementAndGet(index));
        for (int i = 0; i < 500; i++) {
            assertEquals(1, runs.get(i), "index " + i + " of the next run");
        }
    }

    private static void sleep() {
        try {
            Thread.sleep(1);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
