package dev.trisect.pipeline;

import dev.trisect.render.RenderSettings;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.render.Framebuffer;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.render.TessellationSettings;
import org.junit.jupiter.api.Test;

/** Memory taken by one extreme frame goes back once frames are ordinary again. */
class ScratchTrimTest {
    @Test
    void oneExtremeFrameDoesNotKeepItsMemoryForever() {
        SceneAsset scene = DemoScenes.demo();
        Framebuffer fb = new Framebuffer(400, 240);
        Mat4 vp = scene.camera().viewProjection(new Viewport(400, 240));
        RenderSettings normal = RenderSettings.defaults();
        try (FrameRenderer r = new FrameRenderer(2)) {
            long ordinaryPieces = r.render(scene.mesh(), scene.textureArray(), vp, normal, fb).pieces();
            long extremePieces = r.render(scene.mesh(), scene.textureArray(), vp,
                    // The frame piece budget would stop the spike; lift it to make one.
                    normal.withTessellation(TessellationSettings.defaults().withMaxEdge(1)
                            .withMaxFramePieces(Integer.MAX_VALUE)), fb).pieces();
            assertTrue(extremePieces > 20 * ordinaryPieces, extremePieces + " vs " + ordinaryPieces);
            long afterSpike = r.retainedTriangleCapacity();
            assertTrue(afterSpike >= extremePieces, "the spike's storage is there at first");
            for (int i = 0; i < FrameRenderer.TRIM_FRAMES - 2; i++) {
                r.render(scene.mesh(), scene.textureArray(), vp, normal, fb);
            }
            assertEquals(afterSpike, r.retainedTriangleCapacity(), "a short dip keeps the storage (no churn)");
            for (int i = 0; i < 5; i++) {
                r.render(scene.mesh(), scene.textureArray(), vp, normal, fb);
            }
            long trimmed = r.retainedTriangleCapacity();
            assertTrue(trimmed < afterSpike / 4, "storage given back: " + trimmed + " of " + afterSpike);
            long steady = r.retainedTriangleCapacity();
            for (int i = 0; i < 3 * FrameRenderer.TRIM_FRAMES; i++) {
                r.render(scene.mesh(), scene.textureArray(), vp, normal, fb);
            }
            assertEquals(steady, r.retainedTriangleCapacity(), "steady frames neither grow nor shrink it");
        }
    }
}
