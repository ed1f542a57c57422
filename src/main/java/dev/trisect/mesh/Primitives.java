package dev.trisect.mesh;

import dev.trisect.math.Vec3;

/**
 * Built-in shapes, front faces outward (counter-clockwise seen from outside), with texture
 * coordinates and outward unit normals: one per face on flat faces (a box's sides, a plane, a
 * pyramid's faces, the ends of a cylinder), one per position on curved surfaces (smooth: a sphere, a
 * torus, the sides of a cylinder, a cone and an arrow). The closed ones (box, sphere, cylinder, cone,
 * torus, pyramid, arrow) are watertight: every edge is shared by exactly two triangles, and but for the
 * sphere (whose seam and poles are within 1e-16 of themselves, as it always was) their positions meet
 * bit for bit.
 *
 * <p>Two forms: {@link #box(double, double, double)}, {@link #plane(double, double, int, int)},
 * {@link #sphere(double, int, int)}, {@link #cylinder(double, double, int)},
 * {@link #cone(double, double, int)}, {@link #torus(double, double, int, int)},
 * {@link #pyramid(double, double, double)} and {@link #arrow(Vec3, Vec3, double, double, double, int)}
 * return a finished {@link Mesh} centred on the origin of its object space (the arrow where its ends
 * are), ready for a {@code dev.trisect.scene.SceneObject}; the forms taking a {@link MeshBuilder}
 * append to it at a given place (to build one mesh of several shapes).
 *
 * <pre>{@code
 * Mesh axisX = Primitives.arrow(Vec3.ZERO, new Vec3(1, 0, 0), 0.02, 0.05, 0.15, 16);
 * }</pre>
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

    /**
     * A cylinder about the y axis centred on the origin: the side smooth, u once around and v from 0 at
     * the bottom to 1 at the top; the two ends flat disks, each showing the whole texture.
     *
     * @param radius radius, object units, &gt; 0
     * @param height extent along y, object units, &gt; 0
     * @param slices divisions around, &gt;= 3
     * @return a mesh of {@code 4 * slices} triangles, one material
     */
    public static Mesh cylinder(double radius, double height, int slices) {
        checkSize(radius, height, 1);
        MeshBuilder b = new MeshBuilder();
        cylinder(b, Vec3.ZERO, radius, height, slices);
        return b.build();
    }

    /**
     * A cone about the y axis centred on the origin: the base a flat disk at y = -height/2 showing the
     * whole texture, the apex at y = height/2; the side smooth, u once around and v from 0 at the base
     * to 1 at the apex.
     *
     * @param radius the base's radius, object units, &gt; 0
     * @param height extent along y, object units, &gt; 0
     * @param slices divisions around, &gt;= 3
     * @return a mesh of {@code 2 * slices} triangles, one material
     */
    public static Mesh cone(double radius, double height, int slices) {
        checkSize(radius, height, 1);
        MeshBuilder b = new MeshBuilder();
        cone(b, Vec3.ZERO, radius, height, slices);
        return b.build();
    }

    /**
     * A torus about the y axis centred on the origin, lying in the plane y = 0: smooth, u once around
     * the y axis and v once around the tube (from its outer equator, upwards first).
     *
     * @param majorRadius distance from the centre to the middle of the tube, object units
     * @param minorRadius the tube's radius, object units, &gt; 0 and less than {@code majorRadius}
     * @param slices      divisions around the y axis, &gt;= 3
     * @param sides       divisions around the tube, &gt;= 3
     * @return a mesh of {@code 2 * slices * sides} triangles, one material
     */
    public static Mesh torus(double majorRadius, double minorRadius, int slices, int sides) {
        MeshBuilder b = new MeshBuilder();
        torus(b, Vec3.ZERO, majorRadius, minorRadius, slices, sides);
        return b.build();
    }

    /**
     * A pyramid centred on the origin: a rectangular base at y = -height/2 and the apex at y =
     * height/2; each face flat with its own normal, each side showing the texture's bottom edge along
     * the base and its top middle at the apex, the base the whole texture.
     *
     * @param width  the base's extent along x, object units, &gt; 0
     * @param depth  the base's extent along z, object units, &gt; 0
     * @param height extent along y, object units, &gt; 0
     * @return a mesh of 6 triangles, one material
     */
    public static Mesh pyramid(double width, double depth, double height) {
        checkSize(width, height, depth);
        MeshBuilder b = new MeshBuilder();
        pyramid(b, Vec3.ZERO, new Vec3(width, height, depth));
        return b.build();
    }

    /**
     * An arrow from {@code start} to {@code end}: a cylindrical shaft and a conical head whose tip is
     * at {@code end} exactly (as float positions hold it), closed by a flat disk at {@code start}.
     * Smooth round, with v running from 0 at the start to 1 at the tip along the profile (by length)
     * and u once around; the disk shows the whole texture.
     *
     * @param start       where the shaft starts, object space
     * @param end         where the tip is, object space; not {@code start}
     * @param shaftRadius the shaft's radius, object units, &gt; 0
     * @param headRadius  the head's radius at its base, object units, &gt; {@code shaftRadius}
     * @param headLength  the head's length along the arrow, object units, &gt; 0; a head as long as the
     *                    arrow or longer makes the whole arrow a cone
     * @param slices      divisions around, &gt;= 3
     * @return a mesh of {@code 6 * slices} triangles ({@code 2 * slices} without a shaft), one material
     */
    public static Mesh arrow(Vec3 start, Vec3 end, double shaftRadius, double headRadius, double headLength,
                             int slices) {
        MeshBuilder b = new MeshBuilder();
        arrow(b, start, end, shaftRadius, headRadius, headLength, slices);
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
        Revolution.sphere(b, center, radius, slices, stacks);
    }

    /**
     * A cylinder about a vertical axis; see {@link #cylinder(double, double, int)}.
     *
     * @param b      the builder the triangles are added to
     * @param center the middle of its axis, object space
     * @param radius radius, object units, &gt; 0
     * @param height extent along y, object units, &gt; 0
     * @param slices divisions around, &gt;= 3
     */
    public static void cylinder(MeshBuilder b, Vec3 center, double radius, double height, int slices) {
        checkSize(radius, height, 1);
        Revolution.cylinder(b, center, radius, height, slices);
    }

    /**
     * A cone about a vertical axis, apex up; see {@link #cone(double, double, int)}.
     *
     * @param b      the builder the triangles are added to
     * @param center the middle of its axis, object space
     * @param radius the base's radius, object units, &gt; 0
     * @param height extent along y, object units, &gt; 0
     * @param slices divisions around, &gt;= 3
     */
    public static void cone(MeshBuilder b, Vec3 center, double radius, double height, int slices) {
        checkSize(radius, height, 1);
        Revolution.cone(b, center, radius, height, slices);
    }

    /**
     * A torus about a vertical axis; see {@link #torus(double, double, int, int)}.
     *
     * @param b           the builder the triangles are added to
     * @param center      its centre, object space
     * @param majorRadius distance from the centre to the middle of the tube, object units
     * @param minorRadius the tube's radius, object units, &gt; 0 and less than {@code majorRadius}
     * @param slices      divisions around the vertical axis, &gt;= 3
     * @param sides       divisions around the tube, &gt;= 3
     */
    public static void torus(MeshBuilder b, Vec3 center, double majorRadius, double minorRadius, int slices,
                             int sides) {
        checkSize(majorRadius, minorRadius, 1);
        if (!(minorRadius < majorRadius) || sides < 3) {
            throw new IllegalArgumentException("torus needs 0 < minorRadius < majorRadius and sides >= 3, got "
                    + majorRadius + ", " + minorRadius + ", " + sides + " sides");
        }
        Revolution.torus(b, center, majorRadius, minorRadius, slices, sides);
    }

    /**
     * A pyramid with its base horizontal and its apex up; see {@link #pyramid(double, double, double)}.
     *
     * @param b      the builder the triangles are added to
     * @param center the middle of its bounding box, object space
     * @param size   the base's width (x) and depth (z) and the height (y), object units, each &gt; 0
     */
    public static void pyramid(MeshBuilder b, Vec3 center, Vec3 size) {
        checkSize(size.x(), size.y(), size.z());
        Vec3 x = new Vec3(size.x() / 2, 0, 0);
        Vec3 y = new Vec3(0, size.y() / 2, 0);
        Vec3 z = new Vec3(0, 0, size.z() / 2);
        Vec3 base = center.sub(y);
        face(b, base, x, z);
        // The base's corners counter-clockwise seen from above, so each side (c_i, c_i+1, apex) faces out.
        Vec3[] corners = {base.add(x).add(z), base.add(x).sub(z), base.sub(x).sub(z), base.sub(x).add(z)};
        Vec3 apex = center.add(y);
        for (int i = 0; i < 4; i++) {
            Vec3 p0 = corners[i];
            Vec3 p1 = corners[(i + 1) % 4];
            int p = b.position(p0);
            b.position(p1);
            b.position(apex);
            int t = b.uv(0, 0);
            b.uv(1, 0);
            b.uv(0.5, 1);
            int n = b.normal(p1.sub(p0).cross(apex.sub(p0)).normalize());
            b.triangle(p, p + 1, p + 2, t, t + 1, t + 2, n, n, n);
        }
    }

    /**
     * An arrow; see {@link #arrow(Vec3, Vec3, double, double, double, int)}.
     *
     * @param b           the builder the triangles are added to
     * @param start       where the shaft starts, object space
     * @param end         where the tip is, object space; not {@code start}
     * @param shaftRadius the shaft's radius, object units, &gt; 0
     * @param headRadius  the head's radius at its base, object units, &gt; {@code shaftRadius}
     * @param headLength  the head's length along the arrow, object units, &gt; 0
     * @param slices      divisions around, &gt;= 3
     */
    public static void arrow(MeshBuilder b, Vec3 start, Vec3 end, double shaftRadius, double headRadius,
                             double headLength, int slices) {
        checkSize(shaftRadius, headRadius, headLength);
        double length = end.sub(start).length();
        if (!start.isFinite() || !end.isFinite() || !(length > 0 && length < Double.POSITIVE_INFINITY)
                || !(headRadius > shaftRadius)) {
            throw new IllegalArgumentException("arrow needs finite start and end apart and headRadius > "
                    + "shaftRadius, got " + start + " to " + end + ", radii " + shaftRadius + ", " + headRadius);
        }
        Revolution.arrow(b, start, end, shaftRadius, headRadius, headLength, slices);
    }
}
