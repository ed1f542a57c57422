package dev.trisect.mesh;

import dev.trisect.math.Vec3;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;

/**
 * Builds a {@link Mesh} by appending positions, texture coordinates, normals and triangles.
 *
 * <p>Triangles are front-facing when their corners run counter-clockwise as seen from the side they
 * face (OpenGL's default), and get the current material (see {@link #material(String)}). Normals are
 * optional: a corner given none (-1) takes its triangle's face normal ({@link Mesh#cornerNormal}).
 */
public final class MeshBuilder {
    private float[] positions = new float[3 * 64];
    private int positionCount;
    private float[] uvs = new float[2 * 64];
    private int uvCount;
    private float[] normals = new float[0];
    private int normalCount;
    private int[] cornerPositions = new int[3 * 64];
    private int[] cornerUvs = new int[3 * 64];
    private int[] cornerNormals = new int[3 * 64];
    private int[] materials = new int[64];
    private int triangleCount;
    private final List<String> materialNames = new ArrayList<>();
    private int currentMaterial = -1;

    /**
     * Number of positions added so far.
     *
     * @return positions added so far
     */
    public int positionCount() {
        return positionCount;
    }

    /**
     * Number of texture coordinates added so far.
     *
     * @return texture coordinates added so far
     */
    public int uvCount() {
        return uvCount;
    }

    /**
     * Number of normals added so far.
     *
     * @return normals added so far
     */
    public int normalCount() {
        return normalCount;
    }

    /**
     * Number of triangles added so far.
     *
     * @return triangles added so far
     */
    public int triangleCount() {
        return triangleCount;
    }

    /**
     * Makes {@code name} the material of the triangles that follow, adding it if it is new.
     *
     * @param name the material's name (a new name adds a material)
     * @return the material's index
     * @throws NullPointerException when {@code name} is null
     */
    public int material(String name) {
        // Checked here: a null name would otherwise surface only in build(), far from the call.
        Objects.requireNonNull(name, "material name is null");
        int index = materialNames.indexOf(name);
        if (index < 0) {
            index = materialNames.size();
            materialNames.add(name);
        }
        currentMaterial = index;
        return index;
    }

    /**
     * Adds a position in object space and returns its index.
     *
     * @param x object space
     * @param y object space
     * @param z object space
     * @return the new position's index
     * @throws IllegalArgumentException when a coordinate is NaN, infinite or beyond the float range (about
     *                                  3.4e38 in magnitude), as {@code Transform} and {@code Camera} refuse
     *                                  such values: the mesh keeps floats, and a triangle with such a
     *                                  corner could not be drawn
     */
    public int position(double x, double y, double z) {
        if (!(isFloat(x) && isFloat(y) && isFloat(z))) {
            throw notFloat("position", x, y, z);
        }
        if (3 * positionCount + 3 > positions.length) {
            positions = Arrays.copyOf(positions, positions.length * 2);
        }
        positions[3 * positionCount] = (float) x;
        positions[3 * positionCount + 1] = (float) y;
        positions[3 * positionCount + 2] = (float) z;
        return positionCount++;
    }

    /**
     * Adds a position in object space and returns its index.
     *
     * @param p the position, object space
     * @return the new position's index
     */
    public int position(Vec3 p) {
        return position(p.x(), p.y(), p.z());
    }

    /**
     * Adds a texture coordinate and returns its index.
     *
     * @param u texture coordinate, (0, 0) the bottom-left
     * @param v texture coordinate
     * @return the new texture coordinate's index
     * @throws IllegalArgumentException when a coordinate is NaN, infinite or beyond the float range
     */
    public int uv(double u, double v) {
        if (!(isFloat(u) && isFloat(v))) {
            throw notFloat("texture coordinate", u, v);
        }
        if (2 * uvCount + 2 > uvs.length) {
            uvs = Arrays.copyOf(uvs, uvs.length * 2);
        }
        uvs[2 * uvCount] = (float) u;
        uvs[2 * uvCount + 1] = (float) v;
        return uvCount++;
    }

    /**
     * Adds a normal in object space and returns its index. Only its direction matters: the mesh keeps
     * it as given, and lighting makes it unit length.
     *
     * @param x object space
     * @param y object space
     * @param z object space
     * @return the new normal's index
     * @throws IllegalArgumentException when a component is not finite or all three are zero (no
     *                                  direction)
     */
    public int normal(double x, double y, double z) {
        float fx = (float) x;
        float fy = (float) y;
        float fz = (float) z;
        if (!Float.isFinite(fx) || !Float.isFinite(fy) || !Float.isFinite(fz) || (fx == 0 && fy == 0 && fz == 0)) {
            throw new IllegalArgumentException("normal (" + x + ", " + y + ", " + z
                    + ") has no direction: it must be finite and not zero (as a float)");
        }
        if (3 * normalCount + 3 > normals.length) {
            normals = Arrays.copyOf(normals, Math.max(3 * 64, normals.length * 2));
        }
        normals[3 * normalCount] = fx;
        normals[3 * normalCount + 1] = fy;
        normals[3 * normalCount + 2] = fz;
        return normalCount++;
    }

    /**
     * Adds a normal in object space and returns its index; see {@link #normal(double, double, double)}.
     *
     * @param n the normal, object space
     * @return the new normal's index
     */
    public int normal(Vec3 n) {
        return normal(n.x(), n.y(), n.z());
    }

