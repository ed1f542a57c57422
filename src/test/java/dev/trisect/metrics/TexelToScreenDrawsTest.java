package dev.trisect.metrics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Mat4;
import dev.trisect.math.Quaternion;
import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.mesh.Primitives;
import dev.trisect.pipeline.Draws;
import dev.trisect.scene.Camera;
import dev.trisect.texture.Texture;
import org.junit.jupiter.api.Test;

/** The exact texel-to-screen maps of a frame of several draws, each with its own transform. */
class TexelToScreenDrawsTest {
    private static final Viewport VIEWPORT = new Viewport(320, 200);

    /** {@code mesh} with every position taken through {@code model}: what the draw shows, in world space. */
    private static Mesh placed(Mesh mesh, Mat4 model) {
        MeshBuilder b = new MeshBuilder();
        double[] p = new double[4];
        float[] pos = mesh.positions();
        for (int i = 0; i < mesh.positionCount(); i++) {
            model.transformPoint(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], p, 0);
            b.position(p[0] / p[3], p[1] / p[3], p[2] / p[3]);
        }
        float[] uv = mesh.uvs();
        for (int i = 0; i < mesh.uvCount(); i++) {
            b.uv(uv[2 * i], uv[2 * i + 1]);
        }
        int[] cp = mesh.cornerPositions();
        int[] cu = mesh.cornerUvs();
        for (int t = 0; t < mesh.triangleCount(); t++) {
            b.material(mesh.materialNames().get(mesh.triangleMaterials()[t]));
            b.triangle(cp[3 * t], cp[3 * t + 1], cp[3 * t + 2], cu[3 * t], cu[3 * t + 1], cu[3 * t + 2]);
        }
        return b.build();
    }

    @Test
    void eachDrawsTrianglesMapAsTheSameTrianglesPlacedInTheWorld() {
        Mat4 vp = Camera.looking(new Vec3(1, 3, 6), new Vec3(0, 0.5, 0)).viewProjection(VIEWPORT);
        Mesh ground = Primitives.plane(8, 8, 2, 2);
        Mesh box = Primitives.box(1, 1, 1);
        Texture small = Texture.solid("a", 0xFF112233);
        Texture grid = dev.trisect.texture.ProceduralTextures.uvGrid(64);
        Mat4 boxModel = Transform.translation(1, 0.5, -1).withRotation(Quaternion.ofY(35)).matrix();
        Draws draws = new Draws();
        draws.add(ground, new Texture[] {small}, vp);
        draws.add(box, new Texture[] {grid}, vp.mul(boxModel));
        TexelToScreen frame = new TexelToScreen(draws, VIEWPORT);
        TexelToScreen groundAlone = new TexelToScreen(ground, new Texture[] {small}, vp, VIEWPORT);
        TexelToScreen boxInWorld = new TexelToScreen(placed(box, boxModel), new Texture[] {grid}, vp, VIEWPORT);
        assertEquals(ground.triangleCount() + box.triangleCount(), frame.triangleCount());
        int compared = 0;
        for (int t = 0; t < ground.triangleCount(); t++) {
            compared += same(groundAlone.screenOf(t, 0.3, 0.6), frame.screenOf(t, 0.3, 0.6));
        }
        int first = draws.firstTriangle(1);
        for (int t = 0; t < box.triangleCount(); t++) {
            compared += same(boxInWorld.screenOf(t, 20.5, 40.25), frame.screenOf(first + t, 20.5, 40.25));
            assertEquals(boxInWorld.displacement(t, 20.5, 40.25, 100, 90),
                    frame.displacement(first + t, 20.5, 40.25, 100, 90), 1e-6);
        }
        assertTrue(compared > box.triangleCount(), "most triangles project: " + compared);
    }

    /** 1 when both points exist and agree, 0 when neither exists; fails otherwise. */
    private static int same(double[] expected, double[] actual) {
        if (expected == null) {
            assertEquals(null, actual);
            return 0;
        }
        assertNotNull(actual);
        // The draw's matrix is projection * view * model, the world mesh's positions model-transformed
        // floats: they agree to float precision of the positions, far below a pixel.
        assertEquals(expected[0], actual[0], 1e-4);
        assertEquals(expected[1], actual[1], 1e-4);
        return 1;
    }
}
