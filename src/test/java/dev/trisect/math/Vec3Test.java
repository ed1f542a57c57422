package dev.trisect.math;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

class Vec3Test {
    @Test
    void directionsOfAnyFiniteMagnitudeNormaliseToUnitLength() {
        for (double m : new double[] {1e300, 1e200, 1e155, 1e-155, 1e-200, 1e-300, Double.MIN_VALUE,
            Double.MAX_VALUE}) {
            assertEquals(new Vec3(0, 1, 0), new Vec3(0, m, 0).normalize(), "up scaled by " + m);
            if (m == Double.MIN_VALUE) {
                continue; // 0.6 and 0.8 of the smallest double round to the same value
            }
            Vec3 d = new Vec3(0.6 * m, 0, -0.8 * m).normalize();
            assertEquals(1, d.length(), 1e-15, "length for " + m);
            assertEquals(0.6, d.x(), 1e-12);
            assertEquals(-0.8, d.z(), 1e-12);
        }
        assertEquals(Vec3.ZERO, Vec3.ZERO.normalize());
    }

    @Test
    void ordinaryVectorsNormaliseBitForBitAsThePlainFormula() {
        Random r = new Random(7);
        for (int i = 0; i < 10_000; i++) {
            double scale = Math.pow(10, r.nextInt(200) - 100);
            Vec3 v = new Vec3(r.nextGaussian() * scale, r.nextGaussian() * scale, r.nextGaussian() * scale);
            double len = Math.sqrt(v.x() * v.x() + v.y() * v.y() + v.z() * v.z());
            assertEquals(v.scale(1 / len), v.normalize(), v.toString());
        }
    }

    @Test
    void lookAtTakesOnlyTheDirectionOfAnExtremeUp() {
        Vec3 eye = new Vec3(1, 2, 3);
        Mat4 unit = Mat4.lookAt(eye, Vec3.ZERO, new Vec3(0, 1, 0));
        for (double m : new double[] {1e300, 1e-160, 1e-300}) {
            Mat4 scaled = Mat4.lookAt(eye, Vec3.ZERO, new Vec3(0, m, 0));
            for (int k = 0; k < 16; k++) {
                assertEquals(unit.get(k / 4, k % 4), scaled.get(k / 4, k % 4), "up 0," + m + ",0 entry " + k);
            }
        }
    }
}
