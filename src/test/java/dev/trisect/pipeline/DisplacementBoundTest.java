package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.raster.Framebuffer;
import dev.trisect.scene.Camera;
import dev.trisect.tessellate.SplitPolicy;
import dev.trisect.tessellate.TessellationSettings;
import dev.trisect.texture.Texture;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The headline promise, measured exactly: under either split policy with threshold E, no pixel's
 * texture lands more than E pixels from where perspective puts it (plus 0.002 px for the 1/256-px
 * snapping of coverage), on scenes made to break it — a plane from the near plane to the horizon,
 * triangles cut by the near plane — and whether or not a cap stops the splitting, because the
 * fallback fills what a cap leaves failing per pixel.
 */
class DisplacementBoundTest {
    /** Slack for a centre covered up to 1/256 px outside its unsnapped piece (docs/math.md). */
    private static final double SNAP_SLACK = 0.002;
    private static final double[] ALL_THRESHOLDS = {0.05, 0.1, 0.25, 0.5, 1, 2, 4, 8, 16};
    private static final FrameRenderer RENDERER = new FrameRenderer(2);
    private static final Texture[] TEX = {TestScenes.distinctTexels()};

    @AfterAll
    static void close() {
        RENDERER.close();
    }

    /**
     * A square of side {@code 2 * half} on y = 0 centred under the origin, texture repeated once per
     * {@code repeat} units, texel coordinates 0 at the centre (so that the float UV output stays
     * precise near a camera above the centre).
     */
    static Mesh plane(double half, double repeat) {
        MeshBuilder b = new MeshBuilder();
        double r = half / repeat;
        int p0 = b.position(-half, 0, half);
        int p1 = b.position(half, 0, half);
        int p2 = b.position(half, 0, -half);
        int p3 = b.position(-half, 0, -half);
        int t0 = b.uv(-r, -r);
        int t1 = b.uv(r, -r);
        int t2 = b.uv(r, r);
        int t3 = b.uv(-r, r);
        b.triangle(p0, p1, p2, t0, t1, t2);
        b.triangle(p0, p2, p3, t0, t2, t3);
        return b.build();
    }

    /** Issue 6's floor: 80 m wide from z = +10 to z = -400, texture repeated 16 x 84 times. */
    static Mesh issueFloor() {
        MeshBuilder b = new MeshBuilder();
        int p0 = b.position(-40, 0, 10);
        int p1 = b.position(40, 0, 10);
        int p2 = b.position(40, 0, -400);
        int p3 = b.position(-40, 0, -400);
        int t0 = b.uv(0, 0);
        int t1 = b.uv(16, 0);
        int t2 = b.uv(16, 84);
        int t3 = b.uv(0, 84);
        b.triangle(p0, p1, p2, t0, t1, t2);
        b.triangle(p0, p2, p3, t0, t2, t3);
        return b.build();
    }

    static Camera issueFloorCamera() {
        return new Camera(new Vec3(0, 1.7, 6), new Vec3(3, 0.2, -40), Vec3.UP, 60, 0.1, 1000);
    }

    /** The 10 km plane: eye 1.6 m above it, near plane 1 cm, looking a little down toward the horizon. */
    static Camera planeCamera() {
        return new Camera(new Vec3(0, 1.6, 0), new Vec3(0, 0.6, -10), Vec3.UP, 60, 0.01, 20000);
    }

    /** Slanted triangles through the camera's plane, each cut by the near plane. */
    static Mesh nearPlaneTriangles() {
        MeshBuilder b = new MeshBuilder();
        double[][][] tris = {
            {{-3, -1, 4}, {5, -0.6, -30}, {-2, 1.5, -9}},
            {{2, -1.2, 1}, {-1, 0.8, -6}, {-6, -0.4, -60}},
            {{-0.5, 0.3, 2}, {0.6, -0.2, -0.05}, {0.2, 0.9, -3}},
        };
        double[][] uvs = {{0, 0}, {7, 1}, {2, 5}};
        for (double[][] t : tris) {
            int[] p = new int[3];
            int[] u = new int[3];
            for (int k = 0; k < 3; k++) {
                p[k] = b.position(t[k][0], t[k][1], t[k][2]);
                u[k] = b.uv(uvs[k][0], uvs[k][1]);
            }
            b.triangle(p[0], p[1], p[2], u[0], u[1], u[2]);
        }
        return b.build();
    }

