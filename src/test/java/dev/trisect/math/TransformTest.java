package dev.trisect.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** Rotations and transforms against values worked out by hand. */
class TransformTest {
    private static void near(Vec3 expected, Vec3 actual) {
        assertEquals(expected.x(), actual.x(), 1e-12, "x of " + actual);
        assertEquals(expected.y(), actual.y(), 1e-12, "y of " + actual);
        assertEquals(expected.z(), actual.z(), 1e-12, "z of " + actual);
    }

    @Test
    void rotationsTurnCounterClockwiseAboutTheirAxis() {
        near(new Vec3(0, 0, -1), Quaternion.ofY(90).rotate(new Vec3(1, 0, 0)));
        near(new Vec3(0, 1, 0), Quaternion.ofZ(90).rotate(new Vec3(1, 0, 0)));
        near(new Vec3(0, 0, 1), Quaternion.ofX(90).rotate(new Vec3(0, 1, 0)));
        // b first, then a: x -> (about z) y -> (about x) z
        near(new Vec3(0, 0, 1), Quaternion.ofX(90).mul(Quaternion.ofZ(90)).rotate(new Vec3(1, 0, 0)));
        near(new Vec3(1, 0, 0), Quaternion.ofY(37).inverse().mul(Quaternion.ofY(37)).rotate(new Vec3(1, 0, 0)));
        near(new Vec3(0, 1, 0), Quaternion.axisAngle(new Vec3(1, 1, 1), 120).rotate(new Vec3(1, 0, 0)));
    }

    @Test
    void transformScalesThenRotatesThenMoves() {
        Transform t = Transform.translation(10, 20, 30).withRotation(Quaternion.ofZ(90)).withScale(new Vec3(2, 3, 4));
        // (1, 1, 1) -> scaled (2, 3, 4) -> rotated about z (-3, 2, 4) -> moved (7, 22, 34)
        near(new Vec3(7, 22, 34), t.apply(new Vec3(1, 1, 1)));
        near(new Vec3(7, 22, 34), t.matrix().transformProject(new Vec3(1, 1, 1)));
        near(new Vec3(11, 21, 31), Transform.IDENTITY.movedBy(11, 21, 31).apply(Vec3.ZERO));
    }

    @Test
    void badValuesAreRefusedWithTheirValue() {
        assertThrows(IllegalArgumentException.class, () -> Transform.scale(0));
        assertThrows(IllegalArgumentException.class, () -> Transform.translation(Double.NaN, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> Quaternion.axisAngle(Vec3.ZERO, 10));
        assertEquals("transform rotation is null",
                assertThrows(NullPointerException.class, () -> Transform.IDENTITY.withRotation(null)).getMessage());
    }

    /** get(4, 0) read the element at (0, 1) of the column-major array instead of refusing the row. */
    @Test
    void matrixElementsOutsideTheFourByFourAreRefused() {
        Mat4 m = Transform.translation(1, 2, 3).matrix();
        assertEquals(3, m.get(2, 3));
        assertThrows(IndexOutOfBoundsException.class, () -> m.get(4, 0));
        assertThrows(IndexOutOfBoundsException.class, () -> m.get(-1, 1));
        assertThrows(IndexOutOfBoundsException.class, () -> m.get(0, 4));
    }

    /** lookAt(eye, eye, up) gave a matrix of zeros and perspective(0, ...) one of infinities, silently. */
    @Test
    void degenerateCameraMatricesAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> Mat4.lookAt(Vec3.ZERO, Vec3.ZERO, Vec3.UP));
        assertThrows(IllegalArgumentException.class, () -> Mat4.lookAt(Vec3.ZERO, new Vec3(0, 5, 0), Vec3.UP));
        assertThrows(IllegalArgumentException.class, () -> Mat4.lookAt(Vec3.ZERO, new Vec3(1, 0, 0), Vec3.ZERO));
        assertThrows(IllegalArgumentException.class,
                () -> Mat4.lookAt(new Vec3(Double.NaN, 0, 0), new Vec3(1, 0, 0), Vec3.UP));
        assertThrows(IllegalArgumentException.class, () -> Mat4.perspective(0, 1, 0.1, 10));
        assertThrows(IllegalArgumentException.class, () -> Mat4.perspective(60, 0, 0.1, 10));
        assertThrows(IllegalArgumentException.class, () -> Mat4.perspective(60, 1, 0, 10));
        assertThrows(IllegalArgumentException.class, () -> Mat4.perspective(60, 1, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> Mat4.perspective(60, 1, 1, Double.POSITIVE_INFINITY));
        assertEquals(1, Mat4.lookAt(Vec3.ZERO, new Vec3(0, 0, -1), Vec3.UP).get(2, 2)); // looking down -z: the identity
        assertEquals(1, Mat4.perspective(90, 1, 1, 2).get(1, 1), 1e-15);
    }

    /**
     * A far plane beyond Double.MAX_VALUE / 2 overflowed 2 * far * near (computed with 2 * far first),
     * and every triangle was skipped; near first, every finite far works with a near below 0.5. Where
     * the product itself overflows, the matrix is refused instead of holding an infinity.
     */
    @Test
    void everyFiniteFarWorksWithASmallNearAndAnOverflowIsRefused() {
        Mat4 p = Mat4.perspective(60, 1, 0.1, Double.MAX_VALUE);
        assertEquals(-1, p.get(2, 2));
        assertEquals(-0.2, p.get(2, 3), 1e-15);
        assertThrows(IllegalArgumentException.class, () -> Mat4.perspective(60, 1, 1, 1e308));
        // Below the overflow, the same bits as the old order: doubling is exact.
        assertEquals(2 * 1000.0 * 0.1 / (0.1 - 1000), Mat4.perspective(60, 1, 0.1, 1000).get(2, 3));
    }
}
