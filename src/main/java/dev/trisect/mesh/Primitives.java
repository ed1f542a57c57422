package dev.trisect.mesh;

import dev.trisect.math.Vec3;

/**
 * Built-in shapes, front faces outward (counter-clockwise seen from outside), with texture
 * coordinates and outward unit normals: one per face on flat faces (a box's sides, a plane), one per
 * position on curved surfaces (a sphere's, smooth).
 *
 * <p>Two forms: {@link #box(double, double, double)}, {@link #plane(double, double, int, int)} and
 * {@link #sphere(double, int, int)} return a finished {@link Mesh} centred on the origin of its object
 * space, ready for a {@code dev.trisect.scene.SceneObject}; the forms taking a {@link MeshBuilder}
 * append to it at a given place (to build one mesh of several shapes).
 */
public final class Primitives {
    private Primitives() {
    }

    /**
     * A box centred on the origin, each face a quad with UVs (0, 0) to (1, 1), upright on the side faces.
     *
     * @param sizeX edge length along x, object units, &gt; 0
     * @param sizeY edge length along y, object units, &gt; 0
     * @param sizeZ edge length along z, object units, &gt; 0
     * @return a mesh of 12 triangles, one material
     */
    public static Mesh box(double sizeX, double sizeY, double sizeZ) {
        checkSize(sizeX, sizeY, sizeZ);
        MeshBuilder b = new MeshBuilder();
        box(b, Vec3.ZERO, new Vec3(sizeX, sizeY, sizeZ));
        return b.build();
    }

    /**
     * A horizontal rectangle on the plane y = 0 facing +y, centred on the origin, cut into
     * {@code cellsX x cellsZ} quads; the texture repeats once per cell (u along +x, v along -z).
     *
     * @param width  extent along x, object units, &gt; 0
     * @param depth  extent along z, object units, &gt; 0
     * @param cellsX quads along x, &gt;= 1
     * @param cellsZ quads along z, &gt;= 1
     * @return a mesh of {@code 2 * cellsX * cellsZ} triangles, one material
     */
    public static Mesh plane(double width, double depth, int cellsX, int cellsZ) {
        checkSize(width, 1, depth);
        MeshBuilder b = new MeshBuilder();
        grid(b, new Vec3(-width / 2, 0, depth / 2), new Vec3(width, 0, 0), new Vec3(0, 0, -depth), cellsX, cellsZ,
                0, 0, cellsX, cellsZ);
        return b.build();
    }

    /**
     * A UV sphere centred on the origin: u runs once around, v from 0 at the bottom pole to 1 at the top.
     *
     * @param radius radius, object units, &gt; 0
     * @param slices divisions around, &gt;= 3
     * @param stacks divisions from pole to pole, &gt;= 2
     * @return a mesh of {@code 2 * slices * (stacks - 1)} triangles, one material
     */
    public static Mesh sphere(double radius, int slices, int stacks) {
        checkSize(radius, 1, 1);
        MeshBuilder b = new MeshBuilder();
        sphere(b, Vec3.ZERO, radius, slices, stacks);
        return b.build();
    }

