package dev.trisect.light;

/**
 * OpenGL 1.x's fixed-function lighting equation for one vertex, without emission and specular, one
 * side (OpenGL 2.1 specification, section 2.14.1 "Lighting"; two-sided lighting off):
 *
 * <pre>
 * c = a_scene·a_m + Σ_i att_i · (a_li·a_m + max(N·L_i, 0) · d_li·d_m)      clamped to [0, 1] per channel
 * att_i = 1 / (kc + kl·d + kq·d²) for a point light at distance d, 1 for a directional light
 * </pre>
 *
 * where N is the vertex's unit normal and L_i the unit vector from the vertex towards light i (for a
 * directional light, its direction). Everything is in world space: the view transform is a rotation
 * and a translation, so dot products and distances are those of OpenGL's eye space. The normal is
 * normalised here, as {@code GL_NORMALIZE} does; a zero normal lights as N·L = 0.
 */
public final class LightingEquation {
    /** Doubles per material in the {@code material} arguments: ar, ag, ab, dr, dg, db. */
    public static final int MATERIAL_STRIDE = 6;

    private LightingEquation() {
    }

    /**
     * The lit colour of one vertex.
     *
     * @param lights   the frame's lights, world space
     * @param px       the vertex position, world space
     * @param nx       the vertex normal, world space (any length)
     * @param material materials, {@link #MATERIAL_STRIDE} doubles each
     * @param m        offset of this vertex's material in {@code material}
     * @param out      receives r, g, b in [0, 1]
     * @param o        offset in {@code out}
     */
    public static void colour(Lights lights, double px, double py, double pz, double nx, double ny, double nz,
                              double[] material, int m, float[] out, int o) {
        double ar = material[m];
        double ag = material[m + 1];
        double ab = material[m + 2];
        double dr = material[m + 3];
        double dg = material[m + 4];
        double db = material[m + 5];
        double nl = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (nl > 0) {
            nx /= nl;
            ny /= nl;
            nz /= nl;
        }
        double[] a = lights.ambientArray();
        double r = a[0] * ar;
        double g = a[1] * ag;
        double b = a[2] * ab;
        double[] dir = lights.directionalArray();
        for (int i = 0; i < dir.length; i += Lights.DIRECTIONAL_STRIDE) {
            double lambert = Math.max(nx * dir[i] + ny * dir[i + 1] + nz * dir[i + 2], 0);
            r += dir[i + 3] * ar + lambert * dir[i + 6] * dr;
            g += dir[i + 4] * ag + lambert * dir[i + 7] * dg;
            b += dir[i + 5] * ab + lambert * dir[i + 8] * db;
        }
        double[] pt = lights.pointArray();
        for (int i = 0; i < pt.length; i += Lights.POINT_STRIDE) {
            double lx = pt[i] - px;
            double ly = pt[i + 1] - py;
            double lz = pt[i + 2] - pz;
            double d = Math.sqrt(lx * lx + ly * ly + lz * lz);
            double att = 1 / (pt[i + 9] + pt[i + 10] * d + pt[i + 11] * d * d);
            double lambert = d > 0 ? Math.max((nx * lx + ny * ly + nz * lz) / d, 0) : 0;
            r += att * (pt[i + 3] * ar + lambert * pt[i + 6] * dr);
            g += att * (pt[i + 4] * ag + lambert * pt[i + 7] * dg);
            b += att * (pt[i + 5] * ab + lambert * pt[i + 8] * db);
        }
        out[o] = clamp(r);
        out[o + 1] = clamp(g);
        out[o + 2] = clamp(b);
    }

    private static float clamp(double v) {
        return (float) (v < 0 ? 0 : v > 1 ? 1 : v);
    }
}
