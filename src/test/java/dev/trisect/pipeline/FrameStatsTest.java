package dev.trisect.pipeline;

import dev.trisect.render.FrameStats;
import dev.trisect.render.CullMode;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Framebuffer;
import dev.trisect.scene.Camera;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.Texture;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

class FrameStatsTest {
    private static final FrameRenderer RENDERER = new FrameRenderer(2);
    private static final Texture[] TEX = {TestScenes.distinctTexels()};

    @AfterAll
    static void close() {
        RENDERER.close();
    }

    private static FrameStats render(Mesh mesh, Camera cam, RenderSettings s) {
        Framebuffer fb = new Framebuffer(160, 120);
        return RENDERER.render(mesh, TEX, cam.viewProjection(new Viewport(160, 120)), s, fb);
    }

    @Test
    void aBoxSeenFromACornerShowsThreeFacesAndCullsThree() {
        MeshBuilder b = new MeshBuilder();
        Primitives.box(b, Vec3.ZERO, new Vec3(1, 1, 1));
        Camera cam = Camera.looking(new Vec3(2, 1.7, 2.4), Vec3.ZERO);
        FrameStats back = render(b.build(), cam, RenderSettings.defaults().withMode(RenderMode.PERSPECTIVE));
        assertEquals(12, back.trianglesIn());
        assertEquals(6, back.culledBackFace());
        assertEquals(6, back.pieces());
        assertEquals(0, back.clipped());
        FrameStats none = render(b.build(), cam, RenderSettings.defaults().withMode(RenderMode.PERSPECTIVE)
                .withCull(CullMode.NONE));
        assertEquals(0, none.culledBackFace());
        assertEquals(12, none.pieces());
        assertTrue(none.pixelsWritten() > back.pixelsWritten(), "back faces are drawn, then hidden or not");
    }

    /** docs/conventions.md: front faces run counter-clockwise as the camera sees them. */
    @Test
    void aTriangleCounterClockwiseOnScreenIsAFrontFace() {
        Camera cam = Camera.looking(new Vec3(0, 0, 3), Vec3.ZERO); // looking down -z, x right, y up
        Vec3 left = new Vec3(-1, -1, 0);
        Vec3 right = new Vec3(1, -1, 0);
        Vec3 top = new Vec3(0, 1, 0);
        RenderSettings back = RenderSettings.defaults().withMode(RenderMode.PERSPECTIVE);
        FrameStats ccw = render(triangle(left, right, top), cam, back);
        assertEquals(0, ccw.culledBackFace());
        assertTrue(ccw.pixelsWritten() > 1000, ccw.toJson());
        FrameStats cw = render(triangle(left, top, right), cam, back);
        assertEquals(1, cw.culledBackFace());
        assertEquals(0, cw.pixelsWritten());
        FrameStats none = render(triangle(left, top, right), cam, back.withCull(CullMode.NONE));
        assertEquals(ccw.pixelsWritten(), none.pixelsWritten(), "with culling off, the back face is drawn");
    }

    private static Mesh triangle(Vec3 a, Vec3 b, Vec3 c) {
        MeshBuilder m = new MeshBuilder();
        int t = m.uv(0, 0);
        m.triangle(m.position(a), m.position(b), m.position(c), t, t, t);
        return m.build();
    }

    @Test
    void everyPieceIsAccountedFor() {
        MeshBuilder b = new MeshBuilder();
        Primitives.box(b, Vec3.ZERO, new Vec3(1, 1, 1));
        // The sphere straddles the right edge of the frame; the second box is far outside the view.
        Primitives.sphere(b, new Vec3(3.1, 0, -1), 1.2, 12, 6);
        Primitives.box(b, new Vec3(60, 0, 0), new Vec3(1, 1, 1));
        Camera cam = Camera.looking(new Vec3(1, 1.2, 3), new Vec3(0.6, 0, 0));
        Mesh mesh = b.build();
        RenderSettings s = RenderSettings.defaults().withMode(RenderMode.TESSELLATED)
                .withTessellation(TessellationSettings.defaults().withMaxEdge(6));
        FrameStats st = render(mesh, cam, s);
        assertEquals(0, st.clipped(), "nothing crosses the near plane here");
        long entering = st.trianglesIn() - st.culled() - st.skippedInvalid();
        // Every split turns one piece into two; every piece ends filled or dropped off screen.
        assertEquals(entering + st.splits(), st.pieces() + st.piecesOffScreen());
        assertTrue(st.splits() > 0 && st.piecesOffScreen() > 0, st.toJson());
        assertTrue(st.culledFrustum() >= 6, "the far box's front faces are outside the view: " + st.toJson());
        assertTrue(st.deepestSplit() > 0 && st.capsReached() == 0, st.toJson());
    }

    @Test
    void nearPlaneCutsAreCounted() {
        Camera cam = TestScenes.floorCamera();
        FrameStats st = render(TestScenes.floor(1), cam, RenderSettings.defaults().withMode(RenderMode.PERSPECTIVE));
        assertEquals(2, st.trianglesIn());
        assertTrue(st.clipped() >= 1, st.toJson());
        assertTrue(st.pieces() >= 2, "a cut triangle is fanned into more than one: " + st.toJson());
    }

    @Test
    void rasterAndOverlayTimesAreNamedEstimatesWhenTheBordersAreDrawnWithTheFill() {
        Mesh mesh = TestScenes.floor(13);
        RenderSettings s = RenderSettings.defaults().withMode(RenderMode.TESSELLATED);
        FrameStats plain = render(mesh, TestScenes.floorCamera(), s);
        assertFalse(plain.bandTimesEstimated());
        assertEquals(0, plain.overlayNanos());
        assertTrue(plain.toJson().contains("\"raster\":") && plain.toJson().contains("\"overlay\":")
                && !plain.toJson().contains("estimate"), plain.toJson());
        FrameStats borders = render(mesh, TestScenes.floorCamera(), s.withBorders(true));
        assertTrue(borders.bandTimesEstimated());
        assertTrue(borders.overlayNanos() > 0 && borders.rasterNanos() > 0, borders.toJson());
        assertTrue(borders.toJson().contains("\"raster_estimate\":") && borders.toJson().contains("\"overlay_estimate\":")
                && !borders.toJson().contains("\"overlay\":") && !borders.toJson().contains("\"raster\":"),
                borders.toJson());
        for (FrameStats st : new FrameStats[] {plain, borders}) {
            // The stages share out the frame's wall time: they add up to it exactly.
            assertEquals(st.totalNanos(), st.transformNanos() + st.clipNanos() + st.tessellateNanos()
                    + st.rasterNanos() + st.overlayNanos(), st.toJson());
        }
    }
}
