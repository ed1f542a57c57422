package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.render.CullMode;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.TessellationSettings;
import dev.trisect.scene.Camera;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

/**
 * The span path's promise, measured exactly: with knots spaced for a max error E, no pixel's texture
 * lands more than E pixels from where perspective puts it (docs/math.md, "The span path"), on the
 * scenes {@link DisplacementBoundTest} holds the tessellated path to — the 10 km plane from the near
 * plane to the horizon, the plane with texel coordinates in the thousands, issue 6's floor, triangles
 * cut by the near plane — and on the 10 km plane seen with the camera rolled, where depth changes
 * along every row (a level camera over a level plane sees constant depth along its rows, where the
 * span path is exact). The slack is 0.002 px as there, though the span path needs none for snapping:
 * a knot is the exact texel coordinates of its pixel centre on the triangle's plane, inside the
 * triangle or not. Every pixel is measured by mapping its texel coordinates back to the 3D point
 * that carries them ({@link ExactDisplacement}).
 */
class SpanBoundTest {
    private static final double SLACK = 0.002;
    private static final double[] ALL_THRESHOLDS = {0.05, 0.1, 0.25, 0.5, 1, 2, 4, 8, 16};
    private static final FrameRenderer RENDERER = new FrameRenderer(2);
    private static final Texture[] TEX = {TestScenes.distinctTexels()};

    @AfterAll
    static void close() {
        RENDERER.close();
    }

    private static RenderSettings spans(double maxError) {
        return RenderSettings.defaults().withCull(CullMode.NONE).withMode(RenderMode.SPANS)
                .withTessellation(TessellationSettings.defaults()).withKnotError(maxError);
    }

    /** Renders with the span path at each threshold and checks every covered pixel; returns the worst of each. */
    private static double[] check(String name, Mesh mesh, Camera camera, int w, int h, double... thresholds) {
        Mat4 vp = camera.viewProjection(new Viewport(w, h));
        double[] worst = new double[thresholds.length];
        for (int k = 0; k < thresholds.length; k++) {
            double e = thresholds[k];
            for (TextureFilter filter : new TextureFilter[] {TextureFilter.NEAREST, TextureFilter.TRILINEAR}) {
                Framebuffer fb = new Framebuffer(w, h);
                fb.recordUv(true);
                FrameStats st = RENDERER.render(mesh, TEX, vp, spans(e).withFilter(filter), fb);
                ExactDisplacement.Result r = ExactDisplacement.measure(mesh, TEX, vp, fb);
                String what = name + " spans " + e + " px " + filter + ": ";
                assertTrue(r.pixels() > w * h / 10, what + "enough of the frame is covered: " + r.pixels());
                assertTrue(r.worst() <= e + SLACK, what + "pixel " + r.worstX() + "," + r.worstY() + " is "
                        + r.worst() + " px off; " + st.toJson());
                worst[k] = Math.max(worst[k], r.worst());
            }
        }
        return worst;
    }

    /** The 10 km plane seen with the camera rolled by {@code degrees} about its view direction. */
    static Camera rolledPlaneCamera(double degrees) {
        Camera c = DisplacementBoundTest.planeCamera();
        Vec3 forward = c.target().sub(c.eye()).normalize();
        Vec3 right = forward.cross(Vec3.UP).normalize();
        Vec3 up = right.cross(forward);
        double a = Math.toRadians(degrees);
        return new Camera(c.eye(), c.target(), up.scale(Math.cos(a)).add(right.scale(Math.sin(a))), c.fovY(),
                c.near(), c.far());
    }

    @Test
    void planeFromTheNearPlaneToTenKilometresAtFullHd() {
        check("10 km plane", DisplacementBoundTest.plane(10_000, 1), DisplacementBoundTest.planeCamera(), 1920, 1080,
                0.05, 0.5, 16);
    }

    @Test
    void rolledPlaneFromTheNearPlaneToTenKilometresAtFullHdAndTheBoundIsTight() {
        double[] thresholds = {0.05, 0.5, 4};
        double[] worst = check("rolled 10 km plane", DisplacementBoundTest.plane(10_000, 1), rolledPlaneCamera(30),
                1920, 1080, thresholds);
        for (int k = 0; k < thresholds.length; k++) {
            // Knots as far apart as the bound allows: the worst pixel comes close to it.
            assertTrue(worst[k] > 0.8 * thresholds[k], "the knots use the error allowed: " + worst[k] + " px at "
                    + thresholds[k]);
        }
    }

