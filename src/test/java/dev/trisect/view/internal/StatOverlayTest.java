package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Viewport;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.FrameStats;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;

/** The statistics overlay (U) reads the frame on screen's own numbers. */
class StatOverlayTest {
    private static FrameSlot frame(RenderSettings r) {
        SceneAsset demo = DemoScenes.demo();
        FrameSlot f = new FrameSlot(320, 180);
        try (FrameRenderer renderer = new FrameRenderer(1)) {
            f.stats = renderer.render(demo.mesh(), demo.textureArray(), demo.camera().viewProjection(new Viewport(320, 180)),
                    r, f.frame);
        }
        f.drawnRender = r;
        f.render = r;
        return f;
    }

    @Test
    void theLinesAreTheFramesNumbers() {
        RenderSettings r = ViewSettings.defaults().render();
        FrameSlot f = frame(r);
        FrameStats st = f.stats;
        List<String> lines = StatOverlay.lines(f, 25);
        assertEquals(4, lines.size());
        assertTrue(lines.get(0).startsWith("25.0 fps  frame 40.0 ms = engine "), lines.get(0));
        assertTrue(lines.get(1).contains(String.format(Locale.ROOT, "fill %.1f", st.rasterNanos() / 1e6)), lines.get(1));
        assertTrue(lines.get(2).equals(String.format(Locale.ROOT, "pieces %,d  fallback %,d (filled per pixel)",
                st.pieces(), st.piecesFallback())), lines.get(2));
        assertEquals("path tessellated  policy edge  threshold 32.0 px  filter trilinear", lines.get(3));
        // A path that splits nothing shows no tessellation time, and the span path its knot error.
        assertTrue(StatOverlay.lines(frame(r.withMode(RenderMode.PERSPECTIVE)), 25).get(1).contains("tessellation -"));
        assertEquals("path spans  knot error 0.500 px  filter trilinear", StatOverlay.how(r.withMode(RenderMode.SPANS)));
    }
}
