package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.texture.Texture;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Geometry at the limits of double precision (issue 14, item 6): a quad of half-size 10^e in the
 * plane z = 0, seen from 3 units away, is either drawn as it is (covering the whole frame, as it does
 * at every size) or counted in skipped_invalid; never dropped silently, never drawn wrong.
 */
class MagnitudeLimitsTest {
    private static final FrameRenderer RENDERER = new FrameRenderer(2);
    private static final Texture[] TEX = {TestScenes.distinctTexels()};
    private static final int W = 64;
    private static final int H = 48;

    @AfterAll
    static void close() {
        RENDERER.close();
    }

    private static Mesh quad(double half) {
        MeshBuilder b = new MeshBuilder();
        int p0 = b.position(-half, -half, 0);
        int p1 = b.position(half, -half, 0);
        int p2 = b.position(half, half, 0);
        int p3 = b.position(-half, half, 0);
        int t0 = b.uv(0, 0);
        int t1 = b.uv(1, 0);
        int t2 = b.uv(1, 1);
        int t3 = b.uv(0, 1);
        b.triangle(p0, p1, p2, t0, t1, t2);
        b.triangle(p0, p2, p3, t0, t2, t3);
        return b.build();
    }

    private static FrameStats render(Mesh mesh, Camera camera, RenderMode mode) {
        Framebuffer fb = new Framebuffer(W, H);
        return RENDERER.render(mesh, TEX, camera.viewProjection(new Viewport(W, H)),
                RenderSettings.defaults().withMode(mode), fb);
    }

    @ParameterizedTest
    @ValueSource(ints = {3, 6, 8, 9, 12, 15, 16, 17, 20, 30, 37})
    void aHugeQuadIsDrawnWholeOrCountedAsSkipped(int exponent) {
        Mesh mesh = quad(Math.pow(10, exponent));
        for (Vec3 eye : new Vec3[] {new Vec3(0, 0, 3), new Vec3(1, 2, 3)}) {
            for (RenderMode mode : new RenderMode[] {RenderMode.PERSPECTIVE, RenderMode.TESSELLATED}) {
                FrameStats s = render(mesh, Camera.looking(eye, Vec3.ZERO), mode);
                String where = "10^" + exponent + " from " + eye + " " + mode + ": " + s;
                assertEquals(2, s.trianglesIn(), where);
                if (s.skippedInvalid() == 0) {
                    assertEquals((long) W * H, s.pixelsWritten(), where);
                } else {
                    assertEquals(2, s.skippedInvalid(), where);
                    assertEquals(0, s.pixelsWritten(), where);
                }
                if (exponent <= 8) {
                    assertEquals(0, s.skippedInvalid(), "well within the limits: " + where);
                }
                if (exponent >= 17) {
                    // The case of the issue: 0 pixels and skipped_invalid 0 before.
                    assertEquals(2, s.skippedInvalid(), "beyond double precision: " + where);
                }
            }
        }
    }

    @Test
    void upOfAnyFiniteMagnitudeGivesTheSameFrame() {
        Mesh floor = TestScenes.floor(8);
        Camera unit = TestScenes.floorCamera();
        int[] expected = TestScenes.render(RENDERER, floor, unit, RenderSettings.defaults(), W, H).colour().clone();
        for (double m : new double[] {1e300, 1e160, 1e-160, 1e-300}) {
            Camera scaled = new Camera(unit.eye(), unit.target(), unit.up().scale(m), unit.fovY(), unit.near(),
                    unit.far());
            int[] got = TestScenes.render(RENDERER, floor, scaled, RenderSettings.defaults(), W, H).colour();
            org.junit.jupiter.api.Assertions.assertArrayEquals(expected, got, "up scaled by " + m);
        }
        IllegalArgumentException zero = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> new Camera(unit.eye(), unit.target(), new Vec3(0, -0.0, 0), 60, 0.1, 100));
        assertEquals("up (0.0,-0.0,0.0) is zero: it must give the direction of up", zero.getMessage());
    }

    @Test
    void aFlatTriangleStaysDegenerateAndAnOrdinaryEdgeOnOneIsNotSkipped() {
        MeshBuilder b = new MeshBuilder();
        int p0 = b.position(-1e9, 0, 0);
        int p1 = b.position(0, 0, 0);
        int p2 = b.position(1e9, 0, 0);
        int t = b.uv(0, 0);
        b.triangle(p0, p1, p2, t, t, t);
        // A unit square seen exactly edge-on.
        int q0 = b.position(-1, -1, -5);
        int q1 = b.position(-1, 1, -5);
        int q2 = b.position(-1, 1, -6);
        b.triangle(q0, q1, q2, t, t, t);
        FrameStats s = render(b.build(), Camera.looking(new Vec3(-1, 0.5, 3), new Vec3(-1, 0.5, 0)),
                RenderMode.PERSPECTIVE);
        assertEquals(0, s.skippedInvalid(), s.toString());
        assertTrue(s.culledDegenerate() >= 1, s.toString());
    }
}
