package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Quaternion;
import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.Primitives;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.texture.Texture;
import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The scene API end to end: objects drawn where hand-computed projections put them, groups, picking
 * against known pixels, and errors for bad input.
 */
class SceneRendererTest {
    /** Camera at the origin looking down -z, 90 degrees: (x, y, z) lands at ((x / -z + 1) * W/2, (1 - y / -z) * H/2). */
    static final Camera CAMERA = new Camera(Vec3.ZERO, new Vec3(0, 0, -1), Vec3.UP, 90, 0.1, 100);
    static final RenderSettings PERSPECTIVE = RenderSettings.defaults().withMode(RenderMode.PERSPECTIVE);

    /** A 2 x 2 square facing +z (the camera), centred on its origin, UV (0, 0) at its bottom-left. */
    static Mesh square() {
        return Primitives.plane(2, 2, 1, 1);
    }

    static final Transform FACING = Transform.rotation(Quaternion.ofX(90));

    /** A 4x4 texture whose texels are all different: texel (column c, row r from the top) = r * 4 + c + 1. */
    static Texture numbered() {
        int[] argb = new int[16];
        for (int i = 0; i < 16; i++) {
            argb[i] = 0xFF000000 | (i + 1) * 0x0F0F0F;
        }
        return new Texture("numbered", 4, 4, argb);
    }

    /** The covered pixels' bounding box {x0, y0, x1, y1} (inclusive) of those not of the background. */
    static int[] box(Framebuffer f) {
        int x0 = Integer.MAX_VALUE;
        int y0 = Integer.MAX_VALUE;
        int x1 = -1;
        int y1 = -1;
        for (int y = 0; y < f.height(); y++) {
            for (int x = 0; x < f.width(); x++) {
                if ((f.colour()[y * f.width() + x] & 0xFFFFFF) != 0) {
                    x0 = Math.min(x0, x);
                    y0 = Math.min(y0, y);
                    x1 = Math.max(x1, x);
                    y1 = Math.max(y1, y);
                }
            }
        }
        return new int[] {x0, y0, x1, y1};
    }

    @Test
    void objectsLandWhereTheProjectionPutsThem() {
        Scene scene = new Scene();
        SceneObject o = new SceneObject(square(), Material.colour(0xFF0000), FACING.withTranslation(1, 0, -5));
        scene.add(o);
        Framebuffer f = new Framebuffer(200, 200);
        try (SceneRenderer r = new SceneRenderer(2)) {
            r.render(scene, CAMERA, PERSPECTIVE, f);
            // x in [0, 2] at z = -5: screen x 100..140; y in [-1, 1]: screen y 80..120. Pixel centres inside.
            assertArrayEquals(new int[] {100, 80, 139, 119}, box(f));
            o.setTransform(o.transform().withScale(2)); // x in [-1, 3], y in [-2, 2]: 80..160, 60..140
            r.render(scene, CAMERA, PERSPECTIVE, f);
            assertArrayEquals(new int[] {80, 60, 159, 139}, box(f));
            o.setTransform(o.transform().withScale(1).withTranslation(1, 0, -10)); // 100..120, 90..110
            r.render(scene, CAMERA, PERSPECTIVE, f);
            assertArrayEquals(new int[] {100, 90, 119, 109}, box(f));
        }
    }

    @Test
    void groupsMoveAndHideWhatTheyHold() {
        Scene scene = new Scene();
        Group g = new Group("g");
        g.add(new SceneObject(square(), Material.colour(0x00FF00), FACING));
        g.setTransform(Transform.translation(-1, 1, -5));
        scene.add(g);
        Framebuffer f = new Framebuffer(200, 200);
        try (SceneRenderer r = new SceneRenderer(1)) {
            r.render(scene, CAMERA, PERSPECTIVE, f);
            // x in [-2, 0]: 60..100; y in [0, 2]: 60..100
            assertArrayEquals(new int[] {60, 60, 99, 99}, box(f));
            g.setVisible(false);
            r.render(scene, CAMERA, PERSPECTIVE, f);
            assertEquals(-1, box(f)[2], "a hidden group draws nothing");
            assertEquals(List.of(), scene.snapshot());
            assertEquals(1, scene.objects().size());
        }
    }

    @Test
    void oneObjectDrawsTheSamePixelsAsTheMeshAlone() {
        SceneAsset demo = DemoScenes.byName("demo").orElseThrow();
        Scene scene = new Scene();
        scene.add(new SceneObject(demo.mesh(), demo.textures().stream().map(Material::of).toList()));
        Framebuffer a = new Framebuffer(160, 90);
        Framebuffer b = new Framebuffer(160, 90);
        RenderSettings s = RenderSettings.defaults();
        try (SceneRenderer r = new SceneRenderer(2); FrameRenderer fr = new FrameRenderer(2)) {
            r.render(scene, demo.camera(), s, a);
            fr.render(demo.mesh(), demo.textureArray(), demo.camera().viewProjection(new Viewport(160, 90)), s, b);
        }
        assertArrayEquals(b.colour(), a.colour());
    }

