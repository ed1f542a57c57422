package dev.trisect.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

class MeshBuilderTest {

    private static MeshBuilder withTriangleCorners() {
        MeshBuilder b = new MeshBuilder();
        b.position(0, 0, 0);
        b.position(1, 0, 0);
        b.position(0, 1, 0);
        b.uv(0, 0);
        return b;
    }

    @Test
    void trianglesWithoutAMaterialGetDefault() {
        MeshBuilder b = withTriangleCorners();
        b.triangle(0, 1, 2, -1, -1, -1);
        assertEquals(1, b.material("red"));
        b.triangle(0, 1, 2, 0, 0, 0);
        assertEquals(0, b.material("default"));
        b.triangle(0, 1, 2, 0, -1, 0);
        Mesh m = b.build();
        assertEquals(List.of("default", "red"), m.materialNames());
        assertArrayEquals(new int[] {0, 1, 0}, m.triangleMaterials());
    }

    @Test
    void aMaterialSetFirstLeavesNoDefault() {
        MeshBuilder b = withTriangleCorners();
        assertEquals(0, b.material("a"));
        assertEquals(1, b.material("b"));
        assertEquals(0, b.material("a"));
        b.triangle(0, 1, 2, -1, -1, -1);
        assertEquals(List.of("a", "b"), b.build().materialNames());
    }

    @Test
    void anEmptyMeshStillHasOneMaterial() {
        Mesh m = new MeshBuilder().build();
        assertEquals(0, m.triangleCount());
        assertEquals(List.of("default"), m.materialNames());
    }

