package dev.trisect.metrics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ImageComparisonTest {
    private static final int GREY = 0xFF808080;

    /** Triangle 1 left of column 13, triangle 2 from there on, nothing in the last row. */
    private static final UvFields.Ids TWO_TRIANGLES = (x, y) -> y == 23 ? 0 : x < 13 ? 1 : 2;

    @Test
    void displacementsAloneEqualThoseOfTheFullComparison() {
        int w = 57;
        int h = 41;
        java.util.Random rnd = new java.util.Random(5);
        double[] ref = new double[3 * w * h];
        double[] test = new double[3 * w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int k = 3 * (y * w + x);
                // Three regions, a hole, a projective map, and a test render off by a little noise.
                double id = (x + y) % 19 == 0 ? 0 : x < 20 ? 1 : y < 25 ? 2 : 3;
                double q = 1 / (1 + 0.03 * x + 0.05 * y);
                ref[k] = (float) (40 * x * q);
                ref[k + 1] = (float) (25 * y * q - 7);
                ref[k + 2] = id;
                test[k] = ref[k] + (float) (0.3 * rnd.nextGaussian());
                test[k + 1] = ref[k + 1] + (float) (0.3 * rnd.nextGaussian());
                test[k + 2] = rnd.nextInt(50) == 0 ? 9 : id;
            }
        }
        int[] argb = new int[w * h];
        float[] full = new float[w * h];
        float[] alone = new float[w * h];
        ImageComparison.compare(w, h, argb, test, argb, ref, full);
        ImageComparison.displacements(w, h, test, ref, alone);
        org.junit.jupiter.api.Assertions.assertArrayEquals(full, alone);
        long defined = 0;
        for (float d : alone) {
            defined += Float.isNaN(d) ? 0 : 1;
        }
        org.junit.jupiter.api.Assertions.assertTrue(defined > w * h / 2, "most pixels have a displacement");
    }

    @Test
    void identicalRendersHaveNoError() {
        int w = 32;
        int h = 24;
        UvFields.Map map = UvFields.affine(2, 0.5, 3, -0.3, 1.7, -10);
        double[] uv = UvFields.buffer(w, h, TWO_TRIANGLES, map, 0, 0);
        int[] argb = new int[w * h];
        for (int i = 0; i < argb.length; i++) {
            argb[i] = 0xFF000000 | (i * 0x9E3779B1) >>> 8;
        }

        Comparison c = ImageComparison.compare(w, h, argb, uv.clone(), argb.clone(), uv);

        assertEquals(w * (h - 1), c.comparedPixels());
        assertEquals(0, c.otherPixels());
        assertEquals(0, c.maxTexelError());
        assertEquals(0, c.p99TexelError());
        assertEquals(0, c.meanTexelError());
        assertEquals(w * (h - 1), c.displacementPixels());
        assertEquals(0, c.maxDisplacement());
        assertEquals(0, c.p99Displacement());
        assertEquals(0, c.meanDisplacement());
        assertEquals(0, c.texelDifferShare());
        assertEquals(0, c.colourRmse());
        assertEquals(Double.POSITIVE_INFINITY, c.psnrDb());
        assertTrue(c.toJson().endsWith("\"psnr_db\":null}"), c.toJson());
    }

    @ParameterizedTest
    @CsvSource({"0.25, 0", "0, -0.3", "0.1, 0.2", "-0.37, 0.05", "1.5, -2.25"})
    void affineReferenceShiftedOnScreenGivesThatDisplacement(double dx, double dy) {
        int w = 32;
        int h = 24;
        // Two triangles with different maps: differences must not reach across the shared edge.
        UvFields.Map left = UvFields.affine(2, 0.5, 0, -0.3, 1.7, 0);
        UvFields.Map right = UvFields.affine(-1.2, 0.4, 50, 0.9, 2.2, -7);
        // Each pixel keeps its own triangle's map, also where the shift crosses the shared edge.
        double[] reference = new double[3 * w * h];
        double[] test = new double[3 * w * h];
        double[] st = new double[2];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int id = TWO_TRIANGLES.at(x, y);
                if (id != 0) {
                    UvFields.Map m = id == 1 ? left : right;
                    m.at(x + 0.5, y + 0.5, st);
                    UvFields.set(reference, w, x, y, st[0], st[1], id);
                    m.at(x + 0.5 + dx, y + 0.5 + dy, st);
                    UvFields.set(test, w, x, y, st[0], st[1], id);
                }
            }
        }
        float[] displacement = new float[w * h];
        int[] argb = UvFields.solid(w, h, GREY);

        Comparison c = ImageComparison.compare(w, h, argb, test, argb, reference, displacement);

        double expected = Math.hypot(dx, dy);
        int covered = w * (h - 1);
        assertEquals(covered, c.comparedPixels());
        assertEquals(covered, c.displacementPixels());
        assertEquals(expected, c.maxDisplacement(), 1e-4);
        assertEquals(expected, c.p99Displacement(), 1e-4);
        assertEquals(expected, c.meanDisplacement(), 1e-4);
        for (int i = 0; i < covered; i++) {
            assertEquals(expected, displacement[i], 1e-4, "pixel " + i);
        }
        for (int i = covered; i < w * h; i++) {
            assertTrue(Float.isNaN(displacement[i]), "uncovered pixel " + i);
        }
        // Texel error is |J (dx, dy)| with each triangle's own J.
        double leftError = Math.hypot(2 * dx + 0.5 * dy, -0.3 * dx + 1.7 * dy);
        double rightError = Math.hypot(-1.2 * dx + 0.4 * dy, 0.9 * dx + 2.2 * dy);
        assertEquals(Math.max(leftError, rightError), c.maxTexelError(), 1e-4);
        double leftShare = 13.0 / w;
        assertEquals(leftShare * leftError + (1 - leftShare) * rightError, c.meanTexelError(), 1e-4);
    }

    @Test
    void affineCaseWithOneTriangle() {
        int w = 20;
        int h = 16;
        double dx = 0.3;
        double dy = -0.4;
        UvFields.Map map = UvFields.affine(2, 0.5, 0, -0.3, 1.7, 0);
        double[] reference = UvFields.oneTriangle(w, h, map, 0, 0);
        double[] test = UvFields.oneTriangle(w, h, map, dx, dy);
        int[] argb = UvFields.solid(w, h, GREY);

        Comparison c = ImageComparison.compare(w, h, argb, test, argb, reference);

        assertEquals(0.5, c.maxDisplacement(), 1e-4);
        assertEquals(0.5, c.meanDisplacement(), 1e-4);
        assertEquals(Math.hypot(2 * dx + 0.5 * dy, -0.3 * dx + 1.7 * dy), c.p99TexelError(), 1e-4);
    }

    @Test
    void firstOrderEstimateIsCloseForSmallShiftsOfAPerspectiveMap() {
        int w = 64;
        int h = 48;
        // A projective map, as perspective-correct texturing produces.
        UvFields.Map map = (x, y, out) -> {
            double q = 1 + 0.012 * x + 0.02 * y;
            out[0] = (3 * x + 0.2 * y + 5) / q;
            out[1] = (-0.4 * x + 2.5 * y + 1) / q;
        };
        double dx = 0.02;
        double dy = -0.01;
        double[] reference = UvFields.oneTriangle(w, h, map, 0, 0);
        double[] test = UvFields.oneTriangle(w, h, map, dx, dy);
        int[] argb = UvFields.solid(w, h, GREY);

        Comparison c = ImageComparison.compare(w, h, argb, test, argb, reference);

        double expected = Math.hypot(dx, dy);
        assertEquals(w * h, c.displacementPixels());
        assertEquals(expected, c.meanDisplacement(), expected * 0.01);
        assertEquals(expected, c.maxDisplacement(), expected * 0.05);
    }

    @Test
    void pixelsNotCoveredByTheSameIdAreExcludedAndCounted() {
        int w = 5;
        int h = 2;
        int[] refIds = {1, 1, 1, 0, 2, 1, 1, 0, 0, 3};
        int[] testIds = {1, 1, 1, 1, 2, 1, 1, 1, 0, 4};
        double[] reference = new double[3 * w * h];
        double[] test = new double[3 * w * h];
        for (int i = 0; i < w * h; i++) {
            int x = i % w;
            int y = i / w;
            if (refIds[i] != 0) {
                UvFields.set(reference, w, x, y, x + 0.5, y + 0.5, refIds[i]);
            }
            if (testIds[i] != 0) {
                // Far off wherever the pixel must not be compared.
                double off = refIds[i] == testIds[i] ? 0 : 1000;
                UvFields.set(test, w, x, y, x + 0.5 + off, y + 0.5, testIds[i]);
            }
        }
        UvFields.set(test, w, 1, 1, 1.5 + 0.25, 1.5, 1);
        float[] displacement = new float[w * h];
        int[] argb = UvFields.solid(w, h, GREY);

        Comparison c = ImageComparison.compare(w, h, argb, test, argb, reference, displacement);

        assertEquals(6, c.comparedPixels());
        assertEquals(3, c.otherPixels()); // test only twice, ids 3 and 4 once
        assertEquals(0.25, c.maxTexelError());
        assertEquals(0.25 / 6, c.meanTexelError(), 1e-9);
        // No Jacobian at (4, 0), a triangle of one pixel, nor at (2, 0), one pixel high in its column.
        assertEquals(4, c.displacementPixels());
        assertEquals(0.25, c.maxDisplacement(), 1e-6);
        for (int i : new int[] {2, 3, 4, 7, 8, 9}) {
            assertTrue(Float.isNaN(displacement[i]), "pixel " + i);
        }
        assertEquals(0.25, displacement[6], 1e-6);
    }

    @Test
    void nonFiniteTexelCoordinatesCountAsOther() {
        int w = 3;
        int h = 1;
        double[] reference = UvFields.oneTriangle(w, h, UvFields.IDENTITY, 0, 0);
        double[] test = reference.clone();
        test[3] = Float.NaN;
        reference[6] = Float.POSITIVE_INFINITY;
        int[] argb = UvFields.solid(w, h, GREY);

        Comparison c = ImageComparison.compare(w, h, argb, test, argb, reference);

        assertEquals(1, c.comparedPixels());
        assertEquals(2, c.otherPixels());
        assertEquals(0, c.maxTexelError());
    }

    @Test
    void p99AndMeanOfAKnownDistribution() {
        int w = 40;
        int h = 25;
        // Identity Jacobian, so each pixel's displacement equals its texel error: a permutation of 1..1000.
        double[] reference = UvFields.oneTriangle(w, h, UvFields.IDENTITY, 0, 0);
        double[] test = reference.clone();
        for (int i = 0; i < w * h; i++) {
            test[3 * i] += (i * 357) % 1000 + 1;
        }
        int[] argb = UvFields.solid(w, h, GREY);

        Comparison c = ImageComparison.compare(w, h, argb, test, argb, reference);

        assertEquals(1000, c.maxTexelError());
        assertEquals(990, c.p99TexelError());
        assertEquals(500.5, c.meanTexelError(), 1e-9);
        assertEquals(1000, c.displacementPixels());
        assertEquals(1000, c.maxDisplacement(), 1e-3);
        assertEquals(990, c.p99Displacement(), 1e-3);
        assertEquals(500.5, c.meanDisplacement(), 1e-3);
        assertEquals(1.0, c.texelDifferShare());
    }

    @Test
    void texelDifferShareUsesFloorNotTruncation() {
        double[][] cases = {
            // s ref, t ref, s test, t test, whether the sampled texel differs
            {0.2, 0.2, 0.7, 0.2, 0},
            {0.2, 0.2, -0.2, 0.2, 1}, // floor -1 vs 0: truncation would call these equal
            {5.9, 3.0, 6.1, 3.0, 1},
            {1.5, 2.5, 1.5, 2.9, 0},
            {1.5, -0.5, 1.5, -0.9, 0},
            {1.5, -0.5, 1.5, 0.1, 1},
            {7.0, 7.0, 7.0, 7.0, 0},
            {7.999, 1.0, 7.0, 1.0, 0},
            {100.5, 4.5, 100.5, 4.5, 0},
            {3.0, 3.0, 2.99, 3.0, 1},
            {3e9, 0.5, 3e9 + 256, 0.5, 1}, // beyond int range: adjacent floats, different texels
            {-3e9, 0.5, -3e9, 0.5, 0},
        };
        int w = cases.length;
        double[] reference = new double[3 * w];
        double[] test = new double[3 * w];
        for (int x = 0; x < w; x++) {
            UvFields.set(reference, w, x, 0, cases[x][0], cases[x][1], 1);
            UvFields.set(test, w, x, 0, cases[x][2], cases[x][3], 1);
        }
        int[] argb = UvFields.solid(w, 1, GREY);

        Comparison c = ImageComparison.compare(w, 1, argb, test, argb, reference);

        assertEquals(12, c.comparedPixels());
        assertEquals(5 / 12.0, c.texelDifferShare(), 1e-12);
    }

    @Test
    void colourRmseAndPsnrByHand() {
        int[] test = {0xFF0A141E, 0x00FFFFFF};
        int[] reference = {0xFF0D101E, 0xFFFFFFFF}; // differences 3, -4, 0; alpha ignored
        double[] nothing = new double[6];

        Comparison c = ImageComparison.compare(2, 1, test, nothing, reference, nothing.clone());

        double rmse = Math.sqrt(25 / 6.0);
        assertEquals(rmse, c.colourRmse(), 1e-12);
        assertEquals(20 * Math.log10(255 / rmse), c.psnrDb(), 1e-9);
        assertEquals(0, c.comparedPixels());
        assertEquals(0, c.otherPixels());
        assertTrue(Double.isNaN(c.meanTexelError()));
        assertTrue(Double.isNaN(c.texelDifferShare()));
    }

    @Test
    void displacementIsUndefinedWithoutANonSingularJacobian() {
        int w = 8;
        int h = 3;
        int[] argb = UvFields.solid(w, h, GREY);
        // One pixel high: no neighbour of the same id vertically.
        UvFields.Ids row = (x, y) -> y == 1 ? 1 : 0;
        UvFields.Map regular = UvFields.affine(2, 0.5, 0, -0.3, 1.7, 0);
        Comparison thin = ImageComparison.compare(w, h, argb, UvFields.buffer(w, h, row, regular, 0.1, 0),
                argb, UvFields.buffer(w, h, row, regular, 0, 0));
        // Texture constant along the screen direction (2, -1): singular Jacobian.
        UvFields.Map singular = UvFields.affine(2, 4, 0, 1, 2, 0);
        float[] displacement = new float[w * h];
        Comparison flat = ImageComparison.compare(w, h, argb, UvFields.oneTriangle(w, h, singular, 0.1, 0),
                argb, UvFields.oneTriangle(w, h, singular, 0, 0), displacement);

        for (Comparison c : new Comparison[] {thin, flat}) {
            assertTrue(c.comparedPixels() > 0);
            assertTrue(c.maxTexelError() > 0.1);
            assertEquals(0, c.displacementPixels());
            assertTrue(Double.isNaN(c.maxDisplacement()));
            assertTrue(Double.isNaN(c.p99Displacement()));
            assertTrue(Double.isNaN(c.meanDisplacement()));
            assertTrue(c.toJson().contains("\"max_displacement_estimate\":null,"), c.toJson());
        }
        for (float d : displacement) {
            assertTrue(Float.isNaN(d));
        }
    }

    @Test
    void jsonIsOneLineWithSnakeCaseKeysAndNullForNonFinite() {
        Comparison c = new Comparison(4, 3, 10, 2, 1.5, 1.25, 0.5, Double.NaN, Double.NaN, Double.NaN,
                0, 3, true, 0.25, 2.5E-4, Double.POSITIVE_INFINITY);

        assertEquals("{\"width\":4,\"height\":3,\"compared_pixels\":10,\"other_pixels\":2,"
                + "\"max_texel_error\":1.5,\"p99_texel_error\":1.25,\"mean_texel_error\":0.5,"
                + "\"max_displacement\":null,\"p99_displacement\":null,\"mean_displacement\":null,"
                + "\"displacement_pixels\":0,\"degenerate_uv_pixels\":3,\"texel_differ_share\":0.25,"
                + "\"colour_rmse\":2.5E-4,\"psnr_db\":null}", c.toJson());
    }

    @Test
    void anEstimatedDisplacementIsLabelledAsOneInJson() {
        Comparison c = new Comparison(4, 3, 10, 2, 1.5, 1.25, 0.5, 2.5, 2, 1,
                7, 0, false, 0.25, 2.5E-4, 40);

        assertEquals("{\"width\":4,\"height\":3,\"compared_pixels\":10,\"other_pixels\":2,"
                + "\"max_texel_error\":1.5,\"p99_texel_error\":1.25,\"mean_texel_error\":0.5,"
                + "\"max_displacement_estimate\":2.5,\"p99_displacement_estimate\":2.0,"
                + "\"mean_displacement_estimate\":1.0,\"displacement_estimate_pixels\":7,"
                + "\"texel_differ_share\":0.25,\"colour_rmse\":2.5E-4,\"psnr_db\":40.0}", c.toJson());
    }

    @Test
    void mismatchedSizesAreRejected() {
        int[] argb = new int[4];
        double[] uv = new double[12];
        assertThrows(IllegalArgumentException.class,
                () -> ImageComparison.compare(2, 2, argb, new double[9], argb, uv));
        assertThrows(IllegalArgumentException.class,
                () -> ImageComparison.compare(2, 2, new int[3], uv, argb, uv));
        assertThrows(IllegalArgumentException.class,
                () -> ImageComparison.compare(2, 2, argb, uv, argb, uv, new float[3]));
        assertThrows(IllegalArgumentException.class,
                () -> ImageComparison.compare(0, 2, new int[0], new double[0], new int[0], new double[0]));
    }
}
