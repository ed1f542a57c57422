package dev.trisect.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Any finite, non-zero quaternion is a rotation, however large or small its components: they are
 * scaled before they are squared (as Vec3.normalize does), so the matrix is finite and right; and a
 * transform either has a finite matrix or is refused where it is made, naming the value.
 */
class QuaternionExtremesTest {
    private static void assertSameMatrix(Mat4 expected, Mat4 actual) {
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 4; c++) {
                assertTrue(Double.isFinite(actual.get(r, c)), "entry " + r + "," + c + " of " + actual);
                assertEquals(expected.get(r, c), actual.get(r, c), 1e-15, "entry " + r + "," + c);
            }
        }
    }

    @Test
    void tinyHugeAndSubnormalComponentsRotateAsTheirDirection() {
        Mat4 halfTurnX = new Quaternion(1, 0, 0, 0).matrix();
        assertSameMatrix(halfTurnX, new Quaternion(1e-200, 0, 0, 0).matrix());
        assertSameMatrix(halfTurnX, new Quaternion(Double.MIN_VALUE, 0, 0, 0).matrix());
        assertSameMatrix(halfTurnX, new Quaternion(1e300, 0, 0, 0).matrix());
        Mat4 quarterX = Quaternion.of(1, 0, 0, 1).matrix();
        assertSameMatrix(quarterX, new Quaternion(1e200, 0, 0, 1e200).matrix());
        assertSameMatrix(quarterX, new Quaternion(1e-200, 0, 0, 1e-200).matrix());
        assertSameMatrix(quarterX, Quaternion.of(1e200, 0, 0, 1e200).matrix());
        assertSameMatrix(quarterX, Quaternion.of(-1e-310, 0, 0, -1e-310).matrix());
        assertSameMatrix(Transform.rotation(Quaternion.of(1, 0, 0, 1)).matrix(),
                Transform.rotation(new Quaternion(1e-200, 0, 0, 1e-200)).matrix());
    }

    @Test
    void productsAndAxesOfExtremeMagnitudeStayRotations() {
        Quaternion big = new Quaternion(1e200, 0, 0, 1e200);
        // Two quarter turns about x: a half turn.
        assertSameMatrix(new Quaternion(1, 0, 0, 0).matrix(), big.mul(big).matrix());
        assertSameMatrix(Quaternion.axisAngle(new Vec3(1, 1, 0), 30).matrix(),
                Quaternion.axisAngle(new Vec3(1e300, 1e300, 0), 30).matrix());
        assertSameMatrix(Quaternion.axisAngle(new Vec3(1, 1, 0), 30).matrix(),
                Quaternion.axisAngle(new Vec3(1e-300, 1e-300, 0), 30).matrix());
    }

    @Test
    void aScaleWhoseMatrixWouldOverflowIsRefusedNamingIt() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Transform.scale(Double.MAX_VALUE));
        assertTrue(e.getMessage().contains(String.valueOf(Double.MAX_VALUE)) && e.getMessage().contains("too large"),
                e.getMessage());
        Mat4 m = Transform.rotation(Quaternion.ofZ(45)).withScale(Transform.MAX_SCALE).matrix();
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                assertTrue(Double.isFinite(m.get(r, c)), m.toString());
            }
        }
    }
}
