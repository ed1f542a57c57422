package dev.trisect.mesh;

import dev.trisect.math.Vec3;

/**
 * Surfaces of revolution for {@link Primitives}: rings of vertices around an axis, joined into strips,
 * closed by an apex or a flat disk; and the shapes made of them (sphere, cylinder, cone, torus, arrow),
 * their arguments checked by {@link Primitives}. One vertex is one position, one texture coordinate and one normal,
 * added together, so a vertex's three indices differ by fixed offsets.
 *
 * <p>The frame is right-handed: {@code e1} and {@code e2 = axis x e1} span the plane of a ring, and a
 * ring's vertex {@code i} of {@code slices} is at angle {@code phi = 2 pi i / slices} from {@code e1}
 * towards {@code e2}, so that going round is counter-clockwise seen from the tip of {@code axis}. A
 * profile point is a radius {@code r} and a height {@code h} along the axis; its normal in the
 * profile plane is {@code (nr, nh)}. A strip from a lower ring to an upper one (in the order the
 * profile runs) faces the side {@code (dh, -dr)}, the profile's tangent turned clockwise: outward for a
 * profile that runs up the outside of a solid, as every profile here does.
 */
final class Revolution {
    private final MeshBuilder b;
    private final Vec3 origin;
    private final Vec3 e1;
    private final Vec3 e2;
    private final Vec3 axis;
    private final int slices;
    private final boolean exactSeam;
    private final int uvOffset;
    private final int normalOffset;

    /**
     * @param b      the builder the vertices and triangles are added to; nothing else may add to it
     *               while this is in use
     * @param origin the point of the axis at height 0, object space
     * @param axis   the axis, unit length
     * @param e1     a unit direction perpendicular to {@code axis}, where each ring starts
     * @param slices vertices around (plus one repeating the first, for the texture's seam), &gt;= 3
     * @param exactSeam whether a ring's last vertex is at its first one's position bit for bit (angle
     *                  0 rather than 2 pi, whose sine is -2.4e-16), so that the seam's edges are shared
     *                  exactly; false only for the sphere, to keep the positions it always had
     */
    Revolution(MeshBuilder b, Vec3 origin, Vec3 axis, Vec3 e1, int slices, boolean exactSeam) {
        if (slices < 3) {
            throw new IllegalArgumentException("a shape of revolution needs at least 3 slices, got " + slices);
        }
        this.b = b;
        this.origin = origin;
        this.axis = axis;
        this.e1 = e1;
        this.e2 = axis.cross(e1);
        this.slices = slices;
        this.exactSeam = exactSeam;
        this.uvOffset = b.uvCount() - b.positionCount();
        this.normalOffset = b.normalCount() - b.positionCount();
    }

    /** A frame about the y axis with e1 = +x, so that e2 = -z (the sphere's longitude). */
    static Revolution aboutY(MeshBuilder b, Vec3 origin, int slices, boolean exactSeam) {
        return new Revolution(b, origin, Vec3.UP, new Vec3(1, 0, 0), slices, exactSeam);
    }

    /** A frame about {@code axis} (unit length), e1 any unit direction perpendicular to it. */
    static Revolution about(MeshBuilder b, Vec3 origin, Vec3 axis, int slices) {
        // Cross with the coordinate axis least aligned with the axis: never near parallel.
        double ax = Math.abs(axis.x());
        double ay = Math.abs(axis.y());
        double az = Math.abs(axis.z());
        Vec3 least = ax <= ay && ax <= az ? new Vec3(1, 0, 0) : ay <= az ? Vec3.UP : new Vec3(0, 0, 1);
        return new Revolution(b, origin, axis, axis.cross(least).normalize(), slices, true);
    }

    /**
     * Adds a ring of {@code slices + 1} vertices (the last at the first's place, with u = 1) at radius
     * {@code r} and height {@code h}, texture coordinates ({@code i / slices}, {@code v}), normals
     * {@code (nr, nh)} turned with the ring.
     *
     * @return the ring's first position index
     */
    int ring(double r, double h, double nr, double nh, double v) {
        int first = b.positionCount();
        for (int i = 0; i <= slices; i++) {
            vertex(r, h, angle(i), nr, nh, (double) i / slices, v);
        }
        return first;
    }

