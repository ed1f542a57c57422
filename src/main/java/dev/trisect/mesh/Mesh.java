package dev.trisect.mesh;

import java.util.List;

/**
 * An indexed triangle mesh with positions, texture coordinates and a material per triangle.
 *
 * <p>Corners index positions and texture coordinates separately, as OBJ does, so a cube can share
 * its 8 positions while every face has its own UVs. Triangles are numbered from 0 in the order they
 * were added; that number is the "triangle index" of the UV output (see {@code docs/conventions.md}).
 *
 * <p>The arrays are handed out as they are, without copies, because the frame pipeline reads them
 * in its per-vertex loop: callers must not modify them.
 */
public final class Mesh {
    private final float[] positions;
    private final float[] uvs;
    private final int[] cornerPositions;
    private final int[] cornerUvs;
    private final int[] triangleMaterials;
    private final List<String> materialNames;

    Mesh(float[] positions, float[] uvs, int[] cornerPositions, int[] cornerUvs,
         int[] triangleMaterials, List<String> materialNames) {
        this.positions = positions;
        this.uvs = uvs;
        this.cornerPositions = cornerPositions;
        this.cornerUvs = cornerUvs;
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