    @Test
    void planeWithLargeTexelCoordinatesAtFullHd() {
        check("offset-UV plane", DisplacementBoundTest.offsetUvPlane(), DisplacementBoundTest.offsetUvPlaneCamera(),
                1920, 1080, 0.5);
    }

    @Test
    void issueFloorAtEveryThreshold() {
        check("issue floor", DisplacementBoundTest.issueFloor(), DisplacementBoundTest.issueFloorCamera(), 640, 360,
                ALL_THRESHOLDS);
    }

    @Test
    void rolledIssueFloorAtEveryThreshold() {
        Camera c = DisplacementBoundTest.issueFloorCamera();
        Camera rolled = new Camera(c.eye(), c.target(), new Vec3(0.5, 1, 0), c.fovY(), c.near(), c.far());
        check("rolled issue floor", DisplacementBoundTest.issueFloor(), rolled, 640, 360, ALL_THRESHOLDS);
    }

    @Test
    void trianglesCutByTheNearPlaneAtEveryThreshold() {
        Mesh mesh = DisplacementBoundTest.nearPlaneTriangles();
        check("near-plane triangles", mesh, DisplacementBoundTest.nearPlaneCamera(), 320, 240, ALL_THRESHOLDS);
        Framebuffer fb = new Framebuffer(320, 240);
        FrameStats st = RENDERER.render(mesh, TEX, DisplacementBoundTest.nearPlaneCamera()
                .viewProjection(new Viewport(320, 240)), spans(0.5), fb);
        assertEquals(3, st.clipped(), "all three are cut by the near plane: " + st.toJson());
    }

    /**
     * The knots follow the span path's own knot error and nothing of the split policy: changing the
     * error policy's max error leaves the frame bit for bit, changing the knot error does not.
     */
    @Test
    void theKnotsFollowTheKnotErrorAndNotTheSplitPolicysMaxError() {
        Mat4 vp = rolledPlaneCamera(30).viewProjection(new Viewport(320, 180));
        Mesh mesh = DisplacementBoundTest.plane(10_000, 1);
        Framebuffer a = new Framebuffer(320, 180);
        RENDERER.render(mesh, TEX, vp, spans(0.5), a);
        Framebuffer b = new Framebuffer(320, 180);
        RENDERER.render(mesh, TEX, vp, spans(0.5).withTessellation(TessellationSettings.defaults().withMaxError(8)), b);
        assertArrayEquals(a.colour(), b.colour(), "max error is the error policy's, not the knots'");
        Framebuffer c = new Framebuffer(320, 180);
        RENDERER.render(mesh, TEX, vp, spans(8), c);
        assertTrue(!java.util.Arrays.equals(a.colour(), c.colour()), "the knot error spaces the knots");
    }

    /**
     * The span path covers exactly the pixels the per-pixel path covers, with the same depth bit for bit
     * (1/w from the same plane at every pixel), on every thread count.
     */
    @Test
    void coverageAndDepthAreThePerPixelPathsOnEveryThreadCount() {
        Mesh mesh = DisplacementBoundTest.nearPlaneTriangles();
        Camera camera = DisplacementBoundTest.nearPlaneCamera();
        Mat4 vp = camera.viewProjection(new Viewport(320, 240));
        Framebuffer perPixel = new Framebuffer(320, 240);
        perPixel.recordUv(true);
        RENDERER.render(mesh, TEX, vp, spans(0.5).withMode(RenderMode.PERSPECTIVE), perPixel);
        Framebuffer first = null;
        for (int threads = 1; threads <= 3; threads++) {
            try (FrameRenderer r = new FrameRenderer(threads)) {
                Framebuffer fb = new Framebuffer(320, 240);
                fb.recordUv(true);
                r.render(mesh, TEX, vp, spans(0.5), fb);
                assertArrayEquals(perPixel.depth(), fb.depth(), threads + " threads: depth");
                if (first == null) {
                    first = fb;
                } else {
                    assertArrayEquals(first.colour(), fb.colour(), threads + " threads: colour");
                    assertArrayEquals(first.uv(), fb.uv(), threads + " threads: UV output");
                }
            }
        }
    }
}