    /**
     * Adds the apex of a cone: {@code slices} vertices at one position, {@code at} exactly, each with
     * the normal of the middle of its slice (so the surface is smooth up to the tip) and u there.
     *
     * @param at the apex's position, object space
     * @return the apex's first position index
     */
    int apex(Vec3 at, double nr, double nh, double v) {
        int first = b.positionCount();
        for (int i = 0; i < slices; i++) {
            b.position(at);
            b.uv((i + 0.5) / slices, v);
            normal(2 * Math.PI * (i + 0.5) / slices, nr, nh);
        }
        return first;
    }

    /** The point of the axis at height {@code h}, object space. */
    Vec3 axisPoint(double h) {
        return origin.add(axis.scale(h));
    }

    /** Joins two rings made by {@link #ring} with two triangles per slice, facing as the class says. */
    void strip(int lower, int upper) {
        strip(lower, upper, true, true);
    }

    /**
     * As {@link #strip(int, int)}, leaving out the lower triangle of each quad ({@code lowerHalf}
     * false: the lower ring has no extent, a pole) or the upper one ({@code upperHalf} false).
     */
    void strip(int lower, int upper, boolean lowerHalf, boolean upperHalf) {
        for (int i = 0; i < slices; i++) {
            int a = lower + i;
            int c = a + 1;
            int d = upper + i + 1;
            int e = upper + i;
            if (lowerHalf) {
                triangle(a, c, d);
            }
            if (upperHalf) {
                triangle(a, d, e);
            }
        }
    }

    /** Joins a ring to an apex made by {@link #apex} above it, one triangle per slice. */
    void toApex(int ring, int apex) {
        for (int i = 0; i < slices; i++) {
            triangle(ring + i, ring + i + 1, apex + i);
        }
    }

    /**
     * A flat disk of radius {@code r} at height {@code h}, facing along the axis ({@code up}) or
     * against it: a centre and a rim, one triangle per slice, the texture mapped flat (the disk spans
     * (0, 0) to (1, 1), upright and unmirrored seen from the side it faces).
     */
    void disk(double r, double h, boolean up) {
        double nh = up ? 1 : -1;
        int centre = b.positionCount();
        b.position(axisPoint(h));
        b.uv(0.5, 0.5);
        normal(0, 0, nh);
        for (int i = 0; i <= slices; i++) {
            double phi = angle(i);
            // Seen from below, e2 points down the picture: v runs against it there.
            vertex(r, h, phi, 0, nh, 0.5 + 0.5 * Math.cos(phi), 0.5 + 0.5 * nh * Math.sin(phi));
        }
        for (int i = 0; i < slices; i++) {
            int rim = centre + 1 + i;
            if (up) {
                triangle(centre, rim, rim + 1);
            } else {
                triangle(centre, rim + 1, rim);
            }
        }
    }

    /** The angle of vertex {@code i} of a ring, radians. */
    private double angle(int i) {
        return 2 * Math.PI * (exactSeam && i == slices ? 0 : i) / slices;
    }

    private void vertex(double r, double h, double phi, double nr, double nh, double u, double v) {
        double x = r * Math.cos(phi);
        double y = r * Math.sin(phi);
        b.position(origin.x() + (e1.x() * x + e2.x() * y + axis.x() * h),
                origin.y() + (e1.y() * x + e2.y() * y + axis.y() * h),
                origin.z() + (e1.z() * x + e2.z() * y + axis.z() * h));
        b.uv(u, v);
        normal(phi, nr, nh);
    }

    private void normal(double phi, double nr, double nh) {
        double x = nr * Math.cos(phi);
        double y = nr * Math.sin(phi);
        b.normal(e1.x() * x + e2.x() * y + axis.x() * nh, e1.y() * x + e2.y() * y + axis.y() * nh,
                e1.z() * x + e2.z() * y + axis.z() * nh);
    }

    private void triangle(int p0, int p1, int p2) {
        b.triangle(p0, p1, p2, p0 + uvOffset, p1 + uvOffset, p2 + uvOffset,
                p0 + normalOffset, p1 + normalOffset, p2 + normalOffset);
    }

    // ---- The shapes, their arguments checked by Primitives ----