    @Test
    void pickingTellsObjectTriangleTexelAndPoint() {
        Scene scene = new Scene();
        Texture tex = numbered();
        SceneObject right = new SceneObject(square(), Material.of(tex), FACING.withTranslation(1, 0, -5));
        right.setName("right");
        SceneObject left = new SceneObject(square(), Material.colour(0x0000FF), FACING.withTranslation(-2, 0, -5));
        scene.add(left, right);
        Framebuffer f = new Framebuffer(200, 200);
        try (SceneRenderer r = new SceneRenderer(2)) {
            assertTrue(r.pick(0, 0).isEmpty(), "nothing drawn yet");
            r.render(scene, CAMERA, PERSPECTIVE, f);
            Pick p = r.pick(120, 100).orElseThrow();
            assertSame(right, p.object());
            // The pixel centre (120.5, 100.5) maps to x = 0.205 * 5, y = -0.005 * 5 at z = -5.
            assertEquals(1.025, p.point().x(), 1e-9);
            assertEquals(-0.025, p.point().y(), 1e-9);
            assertEquals(-5, p.point().z(), 1e-9);
            assertEquals(0.5125, p.u(), 1e-9);
            assertEquals(0.4875, p.v(), 1e-9);
            assertSame(tex, p.texture());
            assertEquals(2, p.texelX());
            assertEquals(2, p.texelY());
            assertEquals(tex.argb()[p.texelY() * 4 + p.texelX()], f.colour()[100 * 200 + 120]);
            // Which of the square's two triangles holds the point: above or below its diagonal.
            assertEquals(p.u() > p.v() ? 0 : 1, p.triangle());
            assertSame(left, r.pick(60, 100).orElseThrow().object());
            assertTrue(r.pick(199, 0).isEmpty(), "background");
            // A frame with UV output is read directly, with the same answer.
            f.recordUv(true);
            r.render(scene, CAMERA, PERSPECTIVE, f);
            assertEquals(p, r.pick(120, 100).orElseThrow());
            // Something else drawn into that framebuffer since: the pick still describes this
            // renderer's last frame, not what the framebuffer now holds.
            Scene other = new Scene();
            SceneObject moved = new SceneObject(square(), Material.colour(0x00FF00), FACING.withTranslation(-4, 0, -5));
            other.add(moved);
            try (SceneRenderer second = new SceneRenderer(1)) {
                second.render(other, CAMERA, PERSPECTIVE, f);
            }
            assertTrue(f.uv()[3 * (100 * 200 + 120) + 2] == 0, "the framebuffer now shows the background there");
            assertEquals(p, r.pick(120, 100).orElseThrow());
            // Recording switched off and on: a new, empty UV output, not what was drawn.
            r.render(scene, CAMERA, PERSPECTIVE, f);
            f.recordUv(false);
            f.recordUv(true);
            assertEquals(p, r.pick(120, 100).orElseThrow());
            // The ids alone (what a view records): read from the frame, with the same answer.
            f.recordUv(false);
            f.recordIds(true);
            r.render(scene, CAMERA, PERSPECTIVE, f);
            assertEquals(p, r.pick(120, 100).orElseThrow());
            // Another path: the same triangle, point and texel (all from the triangle and the camera).
            r.render(scene, CAMERA, RenderSettings.display(), f);
            assertEquals(p, r.pick(120, 100).orElseThrow());
            assertThrows(IllegalArgumentException.class, () -> r.pick(200, 0));
        }
    }

    @Test
    void badInputGetsAClearError() {
        assertEquals("texture is null: read one with TextureReader or Texture.of, or use Material.colour(rgb)",
                assertThrows(NullPointerException.class, () -> Material.of(null)).getMessage());
        Mesh twoMaterials = DemoScenes.byName("demo").orElseThrow().mesh();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new SceneObject(twoMaterials, List.of(Material.colour(0))));
        assertTrue(e.getMessage().contains("materials") && e.getMessage().contains("1 were given"), e.getMessage());
        SceneRenderer r = new SceneRenderer(2);
        r.close();
        IllegalStateException closed = assertThrows(IllegalStateException.class,
                () -> r.render(new Scene(), CAMERA, PERSPECTIVE, new Framebuffer(4, 4)));
        assertEquals("this SceneRenderer is closed", closed.getMessage());
        assertEquals("this SceneRenderer is closed",
                assertThrows(IllegalStateException.class, () -> r.pick(0, 0)).getMessage());
        try (SceneRenderer open = new SceneRenderer(1)) {
            open.render(new Scene(), CAMERA, PERSPECTIVE, new Framebuffer(8, 6));
            assertEquals("pixel (8, 0) is outside the last frame, 8x6",
                    assertThrows(IllegalArgumentException.class, () -> open.pick(8, 0)).getMessage());
            assertEquals("pixel (0, -1) is outside the last frame, 8x6",
                    assertThrows(IllegalArgumentException.class, () -> open.pick(0, -1)).getMessage());
        }
        assertThrows(IllegalArgumentException.class, () -> SceneRenderer.renderImage(new Scene(), CAMERA, 0, 10));
        Group g = new Group();
        Group inner = new Group();
        g.add(inner);
        assertThrows(IllegalArgumentException.class, () -> inner.add(g));
        assertThrows(IllegalArgumentException.class, () -> g.add(new Scene()));
    }

    @Test
    void renderImageGivesThePicture() {
        Scene scene = new Scene();
        scene.add(new SceneObject(square(), Material.colour(0x123456), FACING.withTranslation(0, 0, -5)));
        BufferedImage image = SceneRenderer.renderImage(scene, CAMERA, PERSPECTIVE, 100, 100);
        assertEquals(0x123456, image.getRGB(50, 50) & 0xFFFFFF);
        assertEquals(0, image.getRGB(0, 0) & 0xFFFFFF);
        assertFalse(image.getColorModel().hasAlpha());
    }
}
