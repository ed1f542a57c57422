package dev.trisect.light;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** The per-vertex equation on values computed by hand from OpenGL 2.1, section 2.14.1. */
class LightingEquationTest {
    private static final double[] WHITE = {1, 1, 1, 1, 1, 1};
    private static final double[] NO = {0, 0, 0};
    private static final float EPS = 1e-6f;

    private static float[] light(Lights lights, double[] position, double[] normal, double[] material) {
        float[] out = new float[4];
        LightingEquation.colour(lights, position[0], position[1], position[2], normal[0], normal[1], normal[2],
                material, 0, out, 1);
        return new float[] {out[1], out[2], out[3]};
    }

    @Test
    void ambientAloneIsSceneAmbientTimesMaterialAmbient() {
        Lights l = Lights.builder().ambient(0.2, 0.3, 0.4).build();
        float[] c = light(l, new double[3], new double[] {0, 1, 0}, new double[] {1, 0.5, 0.25, 9, 9, 9});
        assertArrayEquals(new float[] {0.2f, 0.15f, 0.1f}, c, EPS);
    }

    @Test
    void directionalLightFollowsLambertWithTheNormalNormalised() {
        // Towards (0, 0, 2) is (0, 0, 1); the normal (0, 3 sin 60°, 3 cos 60°) normalises to N·L = 0.5.
        Lights l = Lights.builder().directional(0, 0, 2, NO, new double[] {1, 0.5, 0.25}).build();
        double s = Math.sin(Math.toRadians(60));
        float[] c = light(l, new double[] {5, 6, 7}, new double[] {0, 3 * s, 1.5}, new double[] {1, 1, 1, 0.8, 0.8, 1});
        assertArrayEquals(new float[] {0.4f, 0.2f, 0.125f}, c, EPS);
    }

    @Test
    void faceAwayFromTheLightGetsNoDiffuseButStillItsAmbient() {
        Lights l = Lights.builder().ambient(0.1, 0.1, 0.1)
                .directional(0, 1, 0, new double[] {0.05, 0, 0}, new double[] {1, 1, 1}).build();
        float[] c = light(l, new double[3], new double[] {0, -1, 0}, WHITE);
        assertArrayEquals(new float[] {0.15f, 0.1f, 0.1f}, c, EPS);
    }

    @Test
    void pointLightIsAttenuatedByDistance() {
        // Light at (0, 0, 3), vertex at the origin facing it: d = 3, att = 1 / (1 + 0.2·3 + 0.05·9) = 1 / 2.05.
        Lights l = Lights.builder().point(0, 0, 3, new double[] {0.5, 0, 0}, new double[] {1, 0.5, 0}, 1, 0.2, 0.05)
                .build();
        float[] c = light(l, new double[3], new double[] {0, 0, 1}, WHITE);
        double att = 1 / 2.05;
        assertArrayEquals(new float[] {(float) (att * 1.5), (float) (att * 0.5), 0}, c, EPS);
        // At 45° to the normal and the same distance: N·L = cos 45°.
        double h = 3 / Math.sqrt(2);
        float[] oblique = light(l, new double[] {h, 0, 3 - h}, new double[] {0, 0, 1}, WHITE);
        assertEquals((float) (att * (0.5 + Math.sqrt(0.5))), oblique[0], EPS);
    }

    @Test
    void eachChannelIsClampedToOne() {
        Lights l = Lights.builder().ambient(0.5, 0.5, 0.5).directional(0, 1, 0, NO, new double[] {1, 0.2, 0}).build();
        float[] c = light(l, new double[3], new double[] {0, 1, 0}, WHITE);
        assertArrayEquals(new float[] {1, 0.7f, 0.5f}, c, EPS);
    }

    @Test
    void eightLightsSum() {
        Lights.Builder b = Lights.builder();
        for (int i = 0; i < 4; i++) {
            b.directional(0, 1, 0, NO, new double[] {0.05, 0.05, 0.05});
            b.point(0, 2, 0, NO, new double[] {0.1, 0.1, 0.1}, 0, 0, 1);
        }
        Lights l = b.build();
        assertEquals(4, l.directionalCount());
        assertEquals(4, l.pointCount());
        // 4 · 0.05 + 4 · 0.1 / 4 = 0.3
        float[] c = light(l, new double[3], new double[] {0, 1, 0}, WHITE);
        assertArrayEquals(new float[] {0.3f, 0.3f, 0.3f}, c, EPS);
    }

    @Test
    void zeroNormalGetsAmbientOnly() {
        Lights l = Lights.builder().ambient(0.25, 0.25, 0.25).directional(0, 1, 0, NO, new double[] {1, 1, 1}).build();
        assertArrayEquals(new float[] {0.25f, 0.25f, 0.25f}, light(l, new double[3], new double[3], WHITE), EPS);
    }

    @Test
    void badLightsAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> Lights.builder().directional(0, 0, 0, NO, NO));
        assertThrows(IllegalArgumentException.class, () -> Lights.builder().point(0, 0, 0, NO, NO, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> Lights.builder().point(0, 0, 0, NO, NO, -1, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> Lights.builder().ambient(Double.NaN, 0, 0));
    }
}
