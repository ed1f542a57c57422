package dev.trisect.pipeline;

import dev.trisect.light.LightingEquation;
import dev.trisect.light.Lights;
import dev.trisect.light.Surface;
import dev.trisect.math.Mat4;
import dev.trisect.mesh.Mesh;
import dev.trisect.raster.PixelState;
import dev.trisect.render.Shading;
import java.util.Arrays;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.Map;

/**
 * The per-vertex stage of lighting: the lit colour r, g, b of every vertex of a frame's lit draws,
 * by {@link LightingEquation}, with the draw's world-space positions and its normals carried by the
 * normal matrix ({@link Mat4#normalMatrix()}). A vertex is a distinct (position, normal, material) of
 * a mesh — a corner without a normal of its own has its triangle's face normal, so it is a vertex of
 * that triangle alone — found once per mesh and kept while the mesh is drawn, so a frame lights each
 * shared vertex once, on all threads. {@link #index} gives a corner's colour: its own vertex's for
 * {@link Shading#SMOOTH}, its triangle's last corner's for {@link Shading#FLAT} (OpenGL's provoking
 * vertex). Not thread-safe: one frame at a time.
 */
final class VertexColours {
    /** Lit vertices per task. */
    private static final int BLOCK = 4096;

    /**
     * One mesh's vertices: distinct (position, normal, material) of its corners; per corner its
     * vertex, per vertex its first corner, per triangle its last corner's vertex (the provoking one).
     */
    private record Vertices(int[] ofCorner, int[] corner, int[] provoking) {
        int count() {
            return corner.length;
        }
    }

    private Map<Mesh, Vertices> tables = new IdentityHashMap<>();
    private Vertices[] drawTables = new Vertices[4];
    /** Per draw and one past the last: its first vertex in {@link #colours}. */
    private int[] base = new int[5];
    private float[] colours = new float[0];
    /**
     * Per vertex its colour as a flat value ({@link PixelState#flatColour}), beside {@link #colours}:
     * made only for frames without a smooth material ({@link #flatValues}).
     */
    private double[] flatColours = new double[0];
    /** Whether {@link #flatColours} holds the values of {@link #colours}. */
    private boolean flatValues;
    private double[] factors = new double[0];
    private boolean lit;
    /** Unlit frames in a row since the last lit one. */
    private int unlitFrames;
    /** What the colours were computed for ({@link #unchanged}): lights, per draw mesh and world, materials. */
    private Lights lastLights;
    private Mesh[] lastMeshes = new Mesh[0];
    private Mat4[] lastWorlds = new Mat4[0];
    private int lastMaterials = -1;
    private double[] lastFactors = new double[0];
    private boolean[] lastLit = new boolean[0];

    /**
     * Lights the vertices of every draw with a lit material; does nothing (and {@link #lit()} is
     * false) when no draw has one. The meshes' vertex tables are kept over up to
     * {@link Retention#FRAMES} unlit frames in a row, as buffers are, so that a view drawing lit and
     * unlit frames in turn does not find each mesh's vertices anew each time.
     */
    void compute(Draws draws, WorkerPool pool) {
        lit = draws.anyLit();
        if (!lit) {
            if (++unlitFrames >= Retention.FRAMES && !tables.isEmpty()) {
                tables = new IdentityHashMap<>();
                lastMeshes = new Mesh[0];
                lastWorlds = new Mat4[0];
            }
            return;
        }
        unlitFrames = 0;
        int n = draws.size();
        if (drawTables.length < n) {
            drawTables = new Vertices[n];
            base = new int[n + 1];
        }
        Map<Mesh, Vertices> kept = new IdentityHashMap<>();
        for (int d = 0; d < n; d++) {
            Mesh mesh = draws.mesh(d);
            Vertices v = kept.get(mesh);
            if (v == null) {
                v = tables.get(mesh);
                if (v == null) {
                    v = vertices(mesh);
                }
                kept.put(mesh, v);
            }
            drawTables[d] = v;
            base[d + 1] = base[d] + v.count();
        }
        tables = kept;
        int total = base[n];
        if (colours.length < 3 * total) {
            colours = new float[3 * total];
            flatColours = new double[total];
        }
        Surface[] surfaces = draws.surfaces();
        int materials = draws.firstMaterial(n);
        if (factors.length < LightingEquation.MATERIAL_STRIDE * materials) {
            factors = new double[LightingEquation.MATERIAL_STRIDE * materials];
        }
        for (int m = 0; m < materials; m++) {
            surfaces[m].factors(factors, LightingEquation.MATERIAL_STRIDE * m);
        }
        // The packed colours only for a frame without a smooth material, the one layout that reads them.
        boolean flat = !draws.anySmooth();
        if (unchanged(draws, materials) && (flatValues || !flat)) {
            return;
        }
        flatValues = flat;
        Mat4[] normalMatrices = new Mat4[n];
        for (int d = 0; d < n; d++) {
            try {
                normalMatrices[d] = draws.world(d).normalMatrix();
            } catch (IllegalArgumentException e) {
                normalMatrices[d] = null; // a flattened object: its normals have no direction
            }
        }
        Lights lights = draws.lights();
        int blocks = (total + BLOCK - 1) / BLOCK;
        double[][] scratch = new double[pool.threads()][6];
        pool.run(blocks, (thread, b) -> light(draws, lights, normalMatrices, scratch[thread], b * BLOCK,
                Math.min(total, (b + 1) * BLOCK), flat));
    }