    /**
     * Adds a triangle from position indices and texture-coordinate indices (-1 for none), without
     * normals (its corners take its face normal). Indices must already exist; this is checked.
     *
     * @param p0 first corner's position index
     * @param p1 second corner's position index
     * @param p2 third corner's position index (counter-clockwise from the front)
     * @param t0 first corner's texture-coordinate index, or -1
     * @param t1 second corner's texture-coordinate index, or -1
     * @param t2 third corner's texture-coordinate index, or -1
     * @return the new triangle's index
     */
    public int triangle(int p0, int p1, int p2, int t0, int t1, int t2) {
        return triangle(p0, p1, p2, t0, t1, t2, -1, -1, -1);
    }

    /**
     * Adds a triangle from position, texture-coordinate (-1 for none) and normal indices (-1 for
     * none: that corner takes the face normal). Indices must already exist; this is checked.
     *
     * @param p0 first corner's position index
     * @param p1 second corner's position index
     * @param p2 third corner's position index (counter-clockwise from the front)
     * @param t0 first corner's texture-coordinate index, or -1
     * @param t1 second corner's texture-coordinate index, or -1
     * @param t2 third corner's texture-coordinate index, or -1
     * @param n0 first corner's normal index, or -1
     * @param n1 second corner's normal index, or -1
     * @param n2 third corner's normal index, or -1
     * @return the new triangle's index
     */
    public int triangle(int p0, int p1, int p2, int t0, int t1, int t2, int n0, int n1, int n2) {
        checkPosition(p0);
        checkPosition(p1);
        checkPosition(p2);
        checkOptional(t0, uvCount, "uv");
        checkOptional(t1, uvCount, "uv");
        checkOptional(t2, uvCount, "uv");
        checkOptional(n0, normalCount, "normal");
        checkOptional(n1, normalCount, "normal");
        checkOptional(n2, normalCount, "normal");
        if (currentMaterial < 0) {
            material("default");
        }
        if (triangleCount == materials.length) {
            int n = materials.length * 2;
            materials = Arrays.copyOf(materials, n);
            cornerPositions = Arrays.copyOf(cornerPositions, 3 * n);
            cornerUvs = Arrays.copyOf(cornerUvs, 3 * n);
            cornerNormals = Arrays.copyOf(cornerNormals, 3 * n);
        }
        int c = 3 * triangleCount;
        cornerPositions[c] = p0;
        cornerPositions[c + 1] = p1;
        cornerPositions[c + 2] = p2;
        cornerUvs[c] = t0;
        cornerUvs[c + 1] = t1;
        cornerUvs[c + 2] = t2;
        cornerNormals[c] = n0;
        cornerNormals[c + 1] = n1;
        cornerNormals[c + 2] = n2;
        materials[triangleCount] = currentMaterial;
        return triangleCount++;
    }

    /**
     * Adds a quad as two triangles (p0, p1, p2) and (p0, p2, p3); the corners run counter-clockwise
     * as seen from the front.
     *
     * @param p0 first corner, object space
     * @param p1 second corner
     * @param p2 third corner
     * @param p3 fourth corner
     * @param u0 u at {@code p0}
     * @param v0 v at {@code p0}
     * @param u1 u at {@code p1}
     * @param v1 v at {@code p1}
     * @param u2 u at {@code p2}
     * @param v2 v at {@code p2}
     * @param u3 u at {@code p3}
     * @param v3 v at {@code p3}
     */
    public void quad(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3,
                     double u0, double v0, double u1, double v1,
                     double u2, double v2, double u3, double v3) {
        int a = position(p0);
        int b = position(p1);
        int c = position(p2);
        int d = position(p3);
        int ta = uv(u0, v0);
        int tb = uv(u1, v1);
        int tc = uv(u2, v2);
        int td = uv(u3, v3);
        triangle(a, b, c, ta, tb, tc);
        triangle(a, c, d, ta, tc, td);
    }

    /** Whether {@code d} is kept as a finite float: not NaN, not infinite, not beyond the float range. */
    static boolean isFloat(double d) {
        return Float.isFinite((float) d);
    }

    /** The refusal of values that are not all finite floats, naming them. */
    static IllegalArgumentException notFloat(String what, double... values) {
        StringBuilder named = new StringBuilder();
        for (double v : values) {
            named.append(named.length() == 0 ? "" : ", ").append(v);
        }
        return new IllegalArgumentException(what + " (" + named + ") is not a finite float: each coordinate must be a "
                + "number of at most " + Float.MAX_VALUE + " in magnitude");
    }

    private void checkPosition(int p) {
        if (p < 0 || p >= positionCount) {
            throw new IndexOutOfBoundsException("position index " + p + " not in 0.." + (positionCount - 1));
        }
    }

    private static void checkOptional(int i, int count, String what) {
        if (i < -1 || i >= count) {
            throw new IndexOutOfBoundsException(what + " index " + i + " not in -1.." + (count - 1));
        }
    }

    /**
     * The mesh built so far (arrays trimmed to size). The builder may be reused afterwards.
     *
     * @return the mesh, immutable
     */
    public Mesh build() {
        List<String> names = materialNames.isEmpty() ? List.of("default") : materialNames;
        return new Mesh(
                Arrays.copyOf(positions, 3 * positionCount),
                Arrays.copyOf(uvs, 2 * uvCount),
                Arrays.copyOf(normals, 3 * normalCount),
                Arrays.copyOf(cornerPositions, 3 * triangleCount),
                Arrays.copyOf(cornerUvs, 3 * triangleCount),
                Arrays.copyOf(cornerNormals, 3 * triangleCount),
                Arrays.copyOf(materials, triangleCount),
                names);
    }
}
