package dev.trisect.mesh;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The mesh an {@link ObjReader} is building: flat arrays of object-space positions (the file's units),
 * texel coordinates and normals as written, the corners and material of each triangle in file order, and the
 * material names in order of first use. It owns their growth, and with it the limit of
 * docs/reading-limits.md ("too much data" past the largest array the JVM allocates), the counts of
 * what is defined so far that negative indices count back from, and the texel-coordinate transforms
 * of the materials applied once the file has been read.
 */
final class ObjMeshArrays {
    /** Kinds of indexed element, the subscripts of {@link #count}. */
    static final int V = 0;
    static final int VT = 1;
    static final int VN = 2;
    /** Largest array the JVM reliably allocates. */
    private static final long MAX_ARRAY = Integer.MAX_VALUE - 8;

    /** The OBJ file's lines: a "too much data" error names the line being read. */
    private final LineScanner lines;

    private float[] positions = new float[3 * 256];
    private float[] uvs = new float[2 * 256];
    private float[] normals = new float[0];
    private final int[] counts = new int[3];
    private int[] cornerPositions = new int[3 * 256];
    private int[] cornerUvs = new int[3 * 256];
    private int[] cornerNormals = new int[3 * 256];
    private int[] triangleMaterials = new int[256];
    private int triangleCount;
    /** The {@code l} elements' segments: two 0-based position indices each, and the material of each (-1 for none). */
    private int[] segments = new int[0];
    private int[] segmentMaterials = new int[0];
    private int segmentCount;

    private final List<String> materialNames = new ArrayList<>();
    private final Map<String, Integer> materialIndex = new HashMap<>();
    private int currentMaterial = -1;

    ObjMeshArrays(LineScanner lines) {
        this.lines = lines;
    }

    /** How many elements of {@code kind} ({@link #V}, {@link #VT}, {@link #VN}) are defined so far. */
    int count(int kind) {
        return counts[kind];
    }

    int triangleCount() {
        return triangleCount;
    }

    /** The material names in order of first use; the list the mesh is built with. */
    List<String> materialNames() {
        return materialNames;
    }

    /**
     * Makes room for one more position ({@link #V}) or normal ({@link #VN}) before its numbers are
     * parsed, so that on a line with both problems "too much data" is reported first, as it always was.
     */
    void roomForTriple(int kind) {
        if (kind == V) {
            positions = room(positions, 3L * counts[V] + 3);
        } else {
            normals = room(normals, 3L * counts[VN] + 3);
        }
    }

    /**
     * Appends a position ({@link #V}: object space, the file's units) or a normal ({@link #VN}: object
     * space, as written); {@link #roomForTriple} came first.
     */
    void addTriple(int kind, float x, float y, float z) {
        float[] a = kind == V ? positions : normals;
        int at = 3 * counts[kind];
        a[at] = x;
        a[at + 1] = y;
        a[at + 2] = z;
        counts[kind]++;
    }

    /** As {@link #roomForTriple}, for a texel coordinate. */
    void roomForUv() {
        uvs = room(uvs, 2L * counts[VT] + 2);
    }

    /** Appends a texel coordinate as written; {@link #roomForUv} came first. */
    void addUv(float u, float v) {
        int at = 2 * counts[VT];
        uvs[at] = u;
        uvs[at + 1] = v;
        counts[VT]++;
    }

    boolean hasMaterial() {
        return currentMaterial >= 0;
    }

    /** As {@link MeshBuilder#material}, but with a hash lookup so many materials stay linear. */
    void useMaterial(String name) {
        currentMaterial = materialIndex.computeIfAbsent(name, n -> {
            materialNames.add(n);
            return materialNames.size() - 1;
        });
    }

    /**
     * Appends a triangle of the current material: 0-based position, UV and normal indices (UV and
     * normal -1 for none).
     */
    void triangle(int p0, int p1, int p2, int t0, int t1, int t2, int n0, int n1, int n2) {
        triangleMaterials = room(triangleMaterials, triangleCount + 1L);
        cornerPositions = room(cornerPositions, 3L * triangleCount + 3);
        cornerUvs = room(cornerUvs, 3L * triangleCount + 3);
        cornerNormals = room(cornerNormals, 3L * triangleCount + 3);
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
        triangleMaterials[triangleCount++] = currentMaterial;
    }

    /** Appends a segment of an {@code l} element, of the current material (or none): 0-based position indices. */
    void segment(int p0, int p1) {
        segmentMaterials = room(segmentMaterials, segmentCount + 1L);
        segments = room(segments, 2L * segmentCount + 2);
        segments[2 * segmentCount] = p0;
        segments[2 * segmentCount + 1] = p1;
        segmentMaterials[segmentCount++] = currentMaterial;
    }

    int segmentCount() {
        return segmentCount;
    }

    /**
     * The segments read, sharing the mesh's positions, each coloured by its material's {@code Kd}
     * ({@code colours.applyAsInt(name)}), white where it has none (as OpenGL's current colour starts).
     */
    Lines toLines(float[] meshPositions, java.util.function.ToIntFunction<String> colours) {
        int[] rgb = new int[segmentCount];
        for (int s = 0; s < segmentCount; s++) {
            int m = segmentMaterials[s];
            rgb[s] = m < 0 ? 0xFFFFFF : colours.applyAsInt(materialNames.get(m));
        }
        return segmentCount == 0 ? Lines.EMPTY : new Lines(meshPositions, Arrays.copyOf(segments, 2 * segmentCount), rgb);
    }

    /**
     * Gives the triangles of materials with a map_Kd {@code -s}/{@code -o} their own transformed copies
     * of the texel coordinates they use (a coordinate may be shared with other materials).
     */
    void applyUvTransforms(MtlLibraries libraries) {
        if (!libraries.hasUvTransforms()) {
            return;
        }
        float[][] byMaterial = new float[materialNames.size()][];
        for (int m = 0; m < byMaterial.length; m++) {
            byMaterial[m] = libraries.uvTransform(materialNames.get(m));
        }
        Map<Long, Integer> copies = new HashMap<>();
        for (int t = 0; t < triangleCount; t++) {
            int m = triangleMaterials[t];
            float[] x = byMaterial[m];
            if (x == null) {
                continue;
            }
            for (int c = 3 * t; c < 3 * t + 3; c++) {
                int source = cornerUvs[c];
                if (source < 0) {
                    continue;
                }
                cornerUvs[c] = copies.computeIfAbsent((long) source * byMaterial.length + m, key -> {
                    uvs = room(uvs, 2L * counts[VT] + 2);
                    int at = 2 * counts[VT];
                    uvs[at] = uvs[2 * source] * x[0] + x[2];
                    uvs[at + 1] = uvs[2 * source + 1] * x[1] + x[3];
                    return counts[VT]++;
                });
            }
        }
    }

    /** The mesh of what was read, in trimmed copies of the arrays. */
    Mesh toMesh() {
        return new Mesh(Arrays.copyOf(positions, 3 * counts[V]), Arrays.copyOf(uvs, 2 * counts[VT]),
                Arrays.copyOf(normals, 3 * counts[VN]), Arrays.copyOf(cornerPositions, 3 * triangleCount),
                Arrays.copyOf(cornerUvs, 3 * triangleCount), Arrays.copyOf(cornerNormals, 3 * triangleCount),
                Arrays.copyOf(triangleMaterials, triangleCount), materialNames);
    }

    private float[] room(float[] a, long needed) {
        return needed <= a.length ? a : Arrays.copyOf(a, newLength(a.length, needed));
    }

    private int[] room(int[] a, long needed) {
        return needed <= a.length ? a : Arrays.copyOf(a, newLength(a.length, needed));
    }

    private int newLength(int length, long needed) {
        if (needed > MAX_ARRAY) {
            throw lines.error("too much data: the mesh does not fit in memory");
        }
        return (int) Math.min(MAX_ARRAY, Math.max(needed, 2L * length));
    }
}