    /**
     * Whether the colours of the last lit frame stand for this one: the same lights, and per draw the
     * same mesh, world matrix and materials (their factors and whether they are lit) — a still scene
     * under still lights, as a paused view or a benchmark draws it. Otherwise remembers this frame's.
     */
    private boolean unchanged(Draws draws, int materials) {
        int n = draws.size();
        int stride = LightingEquation.MATERIAL_STRIDE;
        boolean same = lastMaterials == materials && lastMeshes.length == n && draws.lights().equals(lastLights)
                && Arrays.equals(factors, 0, stride * materials, lastFactors, 0, stride * materials);
        for (int d = 0; same && d < n; d++) {
            same = lastMeshes[d] == draws.mesh(d) && lastWorlds[d].equals(draws.world(d));
        }
        for (int m = 0; same && m < materials; m++) {
            same = lastLit[m] == draws.surfaces()[m].lit();
        }
        if (same) {
            return true;
        }
        lastLights = draws.lights();
        lastMeshes = new Mesh[n];
        lastWorlds = new Mat4[n];
        for (int d = 0; d < n; d++) {
            lastMeshes[d] = draws.mesh(d);
            lastWorlds[d] = draws.world(d);
        }
        lastMaterials = materials;
        lastFactors = Arrays.copyOf(factors, stride * materials);
        lastLit = new boolean[materials];
        for (int m = 0; m < materials; m++) {
            lastLit[m] = draws.surfaces()[m].lit();
        }
        return false;
    }

    /** Lights frame vertices from..to-1, and with {@code flat} packs their colours as flat values too. */
    private void light(Draws draws, Lights lights, Mat4[] normalMatrices, double[] p, int from, int to,
                       boolean flat) {
        int d = Math.max(0, Arrays.binarySearch(base, 0, draws.size() + 1, from));
        while (base[d + 1] <= from) {
            d++;
        }
        for (int v = from; v < to; v++) {
            while (base[d + 1] <= v) {
                d++;
            }
            Mesh mesh = draws.mesh(d);
            int corner = drawTables[d].corner()[v - base[d]];
            int material = draws.firstMaterial(d) + mesh.triangleMaterials()[corner / 3];
            if (!draws.surfaces()[material].lit()) {
                continue;
            }
            float[] positions = mesh.positions();
            int pi = 3 * mesh.cornerPositions()[corner];
            draws.world(d).transformPoint(positions[pi], positions[pi + 1], positions[pi + 2], p, 0);
            double w = p[3];
            mesh.cornerNormal(corner, p, 3);
            Mat4 nm = normalMatrices[d];
            if (nm != null) {
                nm.transformDirection(p[3], p[4], p[5], p, 3);
            } else {
                p[3] = p[4] = p[5] = 0;
            }
            LightingEquation.colour(lights, p[0] / w, p[1] / w, p[2] / w, p[3], p[4], p[5], factors,
                    LightingEquation.MATERIAL_STRIDE * material, colours, 3 * v);
            if (flat) {
                flatColours[v] = PixelState.flatColour(colours[3 * v], colours[3 * v + 1], colours[3 * v + 2]);
            }
        }
    }

    /** Whether the last {@link #compute} lit anything. */
    boolean lit() {
        return lit;
    }

    /** The colours, r, g, b per vertex, 0..1; read-only. */
    float[] colours() {
        return colours;
    }

    /**
     * Where in {@link #colours()} the colour of draw {@code d}'s corner {@code corner} (3 * triangle +
     * k) starts: its own vertex's, or with {@code flat} its triangle's last corner's.
     */
    int index(int d, int corner, boolean flat) {
        int c = flat ? corner - corner % 3 + 2 : corner;
        return 3 * (base[d] + drawTables[d].ofCorner()[c]);
    }

    /**
     * The colours of every vertex as flat values ({@link PixelState#flatColour}), draw {@code d}'s
     * vertex v's at {@code base(d) + v}; read-only.
     */
    double[] flatColours() {
        return flatColours;
    }

    /** Where draw {@code d}'s vertices start in {@link #flatColours()}. */
    int base(int d) {
        return base[d];
    }

    /**
     * Per triangle of draw {@code d}'s mesh, the vertex of its last corner (OpenGL's provoking vertex,
     * {@link Shading#FLAT}), counted from {@link #base(int)}; read-only.
     */
    int[] provoking(int d) {
        return drawTables[d].provoking();
    }

    /** The distinct (position, normal, material) of a mesh's corners, in order of first use. */
    private static Vertices vertices(Mesh mesh) {
        int corners = 3 * mesh.triangleCount();
        int[] ofCorner = new int[corners];
        int[] first = new int[corners];
        int[] cp = mesh.cornerPositions();
        int[] cn = mesh.cornerNormals();
        int[] tm = mesh.triangleMaterials();
        Map<Key, Integer> seen = new HashMap<>();
        int count = 0;
        for (int c = 0; c < corners; c++) {
            // A corner without a normal takes its triangle's face normal: a vertex of that triangle alone.
            int normal = cn[c] >= 0 ? cn[c] : -1 - c / 3;
            Key key = new Key(cp[c], normal, tm[c / 3]);
            Integer v = seen.putIfAbsent(key, count);
            if (v == null) {
                first[count] = c;
                ofCorner[c] = count++;
            } else {
                ofCorner[c] = v;
            }
        }
        int[] provoking = new int[corners / 3];
        for (int t = 0; t < provoking.length; t++) {
            provoking[t] = ofCorner[3 * t + 2];
        }
        return new Vertices(ofCorner, Arrays.copyOf(first, count), provoking);
    }

    private record Key(int position, int normal, int material) {
    }
}
