package dev.trisect.mesh;

import java.util.List;

/**
 * An indexed triangle mesh with positions, texture coordinates, optional normals and a material per
 * triangle.
 *
 * <p>Corners index positions, texture coordinates and normals separately, as OBJ does, so a cube can
 * share its 8 positions while every face has its own UVs and normal. Triangles are numbered from 0 in
 * the order they were added; that number is the "triangle index" of the UV output (see
 * {@code docs/conventions.md}). A corner without a normal has its triangle's face normal
 * ({@link #cornerNormal}), as OpenGL references given an OBJ without {@code vn} do.
 *
 * <p>The arrays are handed out as they are, without copies, because the frame pipeline reads them
 * in its per-vertex loop: callers must not modify them.
 */
public final class Mesh {
    private final float[] positions;
    private final float[] uvs;
    private final int[] cornerPositions;
    private final int[] cornerUvs;
    private final float[] normals;
    private final int[] cornerNormals;
    private final int[] triangleMaterials;
    private final List<String> materialNames;

    Mesh(float[] positions, float[] uvs, float[] normals, int[] cornerPositions, int[] cornerUvs,
         int[] cornerNormals, int[] triangleMaterials, List<String> materialNames) {
        this.positions = positions;
        this.uvs = uvs;
        this.normals = normals;
        this.cornerPositions = cornerPositions;
        this.cornerUvs = cornerUvs;
        this.cornerNormals = cornerNormals;
        this.triangleMaterials = triangleMaterials;
        this.materialNames = List.copyOf(materialNames);
    }

    /**
     * Number of triangles.
     *
     * @return the triangle count
     */
    public int triangleCount() {
        return triangleMaterials.length;
    }

    /**
     * Number of positions.
     *
     * @return the position count
     */
    public int positionCount() {
        return positions.length / 3;
    }

    /**
     * Number of texture coordinates.
     *
     * @return the texture-coordinate count
     */
    public int uvCount() {
        return uvs.length / 2;
    }

    /**
     * Number of normals.
     *
     * @return the normal count; 0 when no corner has a normal of its own
     */
    public int normalCount() {
        return normals.length / 3;
    }

    /**
     * Positions in object space (world units), x, y, z per position: stride 3. Read-only.
     *
     * @return the positions, not a copy
     */
    public float[] positions() {
        return positions;
    }

    /**
     * Texture coordinates (u, v; (0, 0) is the texture's bottom-left), stride 2. Read-only.
     *
     * @return the texture coordinates, not a copy
     */
    public float[] uvs() {
        return uvs;
    }

    /**
     * Position index of each corner: triangle t has corners 3t, 3t+1, 3t+2. Read-only.
     *
     * @return three position indices per triangle, not a copy
     */
    public int[] cornerPositions() {
        return cornerPositions;
    }

    /**
     * Texture-coordinate index of each corner, or -1 where the corner has none (UV (0, 0)). Read-only.
     *
     * @return three texture-coordinate indices per triangle, not a copy
     */
    public int[] cornerUvs() {
        return cornerUvs;
    }

    /**
     * Normals in object space (x, y, z per normal: stride 3), as given: not necessarily of unit length
     * (an OBJ's {@code vn} is kept as written). Read-only.
     *
     * @return the normals, not a copy
     */
    public float[] normals() {
        return normals;
    }

    /**
     * Normal index of each corner, or -1 where the corner has none (it takes its triangle's face
     * normal, see {@link #cornerNormal}). Read-only.
     *
     * @return three normal indices per triangle, not a copy
     */
    public int[] cornerNormals() {
        return cornerNormals;
    }

    /**
     * The unit normal of a corner in object space: its own normal made unit length, or where it has
     * none its triangle's {@linkplain #faceNormal face normal}. (0, 0, 0) where there is no direction
     * (a zero or non-finite normal, a degenerate triangle). Allocation-free, for per-vertex loops.
     *
     * @param corner the corner, {@code 3 * triangle + k} for k in 0..2
     * @param out    receives x, y, z
     * @param offset where in {@code out}
     */
    public void cornerNormal(int corner, double[] out, int offset) {
        int n = cornerNormals[corner];
        if (n < 0) {
            faceNormal(corner / 3, out, offset);
        } else {
            unit(normals[3 * n], normals[3 * n + 1], normals[3 * n + 2], out, offset);
        }
    }

    /**
     * The unit face normal of a triangle in object space: {@code (p1 - p0) x (p2 - p0)} made unit
     * length, the side from which its corners run counter-clockwise (its front); (0, 0, 0) for a
     * degenerate triangle. Computed in double from the float positions. Allocation-free.
     *
     * @param triangle the triangle
     * @param out      receives x, y, z
     * @param offset   where in {@code out}
     */
    public void faceNormal(int triangle, double[] out, int offset) {
        int a = 3 * cornerPositions[3 * triangle];
        int b = 3 * cornerPositions[3 * triangle + 1];
        int c = 3 * cornerPositions[3 * triangle + 2];
        double ux = (double) positions[b] - positions[a];
        double uy = (double) positions[b + 1] - positions[a + 1];
        double uz = (double) positions[b + 2] - positions[a + 2];
        double vx = (double) positions[c] - positions[a];
        double vy = (double) positions[c + 1] - positions[a + 1];
        double vz = (double) positions[c + 2] - positions[a + 2];
        unit(uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx, out, offset);
    }

    /**
     * (x, y, z) divided by its length, or zeros without a direction. From float coordinates every
     * square stays within double's range (at most about 1e156, at least about 1e-180), so no rescaling.
     */
    private static void unit(double x, double y, double z, double[] out, int offset) {
        double length = Math.sqrt(x * x + y * y + z * z);
        boolean direction = length > 0 && length < Double.POSITIVE_INFINITY;
        out[offset] = direction ? x / length : 0;
        out[offset + 1] = direction ? y / length : 0;
        out[offset + 2] = direction ? z / length : 0;
    }

    /**
     * Material index of each triangle, into {@link #materialNames()}. Read-only.
     *
     * @return one material index per triangle, not a copy
     */
    public int[] triangleMaterials() {
        return triangleMaterials;
    }

    /**
     * Material names, indexed by material index; at least one.
     *
     * @return the names, unmodifiable
     */
    public List<String> materialNames() {
        return materialNames;
    }

    /**
     * Number of materials.
     *
     * @return the number of material names
     */
    public int materialCount() {
        return materialNames.size();
    }
}
