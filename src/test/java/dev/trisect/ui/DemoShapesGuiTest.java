package dev.trisect.ui;

import static dev.trisect.GuiTests.onEdt;
import static dev.trisect.GuiTests.waitFor;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.GuiTests;
import dev.trisect.scene.DrawStyle;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.view.FrameInfo;
import java.util.List;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The demo's X (labels, axes gizmo, glass pane), Z (wireframe) and H (frame-rate HUD): off at start, so
 * the demo's frame is the command line's; on, the frames draw labels' glyphs, the axes' and the
 * wireframe's segments, and a HUD line that names the frame rate.
 */
@Tag("gui")
class DemoShapesGuiTest {
    private DemoWindow window;

    @AfterEach
    void close() throws Exception {
        if (window != null) {
            SwingUtilities.invokeAndWait(() -> window.frame().dispose());
        }
    }

    /** The first frame drawn after {@code after}. */
    private FrameInfo frameAfter(long after) throws Exception {
        waitFor("a frame", () -> window.latest() != null && window.latest().number() > after);
        return window.latest();
    }

    /** A frame drawn after the one before it: a change made on the event thread may miss the frame under way. */
    private FrameInfo frameWith(String what, java.util.function.Predicate<FrameInfo> holds) throws Exception {
        waitFor(what, () -> window.latest() != null && holds.test(window.latest()));
        return window.latest();
    }

    @Test
    void xShowsLabelsAxesAndAPaneZDrawsWireAndHShowsTheRate() throws Exception {
        GuiTests.requireDisplay();
        window = onEdt(DemoWindows::demo);
        onEdt(() -> {
            window.start();
            return null;
        });
        Scene scene = onEdt(() -> window.view().getScene());
        FrameInfo plain = frameAfter(0);
        assertEquals(1, scene.objects().size(), "the demo opens with its scene alone");
        assertEquals(0, plain.stats().glyphs());
        assertEquals(0, plain.stats().segmentsIn());
        assertTrue(scene.screenText().isEmpty());

        onEdt(() -> {
            window.shapes.setExtras(true);
            return null;
        });
        List<String> names = scene.objects().stream().map(SceneObject::name).toList();
        assertTrue(names.containsAll(List.of("axes", "glass pane", "labels")), names.toString());
        FrameInfo extras = frameWith("the axes' three segments", f -> f.stats().segmentsIn() == 3);
        assertTrue(extras.stats().glyphs() > 20, "labels drawn: " + extras.stats().glyphs() + " glyphs");

        assertEquals(DrawStyle.FILLED_AND_WIRE, onEdt(() -> window.shapes.cycleStyle()));
        SceneObject demo = scene.objects().get(0);
        assertEquals(DrawStyle.FILLED_AND_WIRE, demo.drawStyle());
        // The demo's mesh's edges, each shared edge once: thousands (the floor alone is 80 x 80 cells).
        FrameInfo wired = frameWith("the wireframe", f -> f.stats().segmentsIn() > 10_000);
        assertEquals(DrawStyle.WIRE, onEdt(() -> window.shapes.cycleStyle()));
        assertEquals(DrawStyle.FILLED, onEdt(() -> window.shapes.cycleStyle()));
        assertEquals(DrawStyle.FILLED, demo.drawStyle());

        onEdt(() -> {
            window.shapes.setHud(true);
            return null;
        });
        // The line is written before each frame from the frame before it.
        long first = frameAfter(wired.number()).number();
        window.view().requestFrame();
        frameAfter(first);
        String hud = scene.screenText().get(0).text();
        assertTrue(hud.matches("([0-9.]+|\u2013) fps \u00b7 \\d+\\.\\d ms a frame"), hud);
        assertTrue(window.latest().stats().glyphs() > extras.stats().glyphs(), "the HUD's glyphs drawn too");

        onEdt(() -> {
            window.shapes.setExtras(false);
            window.shapes.setHud(false);
            return null;
        });
        assertEquals(1, scene.objects().size());
        assertTrue(scene.screenText().isEmpty());
    }
}
