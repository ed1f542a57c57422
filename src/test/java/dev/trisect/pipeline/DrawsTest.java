package dev.trisect.pipeline;

import dev.trisect.render.FrameStats;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Mat4;
import dev.trisect.math.Quaternion;
import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Framebuffer;
import dev.trisect.scene.Camera;
import dev.trisect.texture.Texture;
import org.junit.jupiter.api.Test;

/**
 * Several meshes in one frame, each with its own model-view-projection: one depth buffer across
 * them, triangles numbered across them in the UV output, each placed by its own matrix.
 */
class DrawsTest {
    private static final Camera CAMERA = new Camera(Vec3.ZERO, new Vec3(0, 0, -1), Vec3.UP, 90, 0.1, 100);
    private static final Viewport VIEW = new Viewport(200, 200);
    private static final Mat4 VP = CAMERA.viewProjection(VIEW);
    private static final RenderSettings PERSPECTIVE = RenderSettings.defaults().withMode(RenderMode.PERSPECTIVE);

    /** A 2 x 2 square facing the camera (+z), centred on its origin. */
    private static final Mesh SQUARE = Primitives.plane(2, 2, 1, 1);
    private static final Mat4 FACING = Transform.rotation(Quaternion.ofX(90)).matrix();

    private static Texture[] colour(int argb) {
        return new Texture[] {Texture.solid("c", 0xFF000000 | argb)};
    }

    private static Mat4 at(double x, double y, double z) {
        return VP.mul(Transform.translation(x, y, z).matrix()).mul(FACING);
    }

    @Test
    void nearerObjectsWinWhateverTheOrderAndIdsRunAcrossDraws() {
        try (FrameRenderer r = new FrameRenderer(2)) {
            for (boolean nearFirst : new boolean[] {true, false}) {
                Draws draws = new Draws();
                Mat4 near = at(0, 0, -4);
                Mat4 far = at(0.5, 0, -5);
                draws.add(SQUARE, colour(nearFirst ? 0xFF0000 : 0x00FF00), nearFirst ? near : far);
                draws.add(new MeshBuilder().build(), colour(0), near); // no triangles: numbers nothing
                draws.add(SQUARE, colour(nearFirst ? 0x00FF00 : 0xFF0000), nearFirst ? far : near);
                Framebuffer f = new Framebuffer(200, 200);
                f.recordUv(true);
                FrameStats stats = r.render(draws, PERSPECTIVE, f);
                assertEquals(4, stats.trianglesIn());
                // The near square (z = -4, x in [-1, 1]) covers x 75..125; the far one reaches 110..130 beyond it.
                assertEquals(0xFF0000, f.colour()[100 * 200 + 100] & 0xFFFFFF, "near wins at the centre");
                assertEquals(0x00FF00, f.colour()[100 * 200 + 127] & 0xFFFFFF, "far shows beside it");
                int nearId = (int) f.uv()[3 * (100 * 200 + 100) + 2] - 1;
                int farId = (int) f.uv()[3 * (100 * 200 + 127) + 2] - 1;
                int nearDraw = nearFirst ? 0 : 2;
                int farDraw = nearFirst ? 2 : 0;
                assertEquals(nearDraw, draws.drawOf(nearId));
                assertEquals(farDraw, draws.drawOf(farId));
                assertTrue(nearId - draws.firstTriangle(nearDraw) < 2 && farId - draws.firstTriangle(farDraw) < 2);
                assertEquals(0, f.uv()[3 * (5 * 200 + 5) + 2], "background has no id");
            }
        }
    }

    @Test
    void eachDrawIsPlacedByItsOwnMatrix() {
        // The same square three times: its pixel box moves and scales as the hand-computed projection says.
        try (FrameRenderer r = new FrameRenderer(1)) {
            Draws draws = new Draws();
            draws.add(SQUARE, colour(0xFF0000), at(-3, 2, -5));                       // x 20..60, y 40..80
            draws.add(SQUARE, colour(0x00FF00), at(3, -2, -10));                      // x 120..140, y 110..130
            draws.add(SQUARE, colour(0x0000FF), VP.mul(Transform.translation(0, 0, -5).withScale(0.5).matrix())
                    .mul(FACING));                                                     // x 90..110, y 90..110
            Framebuffer f = new Framebuffer(200, 200);
            r.render(draws, PERSPECTIVE, f);
            assertArrayEquals(new int[] {20, 40, 59, 79}, box(f, 0xFF0000));
            assertArrayEquals(new int[] {120, 110, 139, 129}, box(f, 0x00FF00));
            assertArrayEquals(new int[] {90, 90, 109, 109}, box(f, 0x0000FF));
        }
    }

    @Test
    void aMissingTextureIsNamed() {
        Draws draws = new Draws();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> draws.add(SQUARE, new Texture[] {null}, VP));
        assertEquals("the texture of material 0 (default) is null", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> draws.add(SQUARE, new Texture[0], VP));
        assertEquals(0, draws.size());
        assertThrows(IndexOutOfBoundsException.class, () -> draws.drawOf(0));
    }

    /** Bounding box {x0, y0, x1, y1} of the pixels of colour {@code rgb}. */
    private static int[] box(Framebuffer f, int rgb) {
        int x0 = Integer.MAX_VALUE;
        int y0 = Integer.MAX_VALUE;
        int x1 = -1;
        int y1 = -1;
        for (int y = 0; y < f.height(); y++) {
            for (int x = 0; x < f.width(); x++) {
                if ((f.colour()[y * f.width() + x] & 0xFFFFFF) == rgb) {
                    x0 = Math.min(x0, x);
                    y0 = Math.min(y0, y);
                    x1 = Math.max(x1, x);
                    y1 = Math.max(y1, y);
                }
            }
        }
        return new int[] {x0, y0, x1, y1};
    }
}
