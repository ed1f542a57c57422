package dev.trisect.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** {@link Mat4#normalMatrix()}: the inverse transpose of a model matrix's 3x3, applied by {@link Mat4#transformDirection}. */
class NormalMatrixTest {

    private static Vec3 direction(Mat4 m, Vec3 d) {
        double[] out = new double[3];
        m.transformDirection(d.x(), d.y(), d.z(), out, 0);
        return new Vec3(out[0], out[1], out[2]);
    }

    private static Transform random(Random r) {
        Quaternion q = Quaternion.ofY(360 * r.nextDouble()).mul(Quaternion.ofX(360 * r.nextDouble()));
        Vec3 scale = new Vec3(sign(r) * (0.1 + 5 * r.nextDouble()), sign(r) * (0.1 + 5 * r.nextDouble()),
                sign(r) * (0.1 + 5 * r.nextDouble()));
        return new Transform(new Vec3(r.nextGaussian() * 10, r.nextGaussian() * 10, r.nextGaussian() * 10), q, scale);
    }

    private static double sign(Random r) {
        return r.nextInt(4) == 0 ? -1 : 1;
    }

    /** N^T A = I for the 3x3 A of random models (rotation, non-uniform and mirroring scale, translation). */
    @Test
    void isTheInverseTransposeOfTheUpperLeft3x3() {
        Random r = new Random(27);
        for (int i = 0; i < 1000; i++) {
            Mat4 a = random(r).matrix();
            Mat4 n = a.normalMatrix();
            for (int row = 0; row < 3; row++) {
                for (int col = 0; col < 3; col++) {
                    double s = 0;
                    for (int k = 0; k < 3; k++) {
                        s += n.get(k, row) * a.get(k, col);
                    }
                    assertEquals(row == col ? 1 : 0, s, 1e-12, "model " + i + " (" + row + ", " + col + ")");
                }
                assertEquals(0, n.get(row, 3), "no translation");
                assertEquals(0, n.get(3, row));
            }
            assertEquals(1, n.get(3, 3));
        }
    }

    /**
     * The reason for it: a surface's normal carried by the normal matrix stays perpendicular to the
     * surface's tangents carried by the model matrix, under non-uniform scale too; the model matrix
     * itself tilts it away.
     */
    @Test
    void keepsNormalsPerpendicularUnderNonUniformScale() {
        Random r = new Random(3);
        for (int i = 0; i < 1000; i++) {
            Mat4 a = random(r).matrix();
            Vec3 normal = new Vec3(r.nextGaussian(), r.nextGaussian(), r.nextGaussian()).normalize();
            Vec3 t1 = normal.cross(new Vec3(r.nextGaussian(), r.nextGaussian(), r.nextGaussian())).normalize();
            Vec3 t2 = normal.cross(t1);
            Vec3 n = direction(a.normalMatrix(), normal).normalize();
            assertEquals(0, n.dot(direction(a, t1).normalize()), 1e-12, "model " + i);
            assertEquals(0, n.dot(direction(a, t2).normalize()), 1e-12, "model " + i);
        }
        Mat4 squash = Transform.IDENTITY.withScale(new Vec3(4, 1, 1)).matrix();
        Vec3 diagonal = new Vec3(1, 1, 0).normalize();
        Vec3 tangent = direction(squash, new Vec3(1, -1, 0));
        assertTrue(Math.abs(direction(squash, diagonal).normalize().dot(tangent.normalize())) > 0.8,
                "the model matrix itself tilts the normal");
        assertEquals(0, direction(squash.normalMatrix(), diagonal).dot(tangent), 1e-15);
    }

    @Test
    void isTheRotationItselfForARotationAndIgnoresTranslation() {
        Mat4 rotation = Transform.rotation(Quaternion.ofY(30).mul(Quaternion.ofX(-70)))
                .withTranslation(5, -3, 100).matrix();
        Mat4 n = rotation.normalMatrix();
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 3; col++) {
                assertEquals(rotation.get(row, col), n.get(row, col), 1e-15);
            }
        }
        assertEquals(new Vec3(2, -4, 8), direction(Transform.translation(1, 2, 3).matrix(), new Vec3(2, -4, 8)));
    }

    @Test
    void aSingularMatrixHasNone() {
        Mat4 flat = Mat4.ofRows(1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, flat::normalMatrix);
        assertTrue(e.getMessage().contains("singular"), e.getMessage());
        Mat4 nan = Mat4.ofRows(Double.NaN, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
        assertThrows(IllegalArgumentException.class, nan::normalMatrix);
    }
}
