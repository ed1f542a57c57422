package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.AssetScenes;
import dev.trisect.devtools.CliArgs;
import dev.trisect.cli.Cli;
import dev.trisect.content.DemoScenes;
import dev.trisect.devtools.CliArgs;
import dev.trisect.metrics.Comparison;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.SplitPolicy;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/** The render thread without a window: frames flow, settings apply, and its comparison is the CLI's. */
class RenderLoopTest {
    private static double number(String json, String key) {
        Matcher m = Pattern.compile("\"" + key + "\":(-?[0-9.eE+-]+|null)").matcher(json);
        assertTrue(m.find(), key + " in " + json);
        return m.group(1).equals("null") ? Double.NaN : Double.parseDouble(m.group(1));
    }

    /** Runs the loop until a measurement of a frame drawn with {@code settings} exists. */
    private static ViewState.Measurement measure(ViewState state, ViewSettings settings) throws Exception {
        state.settings(settings);
        state.toolsOpen(true);
        // Frames keep flowing even though nobody paints them (the wait times out); the progress is
        // published just after the frame that carries the measurement.
        return LoopRun.until(state, new TripleBuffer(), 2, "measurement", () -> {
            ViewState.Measurement m = state.measurement();
            return m != null && m.settings().equals(settings) && state.progress().frames() >= 1 ? m : null;
        });
    }

    @Test
    void theLoopsComparisonIsWhatTheCommandLinePrintsForTheSameFrame() throws Exception {
        ViewState state = new ViewState(DemoScenes.demo());
        state.viewSize(320, 180);
        ViewSettings settings = ViewSettings.defaults().withRender(ViewSettings.defaults().render()
                .withMode(RenderMode.TESSELLATED).withBorders(true)
                .withTessellation(ViewSettings.defaults().render().tessellation().withPolicy(SplitPolicy.ERROR)
                        .withMaxError(0.7)));
        ViewState.Measurement m = measure(state, settings);
        assertEquals(320, m.width());
        List<String> args = CliArgs.compare(AssetScenes.assetOf(state.scene()).orElseThrow(), m);
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Cli.run(new PrintWriter(out, true), new PrintWriter(err, true), args.toArray(String[]::new));
        assertEquals(0, status, err.toString());
        String json = out.toString();
        Comparison c = m.comparison();
        assertEquals(c.maxDisplacement(), number(json, "max_displacement"), 0.0);
        assertEquals(c.p99Displacement(), number(json, "p99_displacement"), 0.0);
        assertEquals(c.texelDifferShare(), number(json, "texel_differ_share"), 0.0);
        assertEquals(c.psnrDb(), number(json, "psnr_db"), 0.0);
        assertTrue(c.maxDisplacement() <= 0.7, "the error policy's bound holds in the demo too");
    }

    @Test
    void theOverlayIsNeverMeasured() throws Exception {
        ViewSettings plain = ViewSettings.defaults().withRender(ViewSettings.defaults().render()
                .withTessellation(ViewSettings.defaults().render().tessellation().withPolicy(SplitPolicy.ERROR)
                        .withMaxError(0.5)));
        ViewState a = new ViewState(DemoScenes.demo());
        a.viewSize(320, 180);
        Comparison without = measure(a, plain).comparison();
        ViewState b = new ViewState(DemoScenes.demo());
        b.viewSize(320, 180);
        Comparison with = measure(b, plain.withRender(plain.render().withBorders(true))).comparison();
        assertEquals(without.psnrDb(), with.psnrDb(), 0.0, "PSNR of the image, not of the borders");
        assertEquals(without.texelDifferShare(), with.texelDifferShare(), 0.0);
        assertEquals(without.maxDisplacement(), with.maxDisplacement(), 0.0);
    }

    @Test
    void withTheToolsClosedTheComparisonViewsAreNeitherShownNorPaidFor() throws Exception {
        ViewState state = new ViewState(DemoScenes.floor());
        state.viewSize(96, 64);
        state.settings(ViewSettings.defaults().withView(ViewKind.DIFFERENCE));
        state.toolsOpen(false);
        TripleBuffer buffers = new TripleBuffer();
        RenderLoop loop = new RenderLoop(state, buffers, () -> { }, 1);
        Thread t = new Thread(loop, "test-render");
        t.start();
        try {
            for (int poll = 0; poll < 1000 && state.progress().frames() < 1; poll++) {
                Thread.sleep(10);
            }
            FrameSlot shown = buffers.acquire(null);
            assertEquals(ViewKind.IMAGE, shown.view, "the image, not a heat map nobody can switch off");
            assertEquals(null, state.measurement(), "and no comparison");
            state.toolsOpen(true);
            for (int poll = 0; poll < 1000 && (shown = buffers.acquire(shown)).view != ViewKind.DIFFERENCE; poll++) {
                Thread.sleep(10);
            }
            assertEquals(ViewKind.DIFFERENCE, shown.view, "with the tools open it shows again");
        } finally {
            loop.stop();
            t.join(5000);
        }
    }