    @Test
    void quadIsTwoTrianglesSharingTheFirstAndThirdCorner() {
        MeshBuilder b = new MeshBuilder();
        b.quad(new Vec3(0, 0, 0), new Vec3(1, 0, 0), new Vec3(1, 1, 0), new Vec3(0, 1, 0),
                0, 0, 1, 0, 1, 1, 0, 1);
        Mesh m = b.build();
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, m.cornerPositions());
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, m.cornerUvs());
        assertArrayEquals(new float[] {0, 0, 1, 0, 1, 1, 0, 1}, m.uvs());
        assertEquals(1, PrimitivesTest.normal(m, 0).normalize().z(), 1e-12);
        assertEquals(1, PrimitivesTest.normal(m, 1).normalize().z(), 1e-12);
    }

    @Test
    void growsPastItsInitialCapacityAndTrimsOnBuild() {
        MeshBuilder b = new MeshBuilder();
        int n = 1000;
        for (int i = 0; i < n; i++) {
            b.position(i, 0.1, -i);
            b.uv(i, 0.5);
        }
        for (int i = 0; i + 2 < n; i++) {
            b.triangle(i, i + 1, i + 2, i, -1, i + 2);
        }
        Mesh m = b.build();
        assertEquals(3 * n, m.positions().length);
        assertEquals(2 * n, m.uvs().length);
        assertEquals(3 * (n - 2), m.cornerPositions().length);
        assertEquals(n - 2, m.triangleMaterials().length);
        assertEquals(999f, m.positions()[3 * 999]);
        assertEquals(0.1f, m.positions()[3 * 999 + 1]);
        assertEquals(-999f, m.positions()[3 * 999 + 2]);
        assertArrayEquals(new int[] {997, -1, 999}, Arrays.copyOfRange(m.cornerUvs(), 3 * 997, 3 * 998));
    }

    @Test
    void aBuiltMeshIsNotChangedByLaterAdditions() {
        MeshBuilder b = withTriangleCorners();
        b.triangle(0, 1, 2, -1, -1, -1);
        Mesh first = b.build();
        b.position(5, 5, 5);
        b.material("late");
        b.triangle(3, 1, 2, -1, -1, -1);
        Mesh second = b.build();
        assertEquals(1, first.triangleCount());
        assertEquals(3, first.positionCount());
        assertEquals(List.of("default"), first.materialNames());
        assertEquals(2, second.triangleCount());
        assertEquals(List.of("default", "late"), second.materialNames());
    }

    @Test
    void rejectsIndicesNotYetAdded() {
        MeshBuilder b = withTriangleCorners();
        assertThrows(IndexOutOfBoundsException.class, () -> b.triangle(0, 1, 3, -1, -1, -1));
        assertThrows(IndexOutOfBoundsException.class, () -> b.triangle(-1, 1, 2, -1, -1, -1));
        assertThrows(IndexOutOfBoundsException.class, () -> b.triangle(0, 1, 2, 1, -1, -1));
        assertThrows(IndexOutOfBoundsException.class, () -> b.triangle(0, 1, 2, -1, -2, -1));
        assertEquals(0, b.triangleCount());
    }

    /** A null material name was taken and failed in build() with List.copyOf's bare NullPointerException. */
    @Test
    void aNullMaterialNameIsRefusedWhereItIsGiven() {
        MeshBuilder b = withTriangleCorners();
        assertEquals("material name is null", assertThrows(NullPointerException.class, () -> b.material(null)).getMessage());
        b.triangle(0, 1, 2, 0, 0, 0);
        assertEquals(List.of("default"), b.build().materialNames());
    }

    @Test
    void normalsAreKeptAsGivenAndIndexedPerCorner() {
        MeshBuilder b = withTriangleCorners();
        assertEquals(0, b.normal(0, 0, 2));
        assertEquals(1, b.normal(new Vec3(1, 0, 0)));
        b.triangle(0, 1, 2, 0, -1, 0, 1, -1, 0);
        b.triangle(0, 1, 2, -1, -1, -1);
        Mesh m = b.build();
        assertEquals(2, m.normalCount());
        assertArrayEquals(new float[] {0, 0, 2, 1, 0, 0}, m.normals());
        assertArrayEquals(new int[] {1, -1, 0, -1, -1, -1}, m.cornerNormals());
        double[] n = new double[3];
        m.cornerNormal(2, n, 0);
        assertArrayEquals(new double[] {0, 0, 1}, n);
        m.cornerNormal(1, n, 0);
        assertArrayEquals(new double[] {0, 0, 1}, n, 0, "the face normal of a counter-clockwise triangle");
    }

    @Test
    void aNormalWithoutDirectionIsRefusedWhereItIsGiven() {
        MeshBuilder b = withTriangleCorners();
        for (double[] bad : new double[][] {{0, 0, 0}, {Double.NaN, 0, 1}, {0, Double.POSITIVE_INFINITY, 0},
            {1e300, 0, 0}, {1e-50, 0, 0}}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> b.normal(bad[0], bad[1], bad[2]));
            assertTrue(e.getMessage().contains("has no direction"), e.getMessage());
        }
        assertEquals(0, b.normalCount());
        assertThrows(IndexOutOfBoundsException.class, () -> b.triangle(0, 1, 2, -1, -1, -1, 0, -1, -1));
        b.normal(0, 0, 1);
        assertThrows(IndexOutOfBoundsException.class, () -> b.triangle(0, 1, 2, -1, -1, -1, 0, 1, -1));
        assertThrows(IndexOutOfBoundsException.class, () -> b.triangle(0, 1, 2, -1, -1, -1, -2, 0, 0));
        assertEquals(0, b.triangleCount());
    }

    /** Face normals of the largest and smallest float triangles are unit: nothing overflows or vanishes. */
    @Test
    void faceNormalsOfHugeAndTinyTrianglesAreUnit() {
        for (double scale : new double[] {1e38, 1e-38, Float.MIN_VALUE, 1}) {
            MeshBuilder b = new MeshBuilder();
            b.position(0, 0, 0);
            b.position(0, 0, -scale);
            b.position(0, 2 * scale, 0);
            b.triangle(0, 1, 2, -1, -1, -1);
            double[] n = new double[4];
            b.build().faceNormal(0, n, 1);
            assertArrayEquals(new double[] {0, 1, 0, 0}, n, 1e-15, "scale " + scale);
        }
    }
}