    /** {@link Primitives#sphere(MeshBuilder, Vec3, double, int, int)}. */
    static void sphere(MeshBuilder b, Vec3 center, double radius, int slices, int stacks) {
        // Rings from the bottom pole to the top, the poles' rings of (nearly) zero radius; their
        // positions are the expressions used before the shapes shared this class, bit for bit.
        Revolution around = aboutY(b, center, slices, false);
        int first = b.positionCount();
        for (int j = 0; j <= stacks; j++) {
            double theta = Math.PI * j / stacks - Math.PI / 2;
            double cy = Math.cos(theta);
            around.ring(radius * cy, radius * Math.sin(theta), cy, Math.sin(theta), (double) j / stacks);
        }
        int row = slices + 1;
        for (int j = 0; j < stacks; j++) {
            around.strip(first + j * row, first + (j + 1) * row, j > 0, j < stacks - 1);
        }
    }

    /** {@link Primitives#cylinder(MeshBuilder, Vec3, double, double, int)}. */
    static void cylinder(MeshBuilder b, Vec3 center, double radius, double height, int slices) {
        Revolution around = aboutY(b, center, slices, true);
        around.disk(radius, -height / 2, false);
        around.strip(around.ring(radius, -height / 2, 1, 0, 0), around.ring(radius, height / 2, 1, 0, 1));
        around.disk(radius, height / 2, true);
    }

    /** {@link Primitives#cone(MeshBuilder, Vec3, double, double, int)}. */
    static void cone(MeshBuilder b, Vec3 center, double radius, double height, int slices) {
        Revolution around = aboutY(b, center, slices, true);
        around.disk(radius, -height / 2, false);
        around.coneSide(radius, -height / 2, height / 2, around.axisPoint(height / 2), 0, 1);
    }

    /** {@link Primitives#torus(MeshBuilder, Vec3, double, double, int, int)}. */
    static void torus(MeshBuilder b, Vec3 center, double majorRadius, double minorRadius, int slices, int sides) {
        Revolution around = aboutY(b, center, slices, true);
        int first = b.positionCount();
        for (int j = 0; j <= sides; j++) {
            // The last ring is the first again, exactly, with v = 1: the tube's seam shares its edges.
            double theta = 2 * Math.PI * (j == sides ? 0 : j) / sides;
            double c = Math.cos(theta);
            double s = Math.sin(theta);
            around.ring(majorRadius + minorRadius * c, minorRadius * s, c, s, (double) j / sides);
        }
        for (int j = 0; j < sides; j++) {
            around.strip(first + j * (slices + 1), first + (j + 1) * (slices + 1));
        }
    }

    /** {@link Primitives#arrow(MeshBuilder, Vec3, Vec3, double, double, double, int)}. */
    static void arrow(MeshBuilder b, Vec3 start, Vec3 end, double shaftRadius, double headRadius,
                      double headLength, int slices) {
        double length = end.sub(start).length();
        Revolution around = about(b, start, end.sub(start).scale(1 / length), slices);
        double shaft = length - Math.min(headLength, length);
        if (shaft == 0) {
            around.disk(headRadius, 0, false);
            around.coneSide(headRadius, 0, length, end, 0, 1);
            return;
        }
        // v by length along the profile: up the shaft, out across the shoulder, up the head's slant.
        double total = shaft + (headRadius - shaftRadius) + Math.hypot(headRadius, length - shaft);
        double v1 = shaft / total;
        double v2 = (shaft + headRadius - shaftRadius) / total;
        around.disk(shaftRadius, 0, false);
        around.strip(around.ring(shaftRadius, 0, 1, 0, 0), around.ring(shaftRadius, shaft, 1, 0, v1));
        around.strip(around.ring(shaftRadius, shaft, 0, -1, v1), around.ring(headRadius, shaft, 0, -1, v2));
        around.coneSide(headRadius, shaft, length, end, v2, 1);
    }

    /**
     * The side of a cone from a ring of {@code radius} at height {@code base} to the apex {@code tip}
     * at height {@code top}, v from {@code v0} to {@code v1}; the normal is the slant's.
     */
    private void coneSide(double radius, double base, double top, Vec3 tip, double v0, double v1) {
        double slant = Math.hypot(radius, top - base);
        double nr = (top - base) / slant;
        double nh = radius / slant;
        toApex(ring(radius, base, nr, nh, v0), apex(tip, nr, nh, v1));
    }
}