    @Test
    void underABudgetTheCopiedCommandCarriesTheChosenThreshold() throws Exception {
        ViewState state = new ViewState(DemoScenes.demo());
        state.viewSize(320, 180);
        // A generous budget: the controller refines below the user's threshold (its ceiling).
        state.budget(new ViewState.Budget(true, 1000));
        state.toolsOpen(true);
        TripleBuffer buffers = new TripleBuffer();
        RenderLoop loop = new RenderLoop(state, buffers, () -> { }, 2);
        Thread t = new Thread(loop, "test-render");
        t.start();
        ViewState.Measurement m = null;
        try {
            // Bounded: a few measurements, so that the controller has moved off the user's threshold.
            for (int poll = 0; poll < 1500; poll++) {
                m = state.measurement();
                if (m != null && state.progress().frames() > 12) {
                    break;
                }
                Thread.sleep(20);
            }
        } finally {
            loop.stop();
            t.join(5000);
        }
        assertNotNull(m);
        List<String> args = CliArgs.compare(AssetScenes.assetOf(state.scene()).orElseThrow(), m);
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        assertEquals(0, Cli.run(new PrintWriter(out, true), new PrintWriter(err, true), args.toArray(String[]::new)),
                err.toString());
        assertEquals(m.comparison().maxDisplacement(), number(out.toString(), "max_displacement"), 0.0);
        assertEquals(m.comparison().psnrDb(), number(out.toString(), "psnr_db"), 0.0);
    }

    @Test
    void minimizedViewDrawsNothingAndResumes() throws Exception {
        ViewState state = new ViewState(DemoScenes.floor());
        state.viewSize(0, 0);
        TripleBuffer buffers = new TripleBuffer();
        RenderLoop loop = new RenderLoop(state, buffers, () -> { }, 1);
        Thread t = new Thread(loop, "test-render");
        t.start();
        try {
            Thread.sleep(300);
            assertEquals(0, state.progress().frames(), "no frames while there is nothing to show");
            state.viewSize(64, 48);
            // A still scene: one frame for the new size, then the loop idles.
            for (int poll = 0; poll < 1000 && state.progress().frames() < 1; poll++) {
                Thread.sleep(10);
            }
            assertTrue(state.progress().frames() >= 1);
            FrameSlot shown = buffers.acquire(null);
            assertNotNull(shown);
            assertEquals(64, shown.width());
            state.viewSize(1, 1);
            state.settings(state.settings().withRenderScale(0.25));
            // Bounded waiting, not 300 ms: under load the 64-pixel frame under way and the next can take longer.
            for (int poll = 0; poll < 1000 && (shown = buffers.acquire(shown)).width() != 1; poll++) {
                Thread.sleep(10);
            }
            assertEquals(1, shown.width(), "a tiny view still gets a frame of at least one pixel");
        } finally {
            loop.stop();
            t.join(5000);
        }
    }

    @Test
    void everyPathIsTimedInAFrameRecordingTheUvOutputAsTheShownOneIs() {
        // The shown path records the UV output while measuring (10-20 % of a frame); the developer tools'
        // rows compare only if the others are timed doing the same. They were timed in a frame without it.
        Framebuffer reference = new Framebuffer(8, 8);
        reference.recordUv(true);
        for (RenderMode shown : RenderMode.values()) {
            List<RenderMode> drawn = new ArrayList<>();
            double[] ms = FrameDrawer.drawReference(shown, true, reference, (mode, into) -> {
                assertNotNull(into.uv(), mode + " timed without the UV output while " + shown + " records it");
                drawn.add(mode);
                return 1_000_000L * (mode.ordinal() + 1);
            });
            assertEquals(RenderMode.PERSPECTIVE, drawn.get(drawn.size() - 1),
                    "the per-pixel frame last, so the comparison reads it");
            for (RenderMode m : RenderMode.values()) {
                boolean timedHere = m != shown || m == RenderMode.PERSPECTIVE;
                assertEquals(timedHere ? 1 : 0, drawn.stream().filter(m::equals).count(), m + " with " + shown + " shown");
                assertEquals(timedHere ? m.ordinal() + 1 : 0, ms[m.ordinal()], 0.0, m + " row");
            }
        }
        List<RenderMode> drawn = new ArrayList<>();
        assertEquals(null, FrameDrawer.drawReference(RenderMode.SPANS, false, reference, (mode, into) -> {
            drawn.add(mode);
            return 1;
        }), "no rows when not measuring");
        assertEquals(List.of(RenderMode.PERSPECTIVE), drawn, "only the reference then");
    }

    @Test
    void aMeasurementGoesWithTheSceneItMeasured() throws Exception {
        // The trial's steps: measure the demo, untick measuring, open the floor, copy the compare command.
        // It named the floor with the demo's camera and the demo's numbers (3.129 px shown, 3.433 px run).
        ViewState state = new ViewState(DemoScenes.demo());
        state.viewSize(160, 90);
        ViewSettings settings = ViewSettings.defaults();
        ViewState.Measurement m = measure(state, settings);
        assertNotNull(state.pathMs());
        state.settings(settings.withCompare(false));
        state.scene(AssetScenes.scene(DemoScenes.floor()));
        TripleBuffer buffers = new TripleBuffer();
        RenderLoop loop = new RenderLoop(state, buffers, () -> { }, 1);
        Thread t = new Thread(loop, "test-render");
        t.start();
        try {
            long from = state.progress().frames();
            for (int poll = 0; poll < 1500 && state.progress().frames() < from + 3; poll++) {
                Thread.sleep(20);
            }
        } finally {
            loop.stop();
            t.join(5000);
        }
        assertEquals(null, state.measurement(), "the demo's numbers are not the floor's: nothing to show or copy");
        assertEquals(null, state.pathMs(), "nor each path's time");
        // A frame of the old scene that finishes after the change does not bring its numbers back.
        state.measurement(m, AssetScenes.scene(DemoScenes.demo()));
        assertEquals(null, state.measurement());
        state.measurement(m, state.scene());
        assertEquals(m, state.measurement(), "a frame of the scene shown is kept");
    }
}
