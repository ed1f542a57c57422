package dev.trisect.pipeline;

import dev.trisect.render.FrameStats;
import dev.trisect.render.CullMode;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.render.Framebuffer;
import dev.trisect.scene.Camera;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.Texture;
import org.junit.jupiter.api.Test;

/**
 * The frame piece budget: a frame that would have more pieces gets a lower depth cap, the same one
 * whatever the number of threads, with the fallback filling what the cap leaves failing — so the
 * bound still holds and nothing cracks.
 */
class FrameBudgetTest {
    private static final Texture[] TEX = {TestScenes.distinctTexels()};

    private static Framebuffer render(int threads, Mesh mesh, Camera cam, RenderSettings s, int w, int h,
                                      FrameStats[] stats) {
        Framebuffer fb = new Framebuffer(w, h);
        fb.recordUv(true);
        try (FrameRenderer r = new FrameRenderer(threads)) {
            stats[0] = r.render(mesh, TEX, cam.viewProjection(new Viewport(w, h)), s, fb);
        }
        return fb;
    }

    @Test
    void tinyThresholdsHitTheBudgetNotTheHeap() {
        // 0.01 px edges over a 10 km plane would be billions of pieces.
        Mesh plane = DisplacementBoundTest.plane(10_000, 1);
        RenderSettings s = RenderSettings.defaults().withCull(CullMode.NONE)
                .withTessellation(TessellationSettings.defaults().withMaxEdge(0.01).withMaxDepth(30)
                        .withMaxPieces(Integer.MAX_VALUE));
        FrameStats[] st = new FrameStats[1];
        render(2, plane, DisplacementBoundTest.planeCamera(), s, 320, 240, st);
        assertEquals(2 + 320 * 240 / TessellationSettings.PIXELS_PER_PIECE, st[0].pieceBudget(),
                "one piece per triangle plus one per 16 pixels");
        assertTrue(st[0].budgetReached() && st[0].budgetDepth() < 30, st[0].toJson());
        assertTrue(st[0].pieces() + st[0].piecesOffScreen() <= st[0].pieceBudget(), st[0].toJson());
        assertTrue(st[0].piecesFallback() > 0, "the fallback fills what the lowered cap stops: " + st[0].toJson());
        assertTrue(st[0].toJson().contains("\"budget_reached\":true"), st[0].toJson());
    }

    @Test
    void budgetedFramesAreTheSameForAnyNumberOfThreads() {
        // A tiled floor (many chunks' worth of triangles would need more, but the verdicts must not
        // depend on how triangles are shared out) with a budget it cannot meet at the configured cap.
        Mesh grid = TestScenes.floor(40);
        RenderSettings s = RenderSettings.defaults().withBorders(true).withTessellation(
                TessellationSettings.defaults().withMaxEdge(2).withMaxFramePieces(20_000));
        FrameStats[] one = new FrameStats[1];
        FrameStats[] three = new FrameStats[1];
        Framebuffer a = render(1, grid, TestScenes.floorCamera(), s, 256, 192, one);
        Framebuffer b = render(3, grid, TestScenes.floorCamera(), s, 256, 192, three);
        assertTrue(one[0].budgetReached(), one[0].toJson());
        assertEquals(one[0].budgetDepth(), three[0].budgetDepth());
        assertEquals(one[0].pieces(), three[0].pieces());
        assertArrayEquals(a.colour(), b.colour());
        assertArrayEquals(a.uv(), b.uv());
    }

    @Test
    void theBoundHoldsAndNothingCracksWhenTheBudgetBites() {
        Mesh plane = DisplacementBoundTest.plane(10_000, 1);
        Camera cam = DisplacementBoundTest.planeCamera();
        int w = 480;
        int h = 270;
        Mat4 vp = cam.viewProjection(new Viewport(w, h));
        for (SplitPolicy policy : SplitPolicy.values()) {
            TessellationSettings t = TessellationSettings.defaults().withPolicy(policy).withMaxEdge(0.5)
                    .withMaxError(0.1).withMaxFramePieces(3000);
            double threshold = policy == SplitPolicy.EDGE ? 0.5 : 0.1;
            RenderSettings s = RenderSettings.defaults().withCull(CullMode.NONE).withTessellation(t);
            FrameStats[] st = new FrameStats[1];
            Framebuffer fb = render(2, plane, cam, s, w, h, st);
            assertTrue(st[0].budgetReached(), st[0].toJson());
            ExactDisplacement.Result r = ExactDisplacement.measure(plane, TEX, vp, fb);
            assertTrue(r.worst() <= threshold + 0.002, policy + ": " + r.worst() + " px off; " + st[0].toJson());
            try (FrameRenderer renderer = new FrameRenderer(2)) {
                int[] whole = renderer.coverage(plane, TEX, vp, s.withMode(RenderMode.PERSPECTIVE), w, h);
                int[] pieces = renderer.coverage(plane, TEX, vp, s, w, h);
                assertArrayEquals(whole, pieces, policy + ": pieces cover every pixel the plane covers, once");
            }
        }
    }
}
