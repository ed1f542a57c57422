package dev.trisect.metrics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.texture.Texture;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The exact displacement ({@link TexelToScreen} through {@link ImageComparison}) on cases whose answer
 * is known in closed form: an affinely textured tilted triangle, whose displacement is equation (3) of
 * docs/math.md, and UV buffers built by hand from chosen 3D points.
 */
class ExactDisplacementTest {
    private static final int W = 160;
    private static final int H = 120;
    private static final Viewport VIEWPORT = new Viewport(W, H);
    /** Looking down onto a plane that recedes: depths 1.8 to 16 across the triangle. */
    private static final Mat4 VP = Mat4.perspective(60, VIEWPORT.aspect(), 0.5, 100)
            .mul(Mat4.lookAt(new Vec3(0, 1.2, 2), new Vec3(0, 0, -6), Vec3.UP));
    private static final Vec3[] CORNERS = {new Vec3(-1.625, 0, 0.375), new Vec3(2.25, 0, -0.625), new Vec3(0.25, 0, -14)};
    /** Positions and UVs a float holds exactly, so that the mesh's floats are the values used here. */
    private static final double[][] UVS = {{0.125, 0.0625}, {0.875, 0.1875}, {0.375, 0.9375}};
    private static final Texture[] TEXTURE = {texture(64, 48)};

    private static Texture texture(int w, int h) {
        int[] argb = new int[w * h];
        for (int i = 0; i < argb.length; i++) {
            argb[i] = 0xFF000000 | (i * 0x9E3779B1 >>> 8);
        }
        return new Texture("distinct", w, h, argb);
    }

    private static Mesh triangle(double[][] uvs) {
        MeshBuilder b = new MeshBuilder();
        int p0 = b.position(CORNERS[0]);
        int p1 = b.position(CORNERS[1]);
        int p2 = b.position(CORNERS[2]);
        if (uvs == null) {
            b.triangle(p0, p1, p2, -1, -1, -1);
        } else {
            b.triangle(p0, p1, p2, b.uv(uvs[0][0], uvs[0][1]), b.uv(uvs[1][0], uvs[1][1]),
                    b.uv(uvs[2][0], uvs[2][1]));
        }
        return b.build();
    }

    private static Framebuffer render(Mesh mesh, RenderMode mode) {
        Framebuffer fb = new Framebuffer(W, H);
        fb.recordUv(true);
        try (FrameRenderer r = new FrameRenderer(1)) {
            r.render(mesh, TEXTURE, VP, RenderSettings.defaults().withMode(mode), fb);
        }
        return fb;
    }

    /** Clip space (x, y, z, w) of a world point. */
    private static double[] clip(Vec3 p) {
        double[] c = new double[4];
        VP.transformPoint(p.x(), p.y(), p.z(), c, 0);
        return c;
    }

    /**
     * Equation (3) of docs/math.md at the centre of pixel (x, y): the displacement of the affine path,
     * {@code |D(s)| = |(1/Omega) sum_{i<j} s_i s_j (w_i - w_j)(p_i - p_j)|}, {@code Omega = sum s_j w_j},
     * with s the screen barycentric coordinates of the centre, p_i the corners' screen positions and w_i
     * their clip-space w.
     */
    private static double equationThree(int x, int y) {
        double[] px = new double[3];
        double[] py = new double[3];
        double[] w = new double[3];
        for (int i = 0; i < 3; i++) {
            double[] c = clip(CORNERS[i]);
            px[i] = VIEWPORT.screenX(c[0], c[3]);
            py[i] = VIEWPORT.screenY(c[1], c[3]);
            w[i] = c[3];
        }
        double cx = x + 0.5;
        double cy = y + 0.5;
        double area = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
        double[] s = new double[3];
        for (int i = 0; i < 3; i++) {
            int j = (i + 1) % 3;
            int k = (i + 2) % 3;
            s[i] = ((px[k] - px[j]) * (cy - py[j]) - (cx - px[j]) * (py[k] - py[j])) / area;
        }
        double omega = s[0] * w[0] + s[1] * w[1] + s[2] * w[2];
        double dx = 0;
        double dy = 0;
        for (int i = 0; i < 3; i++) {
            for (int j = i + 1; j < 3; j++) {
                double f = s[i] * s[j] * (w[i] - w[j]) / omega;
                dx += f * (px[i] - px[j]);
                dy += f * (py[i] - py[j]);
            }
        }
        return Math.hypot(dx, dy);
    }

