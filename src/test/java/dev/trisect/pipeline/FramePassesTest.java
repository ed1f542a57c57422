package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The frame as a list of passes: a pass added after the fill runs on every frame, after the geometry
 * and the fill, sees their results and the filled framebuffer, and may draw over it; a pass that draws
 * nothing leaves every pixel, UV output and statistic as the renderer without it.
 */
class FramePassesTest {
    private static final int W = 160;
    private static final int H = 96;
    private final SceneAsset scene = DemoScenes.byName("demo").orElseThrow();
    private final Mat4 vp = scene.camera().viewProjection(new Viewport(W, H));

    @Test
    void aLaterPassRunsAfterTheFillAndSeesItsResults() {
        List<String> seen = new ArrayList<>();
        FramePass probe = job -> {
            assertNotNull(job.geometry, "the geometry pass ran first");
            assertNotNull(job.bands, "the fill pass ran first");
            long written = 0;
            for (int c : job.frame.colour()) {
                written += c != job.settings.background() ? 1 : 0;
            }
            seen.add(job.chunkCount() + " chunks, " + written + " pixels");
        };
        // A pass that draws: a white column down the middle, over the filled frame.
        FramePass column = job -> {
            for (int y = 0; y < job.frame.height(); y++) {
                job.frame.colour()[y * job.frame.width() + job.frame.width() / 2] = 0xFFFFFF;
            }
        };
        RenderSettings s = RenderSettings.defaults().withMode(RenderMode.TESSELLATED);
        try (FrameRenderer plain = new FrameRenderer(2);
             FrameRenderer more = new FrameRenderer(2, List.of(probe, column))) {
            Framebuffer a = new Framebuffer(W, H);
            plain.render(scene.mesh(), scene.textureArray(), vp, s, a);
            Framebuffer b = new Framebuffer(W, H);
            more.render(scene.mesh(), scene.textureArray(), vp, s, b);
            assertEquals(1, seen.size(), "once per frame");
            assertTrue(seen.get(0).matches("[1-9]\\d* chunks, [1-9]\\d* pixels"), seen.get(0));
            for (int i = 0; i < W * H; i++) {
                int expected = i % W == W / 2 ? 0xFFFFFF : a.colour()[i];
                assertEquals(expected, b.colour()[i], "pixel " + i);
            }
            assertArrayEquals(a.depth(), b.depth(), "the later pass drew colour only");
        }
    }

    @Test
    void aPassThatDrawsNothingChangesNothing() {
        FramePass nothing = job -> { };
        for (RenderMode mode : RenderMode.values()) {
            RenderSettings s = RenderSettings.defaults().withMode(mode).withBorders(true);
            try (FrameRenderer plain = new FrameRenderer(2);
                 FrameRenderer more = new FrameRenderer(2, List.of(nothing))) {
                Framebuffer a = new Framebuffer(W, H);
                a.recordUv(true);
                FrameStats sa = plain.render(scene.mesh(), scene.textureArray(), vp, s, a);
                Framebuffer b = new Framebuffer(W, H);
                b.recordUv(true);
                FrameStats sb = more.render(scene.mesh(), scene.textureArray(), vp, s, b);
                assertArrayEquals(a.colour(), b.colour(), mode.id());
                assertArrayEquals(a.depth(), b.depth(), mode.id());
                assertArrayEquals(a.uv(), b.uv(), mode.id());
                assertEquals(sa.pieces(), sb.pieces(), mode.id());
                assertEquals(sa.pixelsWritten(), sb.pixelsWritten(), mode.id());
                assertArrayEquals(plain.drawn().coverage(), more.drawn().coverage(), mode.id());
            }
        }
    }
}
