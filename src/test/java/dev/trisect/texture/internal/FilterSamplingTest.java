package dev.trisect.texture.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trisect.texture.Texture;
import org.junit.jupiter.api.Test;

/**
 * Bilinear and trilinear sampling against values computed by hand from OpenGL's GL_LINEAR rule with
 * GL_REPEAT (conventions.md, "Texture filtering"): sample at {@code s - 1/2}, four texels wrapped,
 * weighted by the fractions; levels blended by the fraction of lambda.
 */
class FilterSamplingTest {
    private static int grey(int v) {
        return 0xFF000000 | v << 16 | v << 8 | v;
    }

    /** Bilinear sample of a texture's level 0 at texel coordinates (s, t). */
    private static int sample(Texture tex, double s, double t) {
        return Sampler.bilinear(tex.argb(), tex.width(), tex.height(), Sampler.position(s), Sampler.position(t));
    }

    /** A 4x2 texture: bottom row (image row 1) 0, 40, 80, 120; top row (image row 0) 200, 210, 220, 230. */
    private static Texture fourByTwo() {
        return new Texture("4x2", 4, 2, new int[] {
            grey(200), grey(210), grey(220), grey(230),
            grey(0), grey(40), grey(80), grey(120)});
    }

    @Test
    void texelCentresGiveTheTexelItself() {
        Texture tex = fourByTwo();
        assertEquals(grey(0), sample(tex, 0.5, 0.5));
        assertEquals(grey(80), sample(tex, 2.5, 0.5));
        assertEquals(grey(230), sample(tex, 3.5, 1.5));
    }

    @Test
    void betweenCentresTheWeightsAreTheFractions() {
        Texture tex = fourByTwo();
        // s = 1.0: halfway between columns 0 and 1 on the bottom row: (0 + 40) / 2.
        assertEquals(grey(20), sample(tex, 1.0, 0.5));
        // s = 1.75: column 1 with 3/4, column 2... no: s - 1/2 = 1.25, so 3/4 of column 1, 1/4 of column 2.
        assertEquals(grey(50), sample(tex, 1.75, 0.5));
        // t = 1.0: halfway between the rows: (40 + 210) / 2 = 125 at column 1's centre.
        assertEquals(grey(125), sample(tex, 1.5, 1.0));
        // Both: (0 + 40 + 200 + 210) / 4 = 112.5, rounded to nearest.
        assertEquals(grey(113), sample(tex, 1.0, 1.0));
    }

    @Test
    void edgesWrapAround() {
        Texture tex = fourByTwo();
        // s = 0: halfway between column 3 (wrapped from -1) and column 0: (120 + 0) / 2.
        assertEquals(grey(60), sample(tex, 0.0, 0.5));
        // One period further either way is the same point.
        assertEquals(grey(60), sample(tex, 4.0, 0.5));
        assertEquals(grey(60), sample(tex, -4000.0, 0.5));
        // t = 0: halfway between the bottom row and the top row wrapped from below: (0 + 200) / 2.
        assertEquals(grey(100), sample(tex, 0.5, 0.0));
        assertEquals(grey(100), sample(tex, 0.5, -2.0));
    }

    @Test
    void oddSizesWrapWithoutAPowerOfTwoMask() {
        // 3x1: 30, 60, 90. s = 0.25: s - 1/2 = -0.25, so 1/4 of column -1 (wrapped to 2) and 3/4 of column 0.
        Texture tex = new Texture("3x1", 3, 1, new int[] {grey(30), grey(60), grey(90)});
        assertEquals(grey(45), sample(tex, 0.25, 0.5));
        // s = 3.0: halfway between column 2 and column 3 = 0.
        assertEquals(grey(60), sample(tex, 3.0, 0.5));
        assertEquals(grey(60), sample(tex, -3.0, 7.25));
    }

    @Test
    void aOneByOneLevelIsThatTexelEverywhere() {
        Texture tex = Texture.solid("one", 0xFF123456);
        for (double s : new double[] {0, 0.3, 0.5, -7.9, 1e6}) {
            assertEquals(0xFF123456, sample(tex, s, s * 0.7 - 3));
        }
    }

    @Test
    void channelsAreFilteredSeparatelyAndRounded() {
        // Red 255 and blue 255 blended 1/4 : 3/4 at 1/256 precision.
        Texture tex = new Texture("rb", 2, 1, new int[] {0xFFFF0000, 0xFF0000FF});
        // s - 1/2 = 0.25: 3/4 of column 0 (red), 1/4 of column 1 (blue): 191.25 -> 191, 63.75 -> 64.
        assertEquals(0xFFBF0040, sample(tex, 0.75, 0.5));
    }

    @Test
    void blendIsTheExactWeightedSumRoundedOnce() {
        // Every channel: sum of w_ij c_ij with w = (256 - fx)(256 - fy), fx (256 - fy), (256 - fx) fy, fx fy,
        // plus half, over 65536; extreme texels and weights included (255 everywhere, fractions 0 and 255).
        java.util.Random rnd = new java.util.Random(13);
        int[] extremes = {0, 0xFFFFFFFF, 0x00FFFFFF, 0xFF000000, 0x12345678};
        for (int n = 0; n < 200_000; n++) {
            int[] c = new int[4];
            for (int k = 0; k < 4; k++) {
                c[k] = n % 3 == 0 ? extremes[rnd.nextInt(extremes.length)] : rnd.nextInt();
            }
            int fx = n % 5 == 0 ? 255 * rnd.nextInt(2) : rnd.nextInt(256);
            int fy = n % 7 == 0 ? 255 * rnd.nextInt(2) : rnd.nextInt(256);
            int[] w = {(256 - fx) * (256 - fy), fx * (256 - fy), (256 - fx) * fy, fx * fy};
            int expected = 0xFF000000;
            for (int shift = 0; shift < 24; shift += 8) {
                long sum = 0;
                for (int k = 0; k < 4; k++) {
                    sum += (long) w[k] * (c[k] >>> shift & 0xFF);
                }
                expected |= (int) ((sum + 32768) >> 16) << shift;
            }
            assertEquals(Integer.toHexString(expected), Integer.toHexString(Sampler.blend(c[0], c[1], c[2], c[3], fx, fy)));
        }
    }

    @Test
    void lerpBlendsLevelsByWeight() {
        assertEquals(grey(100), Sampler.lerp(grey(100), grey(200), 0));
        assertEquals(grey(150), Sampler.lerp(grey(100), grey(200), 128));
        assertEquals(grey(125), Sampler.lerp(grey(100), grey(200), 64));
        // 255 * 1/256 = 0.996 rounds to 1.
        assertEquals(0xFF010101, Sampler.lerp(grey(0), grey(255), 1));
    }

    @Test
    void positionIsHalfATexelBackInSixteenthsOfAByte() {
        assertEquals(0, Sampler.position(0.5));
        assertEquals(-128, Sampler.position(0.0));
        assertEquals(256 + 64, Sampler.position(1.75));
        assertEquals(-256 - 64, Sampler.position(-0.75));
    }
}