    static Camera nearPlaneCamera() {
        return new Camera(new Vec3(0, 0, 0), new Vec3(0.1, 0, -1), Vec3.UP, 70, 0.05, 500);
    }

    /** Renders with the tessellated path, measures every covered pixel exactly, checks the bound. */
    private static FrameStats check(String name, Mesh mesh, Camera camera, int w, int h, TessellationSettings t,
                                    double threshold) {
        Mat4 vp = camera.viewProjection(new Viewport(w, h));
        Framebuffer fb = new Framebuffer(w, h);
        fb.recordUv(true);
        RenderSettings s = RenderSettings.defaults().withCull(CullMode.NONE).withTessellation(t);
        FrameStats st = RENDERER.render(mesh, TEX, vp, s, fb);
        ExactDisplacement.Result r = ExactDisplacement.measure(mesh, TEX, vp, fb);
        String what = name + " " + t.policy() + " " + threshold + " px: ";
        assertTrue(r.pixels() > w * h / 10, what + "enough of the frame is covered: " + r.pixels());
        assertTrue(r.worst() <= threshold + SNAP_SLACK, what + "pixel " + r.worstX() + "," + r.worstY()
                + " is " + r.worst() + " px off; " + st.toJson());
        assertTrue(st.capsReached() == 0 || st.piecesFallback() > 0,
                what + "when a cap is reached the fallback takes over: " + st.toJson());
        return st;
    }

    private static TessellationSettings settings(SplitPolicy policy, double threshold) {
        return TessellationSettings.defaults().withPolicy(policy).withMaxEdge(threshold).withMaxError(threshold);
    }

    static Stream<Arguments> policies() {
        return Stream.of(SplitPolicy.values()).map(Arguments::of);
    }

    /** Checks the bound at each threshold; returns the statistics of each frame. */
    private static FrameStats[] checkAll(String name, Mesh mesh, Camera camera, int w, int h, SplitPolicy policy,
                                         double... thresholds) {
        FrameStats[] out = new FrameStats[thresholds.length];
        for (int i = 0; i < thresholds.length; i++) {
            out[i] = check(name, mesh, camera, w, h, settings(policy, thresholds[i]), thresholds[i]);
        }
        return out;
    }

    @ParameterizedTest
    @MethodSource("policies")
    void planeFromTheNearPlaneToTenKilometresAtFullHd(SplitPolicy policy) {
        checkAll("10 km plane", plane(10_000, 1), planeCamera(), 1920, 1080, policy, 0.05, 0.5, 16);
    }

    @ParameterizedTest
    @MethodSource("policies")
    void issueFloorAtEveryThreshold(SplitPolicy policy) {
        checkAll("issue floor", issueFloor(), issueFloorCamera(), 640, 360, policy, ALL_THRESHOLDS);
    }

    @ParameterizedTest
    @MethodSource("policies")
    void trianglesCutByTheNearPlaneAtEveryThreshold(SplitPolicy policy) {
        for (FrameStats st : checkAll("near-plane triangles", nearPlaneTriangles(), nearPlaneCamera(), 320, 240,
                policy, ALL_THRESHOLDS)) {
            assertEquals(3, st.clipped(), "all three are cut by the near plane: " + st.toJson());
        }
    }

    @Test
    void capsHandTheRestToTheFallbackAndTheBoundStillHolds() {
        Mesh plane = plane(10_000, 1);
        TessellationSettings base = settings(SplitPolicy.ERROR, 0.25);
        // Tight caps of every kind: per edge level, per triangle pieces.
        for (TessellationSettings t : new TessellationSettings[] {
                base.withMaxDepth(0), base.withMaxDepth(3), base.withMaxPieces(1), base.withMaxPieces(50)}) {
            FrameStats st = check("10 km plane, caps", plane, planeCamera(), 480, 270, t, 0.25);
            assertTrue(st.capsReached() > 0 && st.piecesFallback() > 0, "the caps bite: " + st.toJson());
            assertTrue(st.toJson().contains("\"pieces_fallback\":" + st.piecesFallback()), st.toJson());
        }
    }
}
