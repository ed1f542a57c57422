package dev.trisect.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class PrimitivesTest {
    /** Positions are floats: compare them with this much slack, relative to the primitive's size. */
    private static final double EPS = 1e-5;

    static Vec3 corner(Mesh m, int t, int k) {
        int p = m.cornerPositions()[3 * t + k];
        float[] xyz = m.positions();
        return new Vec3(xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]);
    }

    /** UV of a corner; a corner without one has (0, 0), as the renderer treats it. */
    static double[] uv(Mesh m, int t, int k) {
        int i = m.cornerUvs()[3 * t + k];
        return i < 0 ? new double[] {0, 0} : new double[] {m.uvs()[2 * i], m.uvs()[2 * i + 1]};
    }

    /** The geometric normal of triangle t: counter-clockwise corners, right-handed cross product. */
    static Vec3 normal(Mesh m, int t) {
        Vec3 a = corner(m, t, 0);
        return corner(m, t, 1).sub(a).cross(corner(m, t, 2).sub(a));
    }

    /** The normal a corner has of its own, as given; fails when it has none. */
    static Vec3 givenNormal(Mesh m, int t, int k) {
        int n = m.cornerNormals()[3 * t + k];
        assertTrue(n >= 0, "triangle " + t + " corner " + k + " has no normal");
        float[] xyz = m.normals();
        return new Vec3(xyz[3 * n], xyz[3 * n + 1], xyz[3 * n + 2]);
    }

    /** Checks that every corner has a normal of its own, of unit length, within 1e-6 of {@code expected}. */
    static void assertNormals(Mesh m, java.util.function.BiFunction<Integer, Integer, Vec3> expected) {
        for (int t = 0; t < m.triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                Vec3 n = givenNormal(m, t, k);
                assertEquals(1, n.length(), 1e-6, "triangle " + t + " corner " + k + " normal length");
                assertEquals(0, n.sub(expected.apply(t, k)).length(), 1e-6,
                        "triangle " + t + " corner " + k + ": " + n + " vs " + expected.apply(t, k));
            }
        }
    }

    static Vec3 centroid(Mesh m, int t) {
        return corner(m, t, 0).add(corner(m, t, 1)).add(corner(m, t, 2)).scale(1.0 / 3);
    }

    /**
     * Checks that no triangle is degenerate and that the texture is not mirrored on any: its corners
     * run counter-clockwise in UV space as they do in space seen from the front.
     */
    static void assertNonDegenerateAndUnmirrored(Mesh m, double size) {
        for (int t = 0; t < m.triangleCount(); t++) {
            assertTrue(normal(m, t).length() / 2 > 1e-6 * size * size, "triangle " + t + " is degenerate");
            double[] a = uv(m, t, 0);
            double[] b = uv(m, t, 1);
            double[] c = uv(m, t, 2);
            double uvArea = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
            assertTrue(uvArea > 0, "triangle " + t + " has a mirrored texture");
        }
    }

    /**
     * Checks that the surface is closed and consistently wound: with positions welded, every edge is
     * used once in each direction.
     */
    static void assertClosed(Mesh m, double size) {
        Map<List<Long>, Integer> edges = new HashMap<>();
        for (int t = 0; t < m.triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                List<Long> from = weld(corner(m, t, k), size);
                List<Long> to = weld(corner(m, t, (k + 1) % 3), size);
                edges.merge(List.of(from.get(0), from.get(1), from.get(2), to.get(0), to.get(1), to.get(2)), 1,
                        Integer::sum);
            }
        }
        edges.forEach((edge, n) -> {
            assertEquals(1, n, "edge " + edge + " is used more than once in one direction");
            List<Long> reverse = List.of(edge.get(3), edge.get(4), edge.get(5), edge.get(0), edge.get(1), edge.get(2));
            assertEquals(1, edges.getOrDefault(reverse, 0), "edge " + edge + " has no twin");
        });
    }

    private static List<Long> weld(Vec3 p, double size) {
        double grid = 1e-4 * size;
        return List.of(Math.round(p.x() / grid), Math.round(p.y() / grid), Math.round(p.z() / grid));
    }

    static double area(Mesh m) {
        double sum = 0;
        for (int t = 0; t < m.triangleCount(); t++) {
            sum += normal(m, t).length() / 2;
        }
        return sum;
    }

    // ---- floor ----

    @ParameterizedTest
    @CsvSource({
        "-10, 10, -20, 5, 0, 4, 6, 2",
        "0, 1, 0, 1, -3.5, 1, 1, 1",
        "3, 7, -2, -1, 2, 3, 1, 0.5",
    })
    void floorFacesUpWithTextureRepeatingInWorldUnits(double x0, double x1, double z0, double z1, double y,
                                                     int cellsX, int cellsZ, double repeat) {
        MeshBuilder b = new MeshBuilder();
        Primitives.floor(b, x0, x1, z0, z1, y, cellsX, cellsZ, repeat);
        Mesh m = b.build();
        double size = Math.max(x1 - x0, z1 - z0);

        assertEquals(2 * cellsX * cellsZ, m.triangleCount());
        assertEquals((cellsX + 1) * (cellsZ + 1), m.positionCount());
        assertEquals(m.positionCount(), m.uvCount());
        assertNonDegenerateAndUnmirrored(m, size);
        assertEquals((x1 - x0) * (z1 - z0), area(m), EPS * size * size);
        assertNormals(m, (t, k) -> Vec3.UP);
        assertEquals(1, m.normalCount());
        for (int t = 0; t < m.triangleCount(); t++) {
            Vec3 n = normal(m, t).normalize();
            assertEquals(1, n.y(), 1e-9, "triangle " + t + " does not face +y");
            for (int k = 0; k < 3; k++) {
                Vec3 p = corner(m, t, k);
                assertEquals(y, p.y(), EPS * size);
                assertTrue(p.x() >= x0 - EPS && p.x() <= x1 + EPS && p.z() >= z0 - EPS && p.z() <= z1 + EPS);
                // u grows with x and v toward -z, one repeat every `repeat` world units.
                assertEquals(p.x() / repeat, uv(m, t, k)[0], EPS * size / repeat);
                assertEquals(-p.z() / repeat, uv(m, t, k)[1], EPS * size / repeat);
            }
        }
    }

    // ---- box ----

    @ParameterizedTest
    @CsvSource({
        "0, 0, 0, 1, 1, 1",
        "2, -1, 5, 3, 0.5, 7",
        "-4, 10, -2, 0.25, 6, 2",
    })
    void boxFacesOutwardWithUprightUnitTexturePerFace(double cx, double cy, double cz, double sx, double sy, double sz) {
        Vec3 centre = new Vec3(cx, cy, cz);
        Vec3 half = new Vec3(sx / 2, sy / 2, sz / 2);
        MeshBuilder b = new MeshBuilder();
        Primitives.box(b, centre, new Vec3(sx, sy, sz));
        Mesh m = b.build();
        double size = Math.max(sx, Math.max(sy, sz));

        assertEquals(12, m.triangleCount());
        assertEquals(24, m.positionCount());
        assertEquals(24, m.uvCount());
        assertNonDegenerateAndUnmirrored(m, size);
        assertClosed(m, size);
        assertEquals(2 * (sx * sy + sy * sz + sz * sx), area(m), EPS * size * size);

        Map<Vec3, Integer> trianglesPerFace = new HashMap<>();
        for (int t = 0; t < m.triangleCount(); t++) {
            Vec3 n = normal(m, t).normalize();
            Vec3 axis = new Vec3(Math.round(n.x()), Math.round(n.y()), Math.round(n.z()));
            assertEquals(1, n.dot(axis), 1e-9, "triangle " + t + " is not axis-aligned");
            trianglesPerFace.merge(axis, 1, Integer::sum);
            double halfAlong = Math.abs(half.dot(axis));
            Vec3 faceCentre = centre.add(axis.scale(halfAlong));
            // Outward: the face lies on the side of the centre its normal points to.
            assertEquals(halfAlong, centroid(m, t).sub(centre).dot(axis), EPS * size, "triangle " + t);
            for (int k = 0; k < 3; k++) {
                double[] uv = uv(m, t, k);
                assertTrue((uv[0] == 0 || uv[0] == 1) && (uv[1] == 0 || uv[1] == 1), "UVs span (0,0)-(1,1)");
                if (axis.y() == 0) {
                    // Side faces: v grows with +y; u grows to the right of a viewer looking at the face.
                    Vec3 right = Vec3.UP.cross(axis);
                    Vec3 d = corner(m, t, k).sub(faceCentre);
                    assertEquals(d.y() > 0 ? 1 : 0, uv[1], "triangle " + t + " corner " + k + " v");
                    assertEquals(d.dot(right) > 0 ? 1 : 0, uv[0], "triangle " + t + " corner " + k + " u");
                }
            }
        }
        assertEquals(6, trianglesPerFace.size());
        trianglesPerFace.values().forEach(n -> assertEquals(2, n));
        // One normal per face, outward: the face's own geometric normal.
        assertEquals(6, m.normalCount());
        assertNormals(m, (t, k) -> normal(m, t).normalize());
    }

    // ---- sphere ----

    @ParameterizedTest
    @CsvSource({
        "0, 0, 0, 1, 3, 2",
        "1, 2, 3, 2.5, 16, 8",
        "-5, 0, 4, 0.5, 7, 5",
        "0, 0, 0, 10, 64, 32",
    })
    void sphereFacesOutwardAndIsClosed(double cx, double cy, double cz, double radius, int slices, int stacks) {
        Vec3 centre = new Vec3(cx, cy, cz);
        MeshBuilder b = new MeshBuilder();
        Primitives.sphere(b, centre, radius, slices, stacks);
        Mesh m = b.build();
        double size = 2 * radius;

        assertEquals(slices * (2 * stacks - 2), m.triangleCount());
        assertEquals((slices + 1) * (stacks + 1), m.positionCount());
        assertEquals(m.positionCount(), m.uvCount());
        assertNonDegenerateAndUnmirrored(m, size);
        assertClosed(m, size);
        for (int t = 0; t < m.triangleCount(); t++) {
            Vec3 n = normal(m, t).normalize();
            Vec3 out = centroid(m, t).sub(centre).normalize();
            assertTrue(n.dot(out) > 0.5, "triangle " + t + " does not face outward: " + n + " vs " + out);
            for (int k = 0; k < 3; k++) {
                Vec3 d = corner(m, t, k).sub(centre);
                assertEquals(radius, d.length(), EPS * size);
                // v runs from 0 at the bottom pole to 1 at the top.
                double latitude = Math.atan2(d.y(), Math.hypot(d.x(), d.z()));
                assertEquals(latitude / Math.PI + 0.5, uv(m, t, k)[1], 1e-5);
            }
        }
        // Smooth: each corner's normal is its position's direction from the centre, shared by its triangles.
        assertEquals(m.positionCount(), m.normalCount());
        assertNormals(m, (t, k) -> corner(m, t, k).sub(centre).normalize());
        assertArrayEquals(m.cornerPositions(), m.cornerNormals());
    }

    // ---- grid and arguments ----

    @Test
    void gridFacesRightCrossUpWithTheGivenUvRange() {
        MeshBuilder b = new MeshBuilder();
        Vec3 origin = new Vec3(1, 2, 3);
        Vec3 right = new Vec3(0, 0, -4);
        Vec3 up = new Vec3(0, 2, 0);
        Primitives.grid(b, origin, right, up, 2, 3, 0.5, -1, 3, 2);
        Mesh m = b.build();
        assertEquals(12, m.triangleCount());
        assertNonDegenerateAndUnmirrored(m, 4);
        Vec3 facing = right.cross(up).normalize();
        assertNormals(m, (t, k) -> facing);
        for (int t = 0; t < m.triangleCount(); t++) {
            assertEquals(1, normal(m, t).normalize().dot(facing), 1e-9);
            for (int k = 0; k < 3; k++) {
                Vec3 d = corner(m, t, k).sub(origin);
                assertEquals(0.5 + 3 * d.dot(right) / right.dot(right), uv(m, t, k)[0], EPS);
                assertEquals(-1 + 2 * d.dot(up) / up.dot(up), uv(m, t, k)[1], EPS);
            }
        }
    }

    @Test
    void rejectsTooFewCells() {
        MeshBuilder b = new MeshBuilder();
        assertThrows(IllegalArgumentException.class,
                () -> Primitives.grid(b, Vec3.ZERO, new Vec3(1, 0, 0), Vec3.UP, 0, 1, 0, 0, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> Primitives.sphere(b, Vec3.ZERO, 1, 2, 4));
        assertThrows(IllegalArgumentException.class, () -> Primitives.sphere(b, Vec3.ZERO, 1, 8, 1));
        assertEquals(0, b.triangleCount());
    }
}