    private static void checkSize(double x, double y, double z) {
        if (!(x > 0 && y > 0 && z > 0) || !Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z)) {
            throw new IllegalArgumentException("shape sizes must be positive finite numbers, got " + x + ", " + y
                    + ", " + z);
        }
    }

    /**
     * A rectangle split into {@code cellsU x cellsV} quads (two triangles each), facing the side that
     * {@code right x up} points to. Corner {@code origin} gets UV (u0, v0); moving along {@code right}
     * increases u, along {@code up} increases v, so the texture appears upright to a viewer in front.
     *
     * @param b        the builder the quads are added to
     * @param origin   bottom-left corner, world space
     * @param right    full edge along which u grows, world units
     * @param up       full edge along which v grows, world units
     * @param cellsU   quads along {@code right}, &gt;= 1
     * @param cellsV   quads along {@code up}, &gt;= 1
     * @param u0       u at {@code origin}
     * @param v0       v at {@code origin}
     * @param uSpan    u change across the whole {@code right} edge (repeat count when u0 = 0)
     * @param vSpan    v change across the whole {@code up} edge
     */
    public static void grid(MeshBuilder b, Vec3 origin, Vec3 right, Vec3 up, int cellsU, int cellsV,
                            double u0, double v0, double uSpan, double vSpan) {
        if (cellsU < 1 || cellsV < 1) {
            throw new IllegalArgumentException("grid needs at least one cell each way");
        }
        int firstPos = b.positionCount();
        int firstUv = b.uvCount();
        int normal = b.normal(right.cross(up).normalize());
        for (int j = 0; j <= cellsV; j++) {
            for (int i = 0; i <= cellsU; i++) {
                double s = (double) i / cellsU;
                double t = (double) j / cellsV;
                b.position(origin.add(right.scale(s)).add(up.scale(t)));
                b.uv(u0 + uSpan * s, v0 + vSpan * t);
            }
        }
        int row = cellsU + 1;
        for (int j = 0; j < cellsV; j++) {
            for (int i = 0; i < cellsU; i++) {
                int a = j * row + i;
                int c = a + 1;
                int d = a + 1 + row;
                int e = a + row;
                b.triangle(firstPos + a, firstPos + c, firstPos + d, firstUv + a, firstUv + c, firstUv + d,
                        normal, normal, normal);
                b.triangle(firstPos + a, firstPos + d, firstPos + e, firstUv + a, firstUv + d, firstUv + e,
                        normal, normal, normal);
            }
        }
    }

    /**
     * A horizontal floor at height {@code y} facing +y, covering x in [x0, x1] and z in [z0, z1].
     * u grows with x and v grows toward -z (away from a camera looking down -z), one texture
     * repeat every {@code repeat} world units.
     *
     * @param b      the builder the quads are added to
     * @param x0     left edge, world x
     * @param x1     right edge, world x
     * @param z0     far edge, world z
     * @param z1     near edge, world z
     * @param y      height, world units
     * @param cellsX quads along x, &gt;= 1
     * @param cellsZ quads along z, &gt;= 1
     * @param repeat world units per texture repeat
     */
    public static void floor(MeshBuilder b, double x0, double x1, double z0, double z1, double y,
                             int cellsX, int cellsZ, double repeat) {
        // Bottom-left as seen from above with -z as "up": (x0, z1); right = +x, up = -z.
        Vec3 origin = new Vec3(x0, y, z1);
        Vec3 right = new Vec3(x1 - x0, 0, 0);
        Vec3 up = new Vec3(0, 0, z0 - z1);
        grid(b, origin, right, up, cellsX, cellsZ, x0 / repeat, -z1 / repeat,
                (x1 - x0) / repeat, (z1 - z0) / repeat);
    }

    /**
     * An axis-aligned box, each face a quad with UVs (0, 0) to (1, 1), upright on the side faces.
     *
     * @param b      the builder the faces are added to
     * @param center centre, world space
     * @param size   edge lengths along x, y and z, world units
     */
    public static void box(MeshBuilder b, Vec3 center, Vec3 size) {
        double hx = size.x() / 2;
        double hy = size.y() / 2;
        double hz = size.z() / 2;
        Vec3 x = new Vec3(hx, 0, 0);
        Vec3 y = new Vec3(0, hy, 0);
        Vec3 z = new Vec3(0, 0, hz);
        // Each face: centre offset n, "right" r and "up" u with r x u pointing along n (outward).
        face(b, center.add(z), x, y);              // +z
        face(b, center.sub(z), x.scale(-1), y);    // -z
        face(b, center.add(x), z.scale(-1), y);    // +x
        face(b, center.sub(x), z, y);              // -x
        face(b, center.add(y), x, z.scale(-1));    // +y
        face(b, center.sub(y), x, z);              // -y
    }

    /** A face of a box: the quad c ± r ± u with UVs (0, 0) to (1, 1) and the normal r x u. */
    private static void face(MeshBuilder b, Vec3 c, Vec3 r, Vec3 u) {
        int p = b.position(c.sub(r).sub(u));
        b.position(c.add(r).sub(u));
        b.position(c.add(r).add(u));
        b.position(c.sub(r).add(u));
        int t = b.uv(0, 0);
        b.uv(1, 0);
        b.uv(1, 1);
        b.uv(0, 1);
        int n = b.normal(r.cross(u).normalize());
        b.triangle(p, p + 1, p + 2, t, t + 1, t + 2, n, n, n);
        b.triangle(p, p + 2, p + 3, t, t + 2, t + 3, n, n, n);
    }

    /**
     * A UV sphere: u runs once around (longitude), v from 0 at the bottom pole to 1 at the top.
     * The pole rows are single triangles, so no triangle is degenerate. Normals are smooth: each
     * position's own direction from the centre.
     *
     * @param b      the builder the triangles are added to
     * @param center centre, world space
     * @param radius radius, world units
     * @param slices divisions around, &gt;= 3
     * @param stacks divisions from pole to pole, &gt;= 2
     */
    public static void sphere(MeshBuilder b, Vec3 center, double radius, int slices, int stacks) {
        if (slices < 3 || stacks < 2) {
            throw new IllegalArgumentException("sphere needs slices >= 3 and stacks >= 2");
        }
        int firstPos = b.positionCount();
        int firstUv = b.uvCount();
        int firstNormal = b.normalCount();
        int row = slices + 1;
        for (int j = 0; j <= stacks; j++) {
            double theta = Math.PI * j / stacks - Math.PI / 2;
            for (int i = 0; i <= slices; i++) {
                // Longitude grows toward -z at phi = 0 so that (east, north) x gives the outward normal.
                double phi = 2 * Math.PI * i / slices;
                double cy = Math.cos(theta);
                double nx = cy * Math.cos(phi);
                double ny = Math.sin(theta);
                double nz = -cy * Math.sin(phi);
                // The positions' expressions as before normals existed, so that they stay bit for bit.
                b.position(center.x() + radius * cy * Math.cos(phi),
                        center.y() + radius * Math.sin(theta),
                        center.z() - radius * cy * Math.sin(phi));
                b.uv((double) i / slices, (double) j / stacks);
                b.normal(nx, ny, nz);
            }
        }
        for (int j = 0; j < stacks; j++) {
            for (int i = 0; i < slices; i++) {
                int a = j * row + i;
                int c = a + 1;
                int d = a + 1 + row;
                int e = a + row;
                if (j > 0) {
                    b.triangle(firstPos + a, firstPos + c, firstPos + d, firstUv + a, firstUv + c, firstUv + d,
                            firstNormal + a, firstNormal + c, firstNormal + d);
                }
                if (j < stacks - 1) {
                    b.triangle(firstPos + a, firstPos + d, firstPos + e, firstUv + a, firstUv + d, firstUv + e,
                            firstNormal + a, firstNormal + d, firstNormal + e);
                }
            }
        }
    }
}
