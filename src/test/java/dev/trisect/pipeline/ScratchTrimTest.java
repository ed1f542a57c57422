package dev.trisect.pipeline;

import dev.trisect.render.RenderSettings;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.render.Framebuffer;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.ProceduralTextures;
import dev.trisect.texture.Texture;
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

    /**
     * A frame of a mesh large enough for every chunk, with its borders outlined, then only small frames:
     * after {@link FrameRenderer#TRIM_FRAMES} of them every chunk beyond those in use is gone, the
     * clip-space arrays too, and one frame later the outline plans (drawn after the render), whatever the single chunk left held.
     */
    @Test
    void aLargeMeshsChunksPositionsAndOutlinesGoBackAfterAFewSmallFrames() {
        Mesh large = Primitives.plane(20, 20, 300, 300);
        Mesh box = Primitives.box(1, 1, 1);
        Texture[] textures = {ProceduralTextures.uvGrid(64)};
        Framebuffer fb = new Framebuffer(320, 200);
        Mat4 vp = dev.trisect.scene.Camera.looking(new dev.trisect.math.Vec3(0, 3, 6), dev.trisect.math.Vec3.ZERO)
                .viewProjection(new Viewport(320, 200));
        RenderSettings normal = RenderSettings.defaults();
        try (FrameRenderer r = new FrameRenderer(2)) {
            r.render(box, textures, vp, normal, fb);
            long boxTriangles = r.retainedTriangleCapacity();
            r.render(large, textures, vp, normal, fb);
            r.drawBorders(fb, BorderStyle.plain(), normal.tessellation());
            assertTrue(r.retainedPositionCapacity() >= large.positionCount());
            assertEquals(64, r.retainedOutlinePlans());
            long afterLarge = r.retainedTriangleCapacity();
            assertTrue(afterLarge >= large.triangleCount(), afterLarge + " triangles of room");
            for (int i = 0; i < FrameRenderer.TRIM_FRAMES; i++) {
                r.render(box, textures, vp, normal, fb);
            }
            assertTrue(r.retainedTriangleCapacity() <= Math.max(boxTriangles, Chunk.TRIM_FLOOR) * 2,
                    "chunks keep room for " + r.retainedTriangleCapacity() + " triangles, " + boxTriangles
                            + " before the large frame");
            assertTrue(r.retainedPositionCapacity() < large.positionCount(),
                    "clip space keeps room for " + r.retainedPositionCapacity() + " positions");
            // drawBorders comes after its frame's render: its plans are counted with the next frame.
            r.render(box, textures, vp, normal, fb);
            assertEquals(0, r.retainedOutlinePlans(), "no frame outlined lately");
        }
    }

    /** release() gives everything back at once, and the next frame is the same picture. */
    @Test
    void releaseGivesEverythingBackAndTheNextFrameIsTheSame() {
        SceneAsset scene = DemoScenes.demo();
        Mat4 vp = scene.camera().viewProjection(new Viewport(320, 200));
        RenderSettings withBorders = RenderSettings.defaults().withBorders(true);
        try (FrameRenderer r = new FrameRenderer(2)) {
            Framebuffer before = new Framebuffer(320, 200);
            r.render(scene.mesh(), scene.textureArray(), vp, withBorders, before);
            assertTrue(r.retainedTriangleCapacity() > 0 && r.retainedPositionCapacity() > 0);
            r.release();
            assertEquals(0, r.retainedTriangleCapacity());
            assertEquals(0, r.retainedPositionCapacity());
            assertEquals(0, r.retainedOutlinePlans());
            Framebuffer after = new Framebuffer(320, 200);
            r.render(scene.mesh(), scene.textureArray(), vp, withBorders, after);
            org.junit.jupiter.api.Assertions.assertArrayEquals(before.colour(), after.colour());
        }
    }
}
