package dev.trisect.pipeline;

import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.render.Framebuffer;
import dev.trisect.scene.Camera;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.texture.Texture;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The perspective path's UV output against an exact oracle on whole scenes: the ray through each
 * pixel centre is intersected, in double precision, with the triangle the pixel says it shows, and
 * the texel coordinates there are interpolated from that triangle's corners.
 */
class ExactUvTest {
    private static final int W = 400;
    private static final int H = 240;
    private static final FrameRenderer RENDERER = new FrameRenderer(2);

    @AfterAll
    static void close() {
        RENDERER.close();
    }

    @ParameterizedTest
    @ValueSource(strings = {"floor", "boxes", "demo"})
    void everyPixelShowsTheTexelItsRayHits(String name) {
        SceneAsset scene = DemoScenes.byName(name).orElseThrow();
        Camera cam = scene.camera();
        Framebuffer fb = new Framebuffer(W, H);
        fb.recordUv(true);
        RENDERER.render(scene.mesh(), scene.textureArray(), cam.viewProjection(new Viewport(W, H)),
                RenderSettings.defaults().withMode(RenderMode.PERSPECTIVE), fb);
        Vec3 f = cam.target().sub(cam.eye()).normalize();
        Vec3 r = f.cross(cam.up()).normalize();
        Vec3 u = r.cross(f);
        double tan = Math.tan(Math.toRadians(cam.fovY()) / 2);
        double worst = 0;
        int checked = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int i = y * W + x;
                int id = (int) fb.uv()[3 * i + 2];
                if (id == 0) {
                    continue;
                }
                double nx = (x + 0.5) / W * 2 - 1;
                double ny = 1 - (y + 0.5) / H * 2;
                Vec3 dir = f.add(r.scale(nx * tan * W / H)).add(u.scale(ny * tan));
                double[] exact = texelOnTriangle(scene, id - 1, cam.eye(), dir);
                double err = Math.hypot(fb.uv()[3 * i] - exact[0], fb.uv()[3 * i + 1] - exact[1]);
                // Relative slack for the float the UV output is stored in.
                double allowed = 0.002 + 2e-7 * (Math.abs(exact[0]) + Math.abs(exact[1]));
                assertTrue(err <= allowed, name + " pixel " + x + "," + y + ": " + err + " texels off");
                worst = Math.max(worst, err);
                checked++;
            }
        }
        assertTrue(checked > W * H / 3, name + ": enough pixels checked");
    }

    /** Texel coordinates where the ray eye + k * dir meets the plane of triangle {@code t}. */
    private static double[] texelOnTriangle(SceneAsset scene, int t, Vec3 eye, Vec3 dir) {
        Mesh m = scene.mesh();
        Vec3[] p = new Vec3[3];
        double[][] st = new double[3][2];
        Texture tex = scene.textures().get(m.triangleMaterials()[t]);
        for (int k = 0; k < 3; k++) {
            int pi = m.cornerPositions()[3 * t + k];
            p[k] = new Vec3(m.positions()[3 * pi], m.positions()[3 * pi + 1], m.positions()[3 * pi + 2]);
            int ui = m.cornerUvs()[3 * t + k];
            st[k][0] = ui < 0 ? 0 : m.uvs()[2 * ui] * tex.width();
            st[k][1] = ui < 0 ? 0 : m.uvs()[2 * ui + 1] * tex.height();
        }
        // Moller-Trumbore without the inside test: barycentrics of the ray's hit on the plane.
        Vec3 e1 = p[1].sub(p[0]);
        Vec3 e2 = p[2].sub(p[0]);
        Vec3 pv = dir.cross(e2);
        double det = e1.dot(pv);
        Vec3 tv = eye.sub(p[0]);
        double b1 = tv.dot(pv) / det;
        Vec3 qv = tv.cross(e1);
        double b2 = dir.dot(qv) / det;
        double b0 = 1 - b1 - b2;
        return new double[] {b0 * st[0][0] + b1 * st[1][0] + b2 * st[2][0], b0 * st[0][1] + b1 * st[1][1] + b2 * st[2][1]};
    }
}
