package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.texture.ProceduralTextures;
import org.junit.jupiter.api.Test;

/**
 * Transforms that are valid alone but whose product overflows are refused where they are combined
 * (naming the object), never drawn as nothing; a field of view too narrow to clip in double precision
 * is refused; and a frame that skips triangles says so through the API.
 */
class GroupProductLimitsTest {
    private static SceneObject box(String name) {
        SceneObject o = new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.uvGrid(16)));
        o.setName(name);
        return o;
    }

    @Test
    void addingAnObjectWhoseWorldMatrixWouldOverflowIsRefused() {
        Scene scene = new Scene();
        Group g = new Group("g");
        g.setTransform(Transform.scale(1e200));
        scene.add(g);
        SceneObject o = box("crate");
        o.setTransform(Transform.scale(1e200));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> g.add(o));
        assertTrue(e.getMessage().contains("crate") && e.getMessage().contains("not finite"), e.getMessage());
        assertTrue(g.children().isEmpty(), "nothing added");
        assertNull(o.parent());
    }

    @Test
    void aTransformWhoseProductWouldOverflowIsRefusedAndTheOldOneKept() {
        Scene scene = new Scene();
        Group g = new Group("g");
        SceneObject o = box("crate");
        o.setTransform(Transform.scale(1e200));
        g.add(o);
        scene.add(g);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> g.setTransform(Transform.scale(1e200)));
        assertTrue(e.getMessage().contains("crate") && e.getMessage().contains("1.0E200"), e.getMessage());
        assertEquals(Transform.IDENTITY, g.transform());
        // Each valid alone, and drawn: the object is placed finitely.
        try (SceneRenderer r = new SceneRenderer(1)) {
            FrameStats s = r.render(scene, Camera.looking(new Vec3(0, 0, 5), Vec3.ZERO), RenderSettings.defaults(),
                    new Framebuffer(32, 32));
            assertEquals(12, s.trianglesIn());
            assertEquals(0, s.skippedInvalid());
        }
    }

    @Test
    void aFieldOfViewTooNarrowToClipIsRefusedAndTheNarrowestDraws() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Camera(new Vec3(0, 0, 5), Vec3.ZERO, Vec3.UP, 1e-15, 0.1, 100));
        assertTrue(e.getMessage().contains("1.0E-15") && e.getMessage().contains("too narrow"), e.getMessage());
        Scene scene = new Scene();
        scene.add(new SceneObject(Primitives.plane(20, 20, 4, 4), Material.of(ProceduralTextures.uvGrid(16))));
        Camera narrowest = new Camera(new Vec3(0, 3, 5), Vec3.ZERO, Vec3.UP, Camera.MIN_FOV, 0.1, 100);
        try (SceneRenderer r = new SceneRenderer(1)) {
            Framebuffer f = new Framebuffer(40, 30);
            FrameStats s = r.render(scene, narrowest, RenderSettings.defaults(), f);
            assertEquals(0, s.skippedInvalid());
            assertNull(s.skippedNote());
            assertEquals(40 * 30, s.pixelsWritten(), "the plane fills the view");
        }
    }

    @Test
    void aFrameThatSkipsTrianglesSaysSoThroughItsStatistics() {
        Scene scene = new Scene();
        // A quad far larger than double precision can clip where it leaves the view, seen from 3 units.
        MeshBuilder b = new MeshBuilder();
        double h = 1e20;
        b.triangle(b.position(-h, -h, 0), b.position(h, -h, 0), b.position(h, h, 0), b.uv(0, 0), b.uv(1, 0), b.uv(1, 1));
        b.triangle(0, 2, b.position(-h, h, 0), 0, 2, b.uv(0, 1));
        scene.add(new SceneObject(b.build(), Material.of(ProceduralTextures.uvGrid(16))));
        try (SceneRenderer r = new SceneRenderer(1)) {
            FrameStats s = r.render(scene, Camera.looking(new Vec3(0, 0, 3), Vec3.ZERO),
                    RenderSettings.defaults(), new Framebuffer(64, 48));
            assertEquals(2, s.skippedInvalid());
            assertEquals("2 of 2 triangles skipped: coordinates not finite, or too far from the view to place in "
                    + "double precision (see docs/reading-limits.md)", s.skippedNote());
        }
    }
}
