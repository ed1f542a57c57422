package dev.trisect.mesh;

import static dev.trisect.mesh.PrimitivesTest.assertNonDegenerateAndUnmirrored;
import static dev.trisect.mesh.PrimitivesTest.corner;
import static dev.trisect.mesh.PrimitivesTest.givenNormal;
import static dev.trisect.mesh.PrimitivesTest.normal;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The cylinder, cone, torus, pyramid and arrow: each is watertight with its positions as they are
 * (no welding: every edge is shared by exactly two triangles, bit for bit), wound consistently, encloses
 * a positive volume (so, closed and consistent, every face faces outward), gives every corner a unit
 * normal on the outer side of its triangle, and maps the texture without degenerate or mirrored triangles.
 */
class ShapesTest {

    /** A position's key: its float bits, with -0 made +0 (the same point). */
    private static List<Integer> key(Mesh m, int t, int k) {
        int p = 3 * m.cornerPositions()[3 * t + k];
        float[] xyz = m.positions();
        return List.of(Float.floatToIntBits(xyz[p] + 0f), Float.floatToIntBits(xyz[p + 1] + 0f),
                Float.floatToIntBits(xyz[p + 2] + 0f));
    }

    /**
     * Every edge, positions compared exactly, is used by exactly two triangles, once in each direction;
     * and the enclosed volume (divergence theorem: the sum of p0 . (p1 x p2) / 6) is positive. A closed,
     * consistently wound surface of positive volume has every face outward.
     *
     * @return the enclosed volume
     */
    static double assertWatertightAndOutward(Mesh m) {
        Map<List<List<Integer>>, Integer> directed = new HashMap<>();
        double volume = 0;
        for (int t = 0; t < m.triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                directed.merge(List.of(key(m, t, k), key(m, t, (k + 1) % 3)), 1, Integer::sum);
            }
            volume += corner(m, t, 0).dot(corner(m, t, 1).cross(corner(m, t, 2))) / 6;
        }
        directed.forEach((edge, n) -> {
            assertEquals(1, n, "edge " + edge + " is used more than once in one direction");
            assertEquals(1, directed.getOrDefault(List.of(edge.get(1), edge.get(0)), 0), "edge " + edge
                    + " is not shared by exactly two triangles");
        });
        assertTrue(volume > 0, "the surface encloses a negative volume: it faces inward, " + volume);
        return volume;
    }

    /** Every corner has its own unit normal, on the outer side of its triangle (within 90 degrees of its face). */
    static void assertCornerNormalsOutward(Mesh m) {
        for (int t = 0; t < m.triangleCount(); t++) {
            Vec3 face = normal(m, t).normalize();
            for (int k = 0; k < 3; k++) {
                Vec3 n = givenNormal(m, t, k);
                assertEquals(1, n.length(), 1e-6, "triangle " + t + " corner " + k);
                assertTrue(n.dot(face) > 0, "triangle " + t + " corner " + k + ": normal " + n + " face " + face);
            }
        }
    }

    /**
     * Every check of the class on a shape of {@code triangles} triangles enclosing {@code volume}, its
     * extent about {@code size} (the tolerances scale with it).
     */
    static void assertShape(Mesh m, int triangles, double volume, double size) {
        assertEquals(triangles, m.triangleCount());
        assertEquals(volume, assertWatertightAndOutward(m), 1e-5 * size * size * size);
        assertCornerNormalsOutward(m);
        assertNonDegenerateAndUnmirrored(m, size);
    }

    /** The area of a regular polygon of {@code n} corners on a circle of radius {@code r}. */
    private static double polygon(int n, double r) {
        return n / 2.0 * r * r * Math.sin(2 * Math.PI / n);
    }

    @ParameterizedTest
    @CsvSource({"1, 2, 3", "0.5, 0.1, 16", "3, 7, 40"})
    void cylinder(double radius, double height, int slices) {
        Mesh m = Primitives.cylinder(radius, height, slices);
        assertShape(m, 4 * slices, polygon(slices, radius) * height, Math.max(radius, height));
        for (int t = 0; t < m.triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                Vec3 p = corner(m, t, k);
                Vec3 n = givenNormal(m, t, k);
                assertTrue(Math.abs(p.y()) == (float) (height / 2), "every corner is on an end's rim or centre");
                if (Math.abs(n.y()) < 1e-9) {
                    // The side, smooth: the normal points straight out from the axis.
                    assertEquals(0, n.sub(new Vec3(p.x(), 0, p.z()).normalize()).length(), 1e-6);
                } else {
                    assertEquals(Math.signum(p.y()), n.y(), "the ends face along the axis, out");
                }
            }
        }
    }

    @ParameterizedTest
    @CsvSource({"1, 2, 3", "0.5, 0.1, 16", "3, 7, 40"})
    void cone(double radius, double height, int slices) {
        Mesh m = Primitives.cone(radius, height, slices);
        assertShape(m, 2 * slices, polygon(slices, radius) * height / 3, Math.max(radius, height));
        Vec3 apex = new Vec3(0, (float) (height / 2), 0);
        double slope = radius / height;
        int sides = 0;
        for (int t = 0; t < m.triangleCount(); t++) {
            if (givenNormal(m, t, 0).y() < -0.5) {
                continue; // the base
            }
            sides++;
            assertEquals(apex, corner(m, t, 2), "a side triangle's third corner is the apex");
            for (int k = 0; k < 3; k++) {
                // Smooth, leaning up by the slant's angle.
                Vec3 n = givenNormal(m, t, k);
                assertEquals(slope, n.y() / Math.hypot(n.x(), n.z()), 1e-6, "triangle " + t);
            }
        }
        assertEquals(slices, sides);
    }

    @ParameterizedTest
    @CsvSource({"1, 0.25, 3, 3", "2, 0.5, 24, 12", "5, 4.5, 7, 5"})
    void torus(double major, double minor, int slices, int sides) {
        Mesh m = Primitives.torus(major, minor, slices, sides);
        double size = major + minor;
        // A region of the (radius, height) half-plane swept round a regular n-gon (each radius rho to the
        // n-gon of circumradius rho, of area n/2 rho^2 sin(2 pi / n)) encloses n sin(2 pi / n) times the
        // region's area times its centroid's radius (Pappus for polygons); the tube is a regular polygon
        // centred at the major radius.
        double swept = slices * Math.sin(2 * Math.PI / slices) * polygon(sides, minor) * major;
        assertShape(m, 2 * slices * sides, swept, size);
        for (int t = 0; t < m.triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                Vec3 p = corner(m, t, k);
                Vec3 tube = new Vec3(p.x(), 0, p.z()).normalize().scale(major);
                assertEquals(minor, p.sub(tube).length(), 1e-5 * size, "on the tube");
                assertEquals(0, givenNormal(m, t, k).sub(p.sub(tube).normalize()).length(), 1e-5, "smooth");
            }
        }
    }

    @ParameterizedTest
    @CsvSource({"1, 1, 1", "2, 0.5, 3", "0.1, 4, 0.2"})
    void pyramid(double width, double depth, double height) {
        Mesh m = Primitives.pyramid(width, depth, height);
        assertShape(m, 6, width * depth * height / 3, Math.max(width, Math.max(depth, height)));
        for (int t = 0; t < m.triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                assertEquals(0, givenNormal(m, t, k).sub(normal(m, t).normalize()).length(), 1e-6, "flat faces");
            }
        }
    }

    /** Ends a float holds exactly, so the tip can be compared at 1e-9. */
    private static Vec3 floats(Random r, double scale) {
        return asFloats(new Vec3(r.nextGaussian() * scale, r.nextGaussian() * scale, r.nextGaussian() * scale));
    }

    private static Vec3 asFloats(Vec3 v) {
        return new Vec3((float) v.x(), (float) v.y(), (float) v.z());
    }

    @Test
    void arrowsPointFromStartToEndWithTheTipAtTheEnd() {
        Random r = new Random(29);
        Vec3[] axes = {Vec3.UP, new Vec3(0, -1, 0), new Vec3(1, 0, 0), new Vec3(0, 0, -1), new Vec3(1, 1, 1)};
        for (int i = 0; i < 40; i++) {
            Vec3 start = floats(r, 10);
            Vec3 end = i < axes.length ? asFloats(start.add(axes[i].scale(3))) : floats(r, 10);
            double length = end.sub(start).length();
            double headLength = i % 7 == 6 ? 2 * length : 0.25 * length;
            int slices = 3 + i % 13;
            Mesh m = Primitives.arrow(start, end, 0.02 * length, 0.05 * length, headLength, slices);
            assertEquals((headLength < length ? 6 : 2) * slices, m.triangleCount());
            assertWatertightAndOutward(m);
            assertCornerNormalsOutward(m);
            assertNonDegenerateAndUnmirrored(m, length);
            Vec3 axis = end.sub(start).scale(1 / length);
            // Positions are floats: a few float steps of the largest coordinate around.
            double slack = 1e-6 * (length + start.length() + end.length());
            double farthest = Double.NEGATIVE_INFINITY;
            double tipError = 0;
            for (int t = 0; t < m.triangleCount(); t++) {
                for (int k = 0; k < 3; k++) {
                    Vec3 p = corner(m, t, k);
                    double along = p.sub(start).dot(axis);
                    farthest = Math.max(farthest, along);
                    if (along > length - slack) {
                        tipError = Math.max(tipError, p.sub(end).length());
                    }
                    assertTrue(along > -slack, "nothing behind the start");
                    double radial = p.sub(start).sub(axis.scale(along)).length();
                    assertTrue(radial < 0.05 * length + slack, "nothing wider than the head");
                }
            }
            assertEquals(length, farthest, slack);
            assertTrue(tipError <= 1e-9, "arrow " + i + ": tip " + tipError + " from the end");
        }
    }

    /** An end no float holds: the tip is the end rounded to float, within half a float step per axis. */
    @Test
    void anEndBetweenFloatsIsTheTipRoundedToFloat() {
        Vec3 end = new Vec3(0.1, 1.0 / 3, -2.7);
        Mesh m = Primitives.arrow(Vec3.ZERO, end, 0.01, 0.03, 0.2, 8);
        Vec3 rounded = new Vec3((float) end.x(), (float) end.y(), (float) end.z());
        int tips = 0;
        for (int t = 0; t < m.triangleCount(); t++) {
            for (int k = 0; k < 3; k++) {
                if (corner(m, t, k).sub(end).length() < 1e-6) {
                    assertEquals(rounded, corner(m, t, k));
                    tips++;
                }
            }
        }
        assertEquals(8, tips);
    }

    @Test
    void badArgumentsAreRefusedBeforeAnythingIsAdded() {
        MeshBuilder b = new MeshBuilder();
        assertThrows(IllegalArgumentException.class, () -> Primitives.cylinder(b, Vec3.ZERO, 1, 1, 2));
        assertThrows(IllegalArgumentException.class, () -> Primitives.cylinder(b, Vec3.ZERO, 0, 1, 8));
        assertThrows(IllegalArgumentException.class, () -> Primitives.cone(b, Vec3.ZERO, 1, -1, 8));
        assertThrows(IllegalArgumentException.class, () -> Primitives.torus(b, Vec3.ZERO, 1, 1, 8, 8));
        assertThrows(IllegalArgumentException.class, () -> Primitives.torus(b, Vec3.ZERO, 2, 1, 8, 2));
        assertThrows(IllegalArgumentException.class, () -> Primitives.pyramid(b, Vec3.ZERO, new Vec3(1, 0, 1)));
        assertThrows(IllegalArgumentException.class,
                () -> Primitives.arrow(b, Vec3.UP, Vec3.UP, 0.1, 0.2, 0.3, 8));
        assertThrows(IllegalArgumentException.class,
                () -> Primitives.arrow(b, Vec3.ZERO, Vec3.UP, 0.2, 0.2, 0.3, 8));
        assertThrows(IllegalArgumentException.class,
                () -> Primitives.arrow(b, Vec3.ZERO, new Vec3(Double.NaN, 0, 0), 0.1, 0.2, 0.3, 8));
        assertThrows(IllegalArgumentException.class, () -> Primitives.arrow(b, Vec3.ZERO, Vec3.UP, 0.1, 0.2, 0.3, 2));
        assertEquals(0, b.positionCount());
        assertEquals(0, b.triangleCount());
    }
}
