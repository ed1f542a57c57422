package dev.trisect.pipeline;

import dev.trisect.raster.ScreenTriangles;
import dev.trisect.tessellate.PieceSink;

/**
 * Where the geometry stage's pieces go: each piece the tessellator hands on is appended to a chunk's
 * screen triangles, with its corners' screen positions, {@code 1/w} and varyings (in the layout the
 * screen triangles were set to, the tessellator's), tagged
 * with the input triangle it came from, that triangle's material, its split level and whether it is
 * a per-pixel fallback, its flat values (the input triangle's), and its edges' links (which earlier piece of the chunk shares each). One per
 * thread; pointed at a chunk, then at each input triangle in turn.
 */
final class ScreenPieceSink implements PieceSink {
    private ScreenTriangles out;
    private int id;
    private int material;
    private double[] flat;
    private int flatAt;

    /** Appends the following pieces to {@code triangles}. */
    void target(ScreenTriangles triangles) {
        out = triangles;
    }

    /**
     * The following pieces come from input triangle {@code id} of material {@code material}, with the
     * layout's flat values at {@code flatValues[from..]} (none read when the layout has none).
     */
    void triangle(int triangleId, int materialIndex, double[] flatValues, int from) {
        id = triangleId;
        material = materialIndex;
        flat = flatValues;
        flatAt = from;
    }

    @Override
    public void piece(double[] v, int a, int b, int c, int level, boolean fallback, int[] links) {
        int index = out.count();
        out.add(v, a, b, c, id, material, fallback, level, ScreenTriangles.link(links[0], index),
                ScreenTriangles.link(links[1], index), ScreenTriangles.link(links[2], index), flat, flatAt);
    }
}
