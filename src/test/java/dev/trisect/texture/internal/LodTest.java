package dev.trisect.texture.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The level of detail of OpenGL 4.6 §8.14.1 for constructed derivatives, and the level selection. */
class LodTest {
    @Test
    void lambdaIsLog2OfTheLongerDerivativeVector() {
        assertEquals(1.0, Lod.lambda(2, 0, 0, 2), 1e-12);
        // rho along x is 4, along y 1: the larger counts.
        assertEquals(2.0, Lod.lambda(4, 0, 0, 1), 1e-12);
        assertEquals(2.0, Lod.lambda(0, 1, 0, -4), 1e-12);
        // Lengths, not components: (3, 4) has length 5.
        assertEquals(Math.log(5) / Math.log(2), Lod.lambda(3, 4, 0, 0), 1e-12);
        assertEquals(-1.0, Lod.lambda(0.5, 0, 0, 0.25), 1e-12);
    }

    @Test
    void perspectiveDerivativesMatchFiniteDifferences() {
        // S, T, Q planes of a made-up perspective map; s = S / Q.
        double sB = 3, sDx = 0.7, sDy = -0.2;
        double tB = -1, tDx = 0.1, tDy = 0.9;
        double qB = 0.5, qDx = 0.01, qDy = -0.03;
        double x = 5.5;
        double y = 3.5;
        double h = 1e-5;
        java.util.function.BiFunction<Double, Double, double[]> st = (px, py) -> {
            double q = qB + qDx * px + qDy * py;
            return new double[] {(sB + sDx * px + sDy * py) / q, (tB + tDx * px + tDy * py) / q};
        };
        double[] c = st.apply(x, y);
        double[] ex = st.apply(x + h, y);
        double[] ey = st.apply(x, y + h);
        double expected = Lod.lambda((ex[0] - c[0]) / h, (ex[1] - c[1]) / h, (ey[0] - c[0]) / h, (ey[1] - c[1]) / h);
        double r = 1 / (qB + qDx * x + qDy * y);
        assertEquals(expected, Lod.lambdaPerspective(c[0], c[1], r, sDx, sDy, tDx, tDy, qDx, qDy), 1e-4);
    }

    @Test
    void constantDepthGivesThePerPieceLevel() {
        // With Q constant (an affine map), the per-pixel formula is the per-piece one at every pixel.
        double sDx = 1.7, sDy = 0.3, tDx = -0.4, tDy = 2.2;
        double piece = Lod.lambda(sDx, tDx, sDy, tDy);
        for (double s : new double[] {0, 13.2, -400}) {
            assertEquals(piece, Lod.lambdaPerspective(s, s / 3, 1, sDx, sDy, tDx, tDy, 0, 0));
        }
    }

    @Test
    void selectionSplitsLambdaIntoLevelAndWeight() {
        assertEquals(0, Lod.select(-3, 8), "magnification: level 0 alone");
        assertEquals(0, Lod.select(0, 8), "lambda = 0 is still magnification (c = 0)");
        assertEquals(0, Lod.select(Double.NaN, 8));
        assertEquals(0, Lod.select(Double.NEGATIVE_INFINITY, 8));
        int half = Lod.select(1.5, 8);
        assertEquals(1, Lod.level(half));
        assertEquals(128, Lod.weight(half));
        int small = Lod.select(0.25, 8);
        assertEquals(0, Lod.level(small));
        assertEquals(64, Lod.weight(small));
        int top = Lod.select(9.7, 8);
        assertEquals(8, Lod.level(top), "beyond the last level: the last level alone");
        assertEquals(0, Lod.weight(top));
        assertEquals(8, Lod.level(Lod.select(Double.POSITIVE_INFINITY, 8)));
        assertEquals(0, Lod.select(5, 0), "a 1x1 texture has one level");
    }

