package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.texture.Texture;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Billboards and labels face the camera: over random camera poses, the 3D points their pixels show
 * (each pixel's ray at the depth the frame stored) lie in a plane within 0.1 degrees of the image
 * plane, and a billboard sized in world units is as large as that size at its depth.
 */
class BillboardTest {
    private static final int W = 200;
    private static final int H = 150;
    private static final int RED = 0xFFFF0000;

    /** A 4x4 texture, opaque red but for a transparent texel in one corner. */
    private static Texture marker() {
        int[] t = new int[16];
        java.util.Arrays.fill(t, RED);
        t[0] = 0;
        return new Texture("marker", 4, 4, t);
    }

    /**
     * The largest angle, degrees, between the image plane and the planes through triples of the pixels
     * of colour {@code rgb}, their points unprojected at the depth stored: eye space, per gluPerspective.
     */
    private static double tilt(Framebuffer f, Camera camera, int rgb) {
        int[] c = f.colour();
        float[] q = f.depth();
        double tan = Math.tan(Math.toRadians(camera.fovY()) / 2);
        double[][] p = new double[3][];
        int minX = W;
        int maxX = -1;
        int minY = H;
        int maxY = -1;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                if ((c[y * W + x] & 0xFFFFFF) == (rgb & 0xFFFFFF)) {
                    minX = Math.min(minX, x);
                    maxX = Math.max(maxX, x);
                    minY = Math.min(minY, y);
                    maxY = Math.max(maxY, y);
                }
            }
        }
        assertTrue(maxX - minX >= 2 && maxY - minY >= 2, "the sprite covers a few pixels: " + minX + ".." + maxX);
        int[][] picks = {{minX, minY}, {maxX, minY}, {minX, maxY}, {maxX, maxY}};
        double worst = 0;
        int n = 0;
        double[][] all = new double[4][];
        for (int[] xy : picks) {
            int x = xy[0];
            int y = xy[1];
            // The nearest pixel of the sprite's colour to that corner of its bounds.
            int best = -1;
            for (int yy = minY; yy <= maxY && best < 0; yy++) {
                for (int xx = minX; xx <= maxX; xx++) {
                    int px = x == minX ? xx : maxX - (xx - minX);
                    int py = y == minY ? yy : maxY - (yy - minY);
                    if ((c[py * W + px] & 0xFFFFFF) == (rgb & 0xFFFFFF)) {
                        best = py * W + px;
                        break;
                    }
                }
            }
            double w = 1 / (double) q[best];
            assertTrue(Double.isFinite(w) && w > 0, "depth " + q[best] + " at " + best % W + ", " + best / W);
            double nx = 2 * (best % W + 0.5) / W - 1;
            double ny = 1 - 2 * (best / W + 0.5) / H;
            all[n++] = new double[] {nx * w * tan * W / H, ny * w * tan, -w};
        }
        for (int a = 0; a < 4; a++) {
            for (int b = a + 1; b < 4; b++) {
                for (int d = b + 1; d < 4; d++) {
                    Vec3 pa = new Vec3(all[a][0], all[a][1], all[a][2]);
                    Vec3 u = new Vec3(all[b][0], all[b][1], all[b][2]).sub(pa);
                    Vec3 v = new Vec3(all[d][0], all[d][1], all[d][2]).sub(pa);
                    Vec3 normal = u.cross(v);
                    if (normal.length() <= 1e-9 * u.length() * v.length()) {
                        continue; // three points on a line: no plane
                    }
                    double cos = Math.abs(normal.z()) / normal.length();
                    worst = Math.max(worst, Math.toDegrees(Math.acos(Math.min(1, cos))));
                }
            }
        }
        return worst;
    }

    @Test
    void billboardsAndGlyphsFaceTheCameraFromAHundredPoses() {
        Random random = new Random(28);
        Scene scene = new Scene();
        // Something behind, so that depth is stored around the sprites too.
        scene.add(new SceneObject(Primitives.sphere(0.3, 12, 8), Material.colour(0x202020)));
        SceneObject sprites = SceneObject.billboards(List.of(Billboard.world(marker(), new Vec3(0.8, 0.4, -0.3), 0.6, 0.4)));
        SceneObject label = SceneObject.labels(List.of(Label.of("WWW", new Vec3(-0.7, -0.2, 0.4)).withColour(0x00FF00)));
        scene.add(sprites);
        scene.add(label);
        double worst = 0;
        try (SceneRenderer r = new SceneRenderer(2)) {
            for (int pose = 0; pose < 100; pose++) {
                Vec3 dir = new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalize();
                Vec3 eye = dir.scale(3 + 3 * random.nextDouble());
                Vec3 up = new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
                if (up.cross(eye).length() < 0.1 * up.length() * eye.length()) {
                    up = Vec3.UP;
                }
                Camera camera = Camera.looking(eye, new Vec3(0, 0.1, 0), up.normalize());
                Framebuffer f = new Framebuffer(W, H);
                FrameStats stats = r.render(scene, camera, RenderSettings.defaults(), f);
                assertEquals(1, stats.billboards());
                assertEquals(3, stats.glyphs());
                worst = Math.max(worst, tilt(f, camera, RED));
                worst = Math.max(worst, tilt(f, camera, 0xFF00FF00));
            }
        }
        assertTrue(worst <= 0.1, "a sprite is tilted " + worst + " degrees off the image plane");
    }

    @Test
    void aWorldSizedBillboardIsThatSizeAtItsDepthAndAPixelSizedOneIsNot() {
        Scene scene = new Scene();
        Billboard world = Billboard.world(marker(), new Vec3(0, 0, 0), 1, 0.5);
        scene.add(SceneObject.billboards(List.of(world)));
        for (double distance : new double[] {2, 4}) {
            Camera camera = Camera.looking(new Vec3(0, 0, distance), Vec3.ZERO);
            Framebuffer f = new Framebuffer(W, H);
            try (SceneRenderer r = new SceneRenderer(1)) {
                r.render(scene, camera, RenderSettings.defaults(), f);
            }
            // Pixels per unit at the billboard's depth: half the height over tan(fovY / 2) over the depth.
            double perUnit = H / 2.0 / Math.tan(Math.toRadians(camera.fovY()) / 2) / distance;
            int[] bounds = bounds(f.colour());
            assertEquals(perUnit, bounds[1] - bounds[0] + 1, 1.0, "width at distance " + distance);
            assertEquals(0.5 * perUnit, bounds[3] - bounds[2] + 1, 1.0, "height at distance " + distance);
        }
        scene.clear();
        scene.add(SceneObject.billboards(List.of(Billboard.pixels(marker(), Vec3.ZERO, 40, 20))));
        Framebuffer f = new Framebuffer(W, H);
        try (SceneRenderer r = new SceneRenderer(1)) {
            r.render(scene, Camera.looking(new Vec3(0, 0, 7), Vec3.ZERO), RenderSettings.defaults(), f);
        }
        int[] b = bounds(f.colour());
        assertEquals(40, b[1] - b[0] + 1);
        assertEquals(20, b[3] - b[2] + 1);
        // The transparent texel (top left, 10 x 5 pixels) is not drawn: alpha-tested.
        assertEquals(0, f.colour()[b[2] * W + b[0]] & 0xFFFFFF);
        assertEquals(RED, f.colour()[(b[2] + 5) * W + b[0] + 10]);
    }

    /** Left, right, top, bottom of the red pixels. */
    private static int[] bounds(int[] c) {
        int[] b = {W, -1, H, -1};
        for (int i = 0; i < c.length; i++) {
            if (c[i] == RED) {
                b[0] = Math.min(b[0], i % W);
                b[1] = Math.max(b[1], i % W);
                b[2] = Math.min(b[2], i / W);
                b[3] = Math.max(b[3], i / W);
            }
        }
        return b;
    }
}
