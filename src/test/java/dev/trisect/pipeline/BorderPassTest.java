package dev.trisect.pipeline;

import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.mesh.Mesh;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.Framebuffer;
import dev.trisect.scene.Camera;
import dev.trisect.render.TessellationSettings;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Rendering with the borders on outlines each band as soon as it is filled; the demo and
 * {@code compare} render without them, measure, then call {@code drawBorders}. Both must give the
 * same image, in every path and style.
 */
class BorderPassTest {
    private static final int W = 160;
    private static final int H = 100;

    @Test
    void bordersDrawnWithTheFillEqualBordersDrawnAfterIt() {
        Mesh mesh = TestScenes.floor(13);
        Camera cam = TestScenes.floorCamera();
        List<BorderStyle> styles = List.of(BorderStyle.plain(), new BorderStyle(BorderStyle.Colouring.DEPTH, true),
                new BorderStyle(BorderStyle.Colouring.BOUND, false), BorderStyle.fallbackOnly());
        try (FrameRenderer renderer = new FrameRenderer(2)) {
            for (RenderMode mode : RenderMode.values()) {
                for (BorderStyle style : styles) {
                    RenderSettings s = RenderSettings.defaults().withMode(mode).withBorderStyle(style)
                            .withTessellation(TessellationSettings.defaults().withMaxEdge(6));
                    Framebuffer with = TestScenes.render(renderer, mesh, cam, s.withBorders(true), W, H);
                    Framebuffer after = TestScenes.render(renderer, mesh, cam, s.withBorders(false), W, H);
                    int[] plain = after.colour().clone();
                    renderer.drawBorders(after, style, s.tessellation());
                    assertArrayEquals(with.colour(), after.colour(), mode.id() + " " + style);
                    if (!style.onlyFallback()) {
                        assertNotEquals(Arrays.hashCode(plain), Arrays.hashCode(after.colour()), "outlines drawn");
                    }
                }
            }
        }
    }

    @Test
    void fadedAndColouredOutlinesDoNotDependOnTheNumberOfThreads() {
        // Enough triangles for several chunks (more than the four chunks of 2048 one thread once
        // had): shared edges are walked once per chunk, so the chunks must not depend on the thread count.
        Mesh mesh = TestScenes.floor(70);
        Camera cam = TestScenes.floorCamera();
        for (BorderStyle style : List.of(new BorderStyle(BorderStyle.Colouring.YELLOW, true),
                new BorderStyle(BorderStyle.Colouring.BOUND, true), new BorderStyle(BorderStyle.Colouring.DEPTH, false))) {
            RenderSettings s = RenderSettings.defaults().withBorders(true).withBorderStyle(style)
                    .withTessellation(TessellationSettings.defaults().withMaxEdge(6));
            Framebuffer one;
            try (FrameRenderer single = new FrameRenderer(1)) {
                one = TestScenes.render(single, mesh, cam, s, 2 * W, 2 * H);
            }
            try (FrameRenderer three = new FrameRenderer(3)) {
                assertArrayEquals(one.colour(), TestScenes.render(three, mesh, cam, s, 2 * W, 2 * H).colour(),
                        style.toString());
            }
        }
    }

    @Test
    void chunksAreSetByTheTriangleCountAsDocumented() {
        // The examples of FrameRenderer.SMALL_MESH_CHUNK_CAP and docs/conventions.md.
        assertEquals(1, Chunks.count(0));
        assertEquals(1, Chunks.count(512));
        assertEquals(2, Chunks.count(1000));
        assertEquals(500, Chunks.size(1000, 2));
        assertEquals(64, Chunks.count(32768));
        assertEquals(512, Chunks.size(32768, 64));
        assertEquals(64, Chunks.count(100_000));
        assertEquals(1563, Chunks.size(100_000, 64));
        // Every chunk holds a triangle, the last no more than the others, and up to 32768 triangles none more than 512.
        for (int n = 1; n <= 200_000; n += n < 40_000 ? 1 : 97) {
            int count = Chunks.count(n);
            int size = Chunks.size(n, count);
            int last = n - (count - 1) * size;
            assertTrue(last >= 1 && last <= size, n + " triangles: last chunk " + last + " of " + size);
            assertTrue(n > 32768 || size <= 512, n + " triangles: chunks of " + size);
        }
    }
}