    @Test
    void fixedPointSelectionSplitsAsTheDoubleOne() {
        // select(fixed(lambda)) is select(lambda): floor(256 lambda) = 256 level + weight.
        java.util.Random rnd = new java.util.Random(12);
        for (int maxLevel : new int[] {0, 1, 9, 14}) {
            for (int i = 0; i < 100_000; i++) {
                double lambda = rnd.nextDouble() * (maxLevel + 6) - 3;
                assertEquals(Lod.select(lambda, maxLevel), Lod.select(Lod.fixed(lambda, maxLevel), maxLevel),
                        "lambda " + lambda + ", last level " + maxLevel);
            }
            for (double lambda : new double[] {0, 1, 2.5, maxLevel, maxLevel + 1e-9, -1e300, 1e300,
                Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY}) {
                assertEquals(Lod.select(lambda, maxLevel), Lod.select(Lod.fixed(lambda, maxLevel), maxLevel),
                        "lambda " + lambda);
            }
        }
        assertEquals(Lod.NO_LAMBDA, Lod.fixed(Double.NaN, 8));
        assertEquals(-256, Lod.fixed(-7, 8), "clamped below");
        assertEquals(9 * 256, Lod.fixed(40, 8), "clamped above");
    }

    @Test
    void tableLogarithmIsWithinTwoTenMillionths() {
        java.util.Random rnd = new java.util.Random(11);
        for (int i = 0; i < 100_000; i++) {
            double x = Math.pow(2, rnd.nextDouble() * 80 - 40);
            assertEquals(Math.log(x) / Math.log(2), Lod.log2(x), 2e-7, "log2(" + x + ")");
        }
        assertEquals(3.0, Lod.log2(8), 0.0, "powers of two are exact");
        assertEquals(-1.0, Lod.log2(0.5), 0.0);
        assertEquals(Double.NEGATIVE_INFINITY, Lod.log2(0));
    }

    @Test
    void floatBitsLambdaIsTheExactFloorOrOneStepBelow() {
        // fixedOfSquared (float exponent and a 65-entry table) against floor(256 * 0.5 log2) from Math.log:
        // within 5e-5 of log2, so the same step or a neighbouring one, and the same in nearly all cases.
        java.util.Random rnd = new java.util.Random(19);
        int maxLevel = 14;
        int off = 0;
        int n = 200_000;
        for (int i = 0; i < n; i++) {
            double x = Math.pow(2, rnd.nextDouble() * 34 - 3);
            int exact = Math.max(-256, Math.min(256 * (maxLevel + 1), (int) Math.floor(128 * Math.log(x) / Math.log(2))));
            int got = Lod.fixedOfSquared(x, maxLevel);
            assertTrue(Math.abs(got - exact) <= 1, "rho^2 " + x + ": " + got + " vs " + exact);
            if (got != exact) {
                off++;
            }
            assertEquals(Lod.fixed(Lod.lambdaOf(x), maxLevel) >> 1, got >> 1, 1, "rho^2 " + x);
        }
        assertTrue(off < n / 200, off + " of " + n + " one step off");
        // Powers of two are exact: rho = 2^k is lambda k.
        for (int k = -1; k <= 15; k++) {
            assertEquals(256 * k, Lod.fixedOfSquared(Math.pow(4, k), 15), "rho 2^" + k);
        }
        assertEquals(Lod.NO_LAMBDA, Lod.fixedOfSquared(Double.NaN, 8));
        assertEquals(-256, Lod.fixedOfSquared(0, 8), "zero derivatives: clamped below");
        assertEquals(-256, Lod.fixedOfSquared(-0.0, 8));
        assertEquals(-256, Lod.fixedOfSquared(1e-300, 8), "a float underflow");
        assertEquals(-256, Lod.fixedOfSquared(1e-40, 8), "a subnormal float");
        assertEquals(9 * 256, Lod.fixedOfSquared(1e300, 8), "a float overflow: clamped above");
        assertEquals(9 * 256, Lod.fixedOfSquared(Double.POSITIVE_INFINITY, 8));
        assertEquals(-256, Lod.fixedOfSquared(0.01, 8), "lambda -3.3, clamped to -1");
        assertEquals(0, Lod.select(Lod.fixedOfSquared(0.9, 8), 8), "magnification");
    }
}
