package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.devtools.CliArgs;
import dev.trisect.cli.Cli;
import dev.trisect.content.DemoScenes;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Freeze and step, as a rule and in the running render loop; the camera readout's copied options. */
class FreezeGateTest {
    @TempDir
    Path dir;

    @Test
    void frozenHoldsStepsOnceAndRedrawsOnlyForNewSettings() {
        FreezeGate g = new FreezeGate();
        ViewSettings a = ViewSettings.defaults();
        assertEquals(FreezeGate.Action.RUN, g.next(a, 1));
        g.freeze(true);
        assertFalse(g.holding(), "frozen, but the loop has not yet come back from the frame it was drawing");
        assertEquals(FreezeGate.Action.HOLD, g.next(a, 1), "the frame last drawn stays");
        assertTrue(g.holding());
        assertEquals(FreezeGate.Action.HOLD, g.next(a, 1));
        g.step();
        g.step();
        assertEquals(FreezeGate.Action.STEP, g.next(a, 1));
        assertFalse(g.holding(), "a step is under way");
        assertEquals(FreezeGate.Action.STEP, g.next(a, 1));
        assertEquals(FreezeGate.Action.HOLD, g.next(a, 1), "one frame per step");
        ViewSettings b = a.withRender(a.render().withBorders(true));
        assertEquals(FreezeGate.Action.REDRAW, g.next(b, 1), "a setting changed: same frame, redrawn");
        assertEquals(FreezeGate.Action.HOLD, g.next(b, 1));
        assertEquals(FreezeGate.Action.REDRAW, g.next(b, 2), "the view was resized");
        g.step();
        g.freeze(false);
        assertEquals(FreezeGate.Action.RUN, g.next(b, 2), "thawing drops pending steps");
        assertFalse(g.frozen());
        g.step();
        assertTrue(g.frozen(), "a step while running freezes");
    }

    @Test
    void theLoopStopsOnAFrameStepsOneAndMeasuresTheFrozenFrame() throws Exception {
        ViewState state = new ViewState(DemoScenes.floor());
        state.viewSize(96, 64);
        state.toolsOpen(true);
        state.input.orbit(true);
        TripleBuffer buffers = new TripleBuffer();
        RenderLoop loop = new RenderLoop(state, buffers, () -> { }, 1);
        Thread t = new Thread(loop, "test-render");
        t.start();
        try {
            for (int poll = 0; poll < 1000 && state.progress().frames() < 3; poll++) {
                Thread.sleep(10);
            }
            state.freeze.freeze(true);
            // A frame under way still arrives: wait (bounded) until the loop holds, not a fixed 100 ms,
            // which a frame can outlast on a loaded machine.
            for (int poll = 0; poll < 1000 && !state.freeze.holding(); poll++) {
                Thread.sleep(10);
            }
            assertTrue(state.freeze.holding(), "the loop holds the frozen frame");
            long frozenAt = state.progress().frames();
            Thread.sleep(300);
            assertEquals(frozenAt, state.progress().frames(), "no frames while frozen");
            FrameSlot before = buffers.acquire(null);
            state.freeze.step();
            for (int poll = 0; poll < 1000 && state.progress().frames() == frozenAt; poll++) {
                Thread.sleep(10);
            }
            Thread.sleep(200);
            assertEquals(frozenAt + 1, state.progress().frames(), "exactly one frame per step");
            FrameSlot after = buffers.acquire(before);
            assertEquals(before.serial + 1, after.serial);
            double moved = after.camera.eye().sub(before.camera.eye()).length();
            assertTrue(moved > 0, "the orbit moved on by one step");
            assertEquals(after.serial, state.measurement().frame(), "the numbers are the frozen frame's");
        } finally {
            loop.stop();
            t.join(5000);
        }
    }

    @Test
    void theCopiedCameraOptionsAreWhatTheCommandLineReadsBack() {
        dev.trisect.scene.Camera c = dev.trisect.scene.Camera.looking(new dev.trisect.math.Vec3(1.25, 2.5, -3.75),
                new dev.trisect.math.Vec3(0.1, 0.2, 0.3));
        String options = CliArgs.cameraOptions(c);
        List<String> args = new ArrayList<>(List.of("export", "--scene", "floor", "--to",
                dir.resolve("f.obj").toString()));
        args.addAll(List.of(options.split(" ")));
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        assertEquals(0, Cli.run(new PrintWriter(out, true), new PrintWriter(err, true), args.toArray(String[]::new)),
                err.toString());
        assertTrue(out.toString().contains("camera: " + options), out + " vs " + options);
    }
}