    @Test
    void affineTriangleDisplacementIsEquationThreeAndTheEstimateIsNot() {
        Mesh mesh = triangle(UVS);
        Framebuffer affine = render(mesh, RenderMode.AFFINE);
        Framebuffer perspective = render(mesh, RenderMode.PERSPECTIVE);
        float[] exact = new float[W * H];
        float[] estimate = new float[W * H];
        Comparison c = ImageComparison.compare(W, H, affine.colour(), affine.uv(), perspective.colour(),
                perspective.uv(), new TexelToScreen(mesh, TEXTURE, VP, VIEWPORT), exact);
        Comparison e = ImageComparison.compare(W, H, affine.colour(), affine.uv(), perspective.colour(),
                perspective.uv(), estimate);

        assertTrue(c.displacementExact());
        assertFalse(e.displacementExact());
        int covered = 0;
        double expectedMax = 0;
        double worstEstimateError = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int i = y * W + x;
                if (affine.uv()[3 * i + 2] == 0) {
                    assertTrue(Float.isNaN(exact[i]), "uncovered pixel " + x + "," + y);
                    continue;
                }
                covered++;
                double expected = equationThree(x, y);
                expectedMax = Math.max(expectedMax, expected);
                assertEquals(expected, exact[i], 1e-4, "pixel " + x + "," + y);
                if (!Float.isNaN(estimate[i])) {
                    worstEstimateError = Math.max(worstEstimateError, Math.abs(estimate[i] - expected));
                }
            }
        }
        assertTrue(covered > W * H / 8, "the triangle covers a fair part of the frame: " + covered);
        assertEquals(covered, c.comparedPixels());
        assertEquals(covered, c.displacementPixels());
        assertEquals(0, c.degenerateUvPixels());
        assertTrue(expectedMax > 5, "a bending case: affine is far off, " + expectedMax + " px");
        assertEquals(expectedMax, c.maxDisplacement(), 1e-4);
        // The linearised estimate misreads the bent perspective map by far more than the tolerance.
        assertTrue(worstEstimateError > 0.1, "the estimate is off by " + worstEstimateError + " px at worst");
    }

    @Test
    void thePerspectivePathShowsEveryTexelWhereItBelongs() {
        Mesh mesh = triangle(UVS);
        Framebuffer perspective = render(mesh, RenderMode.PERSPECTIVE);
        Comparison c = ImageComparison.compare(W, H, perspective.colour(), perspective.uv(), perspective.colour(),
                perspective.uv(), new TexelToScreen(mesh, TEXTURE, VP, VIEWPORT), null);
        assertTrue(c.comparedPixels() > W * H / 8);
        // The texel coordinates are kept in doubles: only double rounding remains.
        assertTrue(c.maxDisplacement() < 1e-4, "perspective path off by " + c.maxDisplacement() + " px");
    }

    @Test
    void handBuiltTexelCoordinatesMapToTheirPointsProjection() {
        // UVs repeated many times, so that texel coordinates are large and cancellation would show.
        double[][] uvs = {{300.125, -200.0625}, {300.875, -199.8125}, {300.375, -199.0625}};
        Mesh mesh = triangle(uvs);
        TexelToScreen maps = new TexelToScreen(mesh, TEXTURE, VP, VIEWPORT);
        Random rnd = new Random(6);
        double[] uv = new double[3 * W * H];
        double[] expected = new double[W * H];
        for (int i = 0; i < W * H; i++) {
            int x = i % W;
            int y = i / W;
            // A point of the triangle's plane (barycentric weights may leave the triangle a little).
            double b1 = rnd.nextDouble() * 1.2 - 0.1;
            double b2 = rnd.nextDouble() * (1.1 - b1) - 0.05;
            double b0 = 1 - b1 - b2;
            Vec3 p = CORNERS[0].scale(b0).add(CORNERS[1].scale(b1)).add(CORNERS[2].scale(b2));
            double s = (b0 * uvs[0][0] + b1 * uvs[1][0] + b2 * uvs[2][0]) * 64;
            double t = (b0 * uvs[0][1] + b1 * uvs[1][1] + b2 * uvs[2][1]) * 48;
            UvFields.set(uv, W, x, y, s, t, 1);
            // The expected point is the one the stored values name (doubles: (s, t) as computed).
            double fs = uv[3 * i];
            double ft = uv[3 * i + 1];
            double f1 = solve(uvs, fs / 64, ft / 48, 1);
            double f2 = solve(uvs, fs / 64, ft / 48, 2);
            Vec3 q = CORNERS[0].scale(1 - f1 - f2).add(CORNERS[1].scale(f1)).add(CORNERS[2].scale(f2));
            double[] c = clip(q);
            expected[i] = Math.hypot(VIEWPORT.screenX(c[0], c[3]) - (x + 0.5), VIEWPORT.screenY(c[1], c[3]) - (y + 0.5));
            assertTrue(p.sub(q).length() < 1e-9, "storing moves the point by rounding only");
        }
        float[] out = new float[W * H];
        int[] argb = new int[W * H];
        Comparison c = ImageComparison.compare(W, H, argb, uv, argb, uv, maps, out);
        float[] alone = new float[W * H];
        ImageComparison.displacements(W, H, uv, uv, maps, alone);
        double max = 0;
        for (int i = 0; i < W * H; i++) {
            assertEquals(expected[i], out[i], 1e-4 + 1e-6 * expected[i], "pixel " + i);
            assertEquals(out[i], alone[i], "per-pixel only equals the full comparison");
            assertEquals(out[i], maps.displacement(0, uv[3 * i], uv[3 * i + 1], i % W, i / W), 1e-3);
            max = Math.max(max, out[i]);
        }
        assertEquals(W * H, c.displacementPixels());
        assertEquals(max, c.maxDisplacement());
        double[] at = maps.screenOf(0, uv[0], uv[1]);
        assertEquals(expected[0], Math.hypot(at[0] - 0.5, at[1] - 0.5), 1e-4);
    }

    /** Barycentric weight {@code which} (1 or 2) of the point with UV (u, v) in the triangle's UV space. */
    private static double solve(double[][] uvs, double u, double v, int which) {
        double a = uvs[1][0] - uvs[0][0];
        double b = uvs[2][0] - uvs[0][0];
        double c = uvs[1][1] - uvs[0][1];
        double d = uvs[2][1] - uvs[0][1];
        double du = u - uvs[0][0];
        double dv = v - uvs[0][1];
        double det = a * d - b * c;
        return which == 1 ? (d * du - b * dv) / det : (a * dv - c * du) / det;
    }

    @Test
    void degenerateUvMappingIsLeftOutAndCounted() {
        // No texture coordinates: every corner has UV (0, 0), so no texel names a single point.
        Mesh mesh = triangle(null);
        Framebuffer fb = render(mesh, RenderMode.AFFINE);
        TexelToScreen maps = new TexelToScreen(mesh, TEXTURE, VP, VIEWPORT);
        float[] out = new float[W * H];
        Comparison c = ImageComparison.compare(W, H, fb.colour(), fb.uv(), fb.colour(), fb.uv(), maps, out);
        assertTrue(maps.isDegenerate(0));
        assertTrue(c.comparedPixels() > W * H / 8);
        assertEquals(c.comparedPixels(), c.degenerateUvPixels());
        assertEquals(0, c.displacementPixels());
        assertTrue(Double.isNaN(c.maxDisplacement()));
        assertTrue(c.toJson().contains("\"max_displacement\":null,"), c.toJson());
        for (float d : out) {
            assertTrue(Float.isNaN(d));
        }
        assertNull(maps.screenOf(0, 0, 0));
        // Collinear texture coordinates are degenerate too.
        Mesh collinear = triangle(new double[][] {{0, 0}, {0.5, 0.25}, {1, 0.5}});
        assertTrue(new TexelToScreen(collinear, TEXTURE, VP, VIEWPORT).isDegenerate(0));
        assertFalse(new TexelToScreen(triangle(UVS), TEXTURE, VP, VIEWPORT).isDegenerate(0));
    }

    @Test
    void idsOfOtherTrianglesOrOutOfRangeHaveNoDisplacement() {
        Mesh mesh = triangle(UVS);
        TexelToScreen maps = new TexelToScreen(mesh, TEXTURE, VP, VIEWPORT);
        assertTrue(Double.isNaN(maps.displacement(1, 10, 10, 0, 0)));
        assertTrue(Double.isNaN(maps.displacement(-1, 10, 10, 0, 0)));
        assertFalse(maps.isDegenerate(5));
        // A pixel whose id names no triangle of the mesh is compared (same id in both) but has none.
        double[] uv = new double[3 * W * H];
        UvFields.set(uv, W, 3, 4, 10, 10, 7);
        int[] argb = new int[W * H];
        Comparison c = ImageComparison.compare(W, H, argb, uv, argb, uv, maps, null);
        assertEquals(1, c.comparedPixels());
        assertEquals(0, c.displacementPixels());
        assertEquals(0, c.degenerateUvPixels());
    }
}
