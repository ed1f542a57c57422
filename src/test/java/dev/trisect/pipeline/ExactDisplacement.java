package dev.trisect.pipeline;

import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.render.Framebuffer;
import dev.trisect.texture.Texture;

/**
 * Test oracle: the exact displacement of every pixel of a render, by the definition in the guide.
 * The pixel's texel coordinates (its UV output) are mapped back, in double precision, to the point of
 * the 3D triangle it says it shows that carries them; that point is projected, and its distance to
 * the pixel centre is the displacement, in pixels. Needs triangles whose texel coordinates are not
 * degenerate (every scene these tests use).
 */
final class ExactDisplacement {
    private ExactDisplacement() {
    }

    /** Worst displacement over the covered pixels and how many there were. */
    record Result(double worst, int worstX, int worstY, int pixels) {
    }

    static Result measure(Mesh mesh, Texture[] textures, Mat4 viewProjection, Framebuffer fb) {
        int w = fb.width();
        int h = fb.height();
        double[] uv = fb.uv();
        Viewport vp = new Viewport(w, h);
        double worst = 0;
        int wx = -1;
        int wy = -1;
        int pixels = 0;
        double[] clip = new double[4];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int i = y * w + x;
                int id = (int) uv[3 * i + 2];
                if (id == 0) {
                    continue;
                }
                double[] p = pointCarrying(mesh, textures, id - 1, uv[3 * i], uv[3 * i + 1]);
                viewProjection.transformPoint(p[0], p[1], p[2], clip, 0);
                double d = Math.hypot(vp.screenX(clip[0], clip[3]) - (x + 0.5), vp.screenY(clip[1], clip[3]) - (y + 0.5));
                pixels++;
                if (!(d <= worst)) {
                    worst = d;
                    wx = x;
                    wy = y;
                }
            }
        }
        return new Result(worst, wx, wy, pixels);
    }

    /** The world-space point of triangle {@code t} whose texel coordinates are (s, t). */
    private static double[] pointCarrying(Mesh m, Texture[] textures, int tri, double s, double t) {
        Texture tex = textures[m.triangleMaterials()[tri]];
        double[][] p = new double[3][3];
        double[][] c = new double[3][2];
        for (int k = 0; k < 3; k++) {
            int pi = m.cornerPositions()[3 * tri + k];
            for (int a = 0; a < 3; a++) {
                p[k][a] = m.positions()[3 * pi + a];
            }
            int ui = m.cornerUvs()[3 * tri + k];
            c[k][0] = ui < 0 ? 0 : m.uvs()[2 * ui] * (double) tex.width();
            c[k][1] = ui < 0 ? 0 : m.uvs()[2 * ui + 1] * (double) tex.height();
        }
        // (s, t) = c0 + b1 (c1 - c0) + b2 (c2 - c0), solved by Cramer's rule.
        double a11 = c[1][0] - c[0][0];
        double a12 = c[2][0] - c[0][0];
        double a21 = c[1][1] - c[0][1];
        double a22 = c[2][1] - c[0][1];
        double det = a11 * a22 - a12 * a21;
        if (det == 0) {
            throw new IllegalArgumentException("triangle " + tri + " has degenerate texel coordinates");
        }
        double rs = s - c[0][0];
        double rt = t - c[0][1];
        double b1 = (rs * a22 - a12 * rt) / det;
        double b2 = (a11 * rt - rs * a21) / det;
        double[] out = new double[3];
        for (int a = 0; a < 3; a++) {
            out[a] = p[0][a] + b1 * (p[1][a] - p[0][a]) + b2 * (p[2][a] - p[0][a]);
        }
        return out;
    }
}
