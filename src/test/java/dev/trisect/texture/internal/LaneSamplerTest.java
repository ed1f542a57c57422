package dev.trisect.texture.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.texture.MipChain;
import dev.trisect.texture.Texture;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The packed bilinear blend with 8-bit weights and its padded layout (conventions.md, "Texture
 * filtering"): hand-computed values, the rule channel by channel, the bound against the exact blend,
 * wrapping at every edge of odd and power-of-two levels, and 1x1 levels.
 */
class LaneSamplerTest {
    private static int grey(int v) {
        return 0xFF000000 | v << 16 | v << 8 | v;
    }

    /** The blend of four ARGB texels through lanes, as ARGB. */
    private static int blend(int c00, int c10, int c01, int c11, int fx, int fy) {
        return TexelLanes.argb(LaneSampler.blend(TexelLanes.lanes(c00), TexelLanes.lanes(c10), TexelLanes.lanes(c01),
                TexelLanes.lanes(c11), fx, fy));
    }

    /** The rule written out per channel with its four weights (the class comment of LaneSampler). */
    private static int reference(int c00, int c10, int c01, int c11, int fx, int fy) {
        int w11 = (fx * fy + 128) / 256;
        int[] w = {256 - fx - fy + w11, fx - w11, fy - w11, w11};
        int[] c = {c00, c10, c01, c11};
        int out = 0xFF000000;
        for (int shift = 0; shift < 24; shift += 8) {
            int sum = 128;
            for (int k = 0; k < 4; k++) {
                sum += w[k] * (c[k] >>> shift & 0xFF);
            }
            out |= sum / 256 << shift;
        }
        return out;
    }

    @Test
    void handComputedWeightsAndRounding() {
        // Weight 0: the first texel exactly, whatever the others.
        assertEquals(0xFF123456, blend(0xFF123456, 0xFFFFFFFF, 0xFFFFFFFF, 0xFFFFFFFF, 0, 0));
        // 1/256 of a white texel next to black: (255 * 1 + 128) >> 8 = 1.
        assertEquals(grey(1), blend(grey(0), grey(255), grey(0), grey(255), 1, 0));
        // 255/256 of it: (255 * 255 + 128) >> 8 = 254 (254.5 of the exact blend's 254.0 rounds down).
        assertEquals(grey(254), blend(grey(0), grey(255), grey(0), grey(255), 255, 0));
        // And the other way round: 1 * 255 + 128 = 383 -> 1.
        assertEquals(grey(1), blend(grey(255), grey(0), grey(255), grey(0), 255, 0));
        // Halves round up: 0 and 1 half and half is 0.5 -> 1; 127/256 of 1 is 0.496 -> 0.
        assertEquals(grey(1), blend(grey(0), grey(1), grey(0), grey(1), 128, 0));
        assertEquals(grey(0), blend(grey(0), grey(1), grey(0), grey(1), 127, 0));
        // fx = fy = 128: w11 = 64, and all four weights are 64: (10 + 20 + 30 + 41) / 4 = 25.25 -> 25.
        assertEquals(grey(25), blend(grey(10), grey(20), grey(30), grey(41), 128, 128));
        // fx = fy = 255: w11 = (65025 + 128) >> 8 = 254, w10 = w01 = 1, w00 = 0: c00 gets no weight.
        assertEquals(grey(0), blend(grey(255), grey(0), grey(0), grey(0), 255, 255));
        assertEquals(grey((200 + 100 + 254 * 50 + 128) / 256), blend(grey(255), grey(200), grey(100), grey(50), 255, 255));
        // fx = 1, fy = 255: w11 = (255 + 128) >> 8 = 1, w10 = 0, w01 = 254, w00 = 1.
        assertEquals(grey((7 + 254 * 100 + 200 + 128) / 256), blend(grey(7), grey(255), grey(100), grey(200), 1, 255));
        // Channels stay in their lanes: red 255 and blue 255, 1/4 : 3/4 -> 191.25 -> 191 and 63.75 -> 64.
        assertEquals(0xFFBF0040, blend(0xFFFF0000, 0xFF0000FF, 0xFFFF0000, 0xFF0000FF, 64, 0));
        // Alpha is dropped: the result is opaque.
        assertEquals(0xFF808080, blend(0x00808080, 0x00808080, 0x00808080, 0x00808080, 77, 201));
    }

    @Test
    void everyWeightPairFollowsTheRuleAndStaysWithinOneOfTheExactBlend() {
        Random rnd = new Random(21);
        int[] extremes = {0, 0xFFFFFFFF, 0x00FFFFFF, 0xFF000000, 0xFF00FF00, 0xFFFF00FF};
        for (int fx = 0; fx < 256; fx++) {
            for (int fy = 0; fy < 256; fy++) {
                int w11 = (fx * fy + 128) >> 8;
                assertTrue(w11 >= 0 && fx - w11 >= 0 && fy - w11 >= 0 && 256 - fx - fy + w11 >= 0, fx + "," + fy);
                for (int n = 0; n < 4; n++) {
                    int[] c = new int[4];
                    for (int k = 0; k < 4; k++) {
                        c[k] = n == 0 ? extremes[rnd.nextInt(extremes.length)] : rnd.nextInt();
                    }
                    int got = blend(c[0], c[1], c[2], c[3], fx, fy);
                    assertEquals(Integer.toHexString(reference(c[0], c[1], c[2], c[3], fx, fy)), Integer.toHexString(got));
                    int exact = Sampler.blend(c[0], c[1], c[2], c[3], fx, fy);
                    for (int shift = 0; shift < 24; shift += 8) {
                        int d = Math.abs((got >>> shift & 0xFF) - (exact >>> shift & 0xFF));
                        assertTrue(d <= 1, "fx " + fx + " fy " + fy + ": " + Integer.toHexString(got) + " vs exact "
                                + Integer.toHexString(exact));
                    }
                }
            }
        }
    }

    @Test
    void lerpBlendsLevelsByWeight() {
        long a = TexelLanes.lanes(grey(100));
        long b = TexelLanes.lanes(grey(200));
        assertEquals(grey(100), TexelLanes.argb(LaneSampler.lerp(a, b, 0)));
        assertEquals(grey(150), TexelLanes.argb(LaneSampler.lerp(a, b, 128)));
        assertEquals(grey(200), TexelLanes.argb(LaneSampler.lerp(a, b, 256)));
        assertEquals(0xFF010101, TexelLanes.argb(LaneSampler.lerp(TexelLanes.lanes(grey(0)), TexelLanes.lanes(grey(255)), 1)));
        Random rnd = new Random(5);
        for (int n = 0; n < 100_000; n++) {
            int c0 = rnd.nextInt();
            int c1 = rnd.nextInt();
            int w = rnd.nextInt(257);
            assertEquals(Sampler.lerp(c0, c1, w),
                    TexelLanes.argb(LaneSampler.lerp(TexelLanes.lanes(c0), TexelLanes.lanes(c1), w)));
        }
    }

    @Test
    void lanesRoundTripTheColourChannels() {
        Random rnd = new Random(3);
        for (int n = 0; n < 10_000; n++) {
            int c = rnd.nextInt();
            long l = TexelLanes.lanes(c);
            assertEquals(0, l & ~TexelLanes.CHANNELS);
            assertEquals(c | 0xFF000000, TexelLanes.argb(l));
        }
    }

    @Test
    void alphaIsFilteredAsTheColourIsInItsOwnLane() {
        Random rnd = new Random(5);
        for (int n = 0; n < 10_000; n++) {
            int[] c = {rnd.nextInt(), rnd.nextInt(), rnd.nextInt(), rnd.nextInt()};
            int fx = rnd.nextInt(256);
            int fy = rnd.nextInt(256);
            long l = LaneSampler.blend(TexelLanes.lanes(c[0]), TexelLanes.lanes(c[1]), TexelLanes.lanes(c[2]),
                    TexelLanes.lanes(c[3]), fx, fy);
            int rgb = reference(c[0], c[1], c[2], c[3], fx, fy);
            // The rule on each texel's alpha moved into the blue channel gives the alpha.
            int alpha = reference(c[0] >>> 24, c[1] >>> 24, c[2] >>> 24, c[3] >>> 24, fx, fy) & 0xFF;
            assertEquals(rgb, TexelLanes.argb(l), "colour, as without alpha");
            assertEquals(alpha << 24 | rgb & 0xFFFFFF, TexelLanes.argbWithAlpha(l));
            int weight = rnd.nextInt(257);
            long m = LaneSampler.lerp(l, TexelLanes.lanes(c[0]), weight);
            int want = (alpha * (256 - weight) + (c[0] >>> 24) * weight + 128) >> 8;
            assertEquals(want, TexelLanes.argbWithAlpha(m) >>> 24, "the blend of two levels' alphas");
        }
    }

    /** The sample by the rule, from the texture's own texels: wrap each of the four with floorMod. */
    private static int expected(int[] argb, int w, int h, long px, long py) {
        int i0 = (int) Math.floorMod(px >> 8, (long) w);
        int j0 = (int) Math.floorMod(py >> 8, (long) h);
        int i1 = (i0 + 1) % w;
        int j1 = (j0 + 1) % h;
        return reference(argb[(h - 1 - j0) * w + i0], argb[(h - 1 - j0) * w + i1], argb[(h - 1 - j1) * w + i0],
                argb[(h - 1 - j1) * w + i1], (int) px & 255, (int) py & 255);
    }

    private static Texture noise(int w, int h, long seed) {
        Random rnd = new Random(seed);
        int[] px = new int[w * h];
        for (int i = 0; i < px.length; i++) {
            px[i] = rnd.nextInt();
        }
        return new Texture("noise", w, h, px);
    }

    @Test
    void everyLevelWrapsAtEveryEdgeForOddAndPowerOfTwoSizes() {
        int[][] sizes = {{1, 1}, {2, 2}, {3, 5}, {7, 1}, {1, 6}, {16, 8}, {64, 64}, {37, 23}, {300, 200}};
        Random rnd = new Random(17);
        for (int[] size : sizes) {
            Texture tex = noise(size[0], size[1], size[0] * 31L + size[1]);
            MipChain chain = tex.mipChain();
            TexelLanes lanes = TexelLanes.of(chain);
            assertEquals(chain.levels(), lanes.levelCount());
            for (int d = 0; d < chain.levels(); d++) {
                int w = chain.width(d);
                int h = chain.height(d);
                int o = d * TexelLanes.LEVEL_INTS;
                int[] lv = lanes.levels();
                assertEquals(w + 1, lanes.stride(d));
                boolean pot = (w & (w - 1)) == 0 && (h & (h - 1)) == 0;
                // Every texel position of the level and one period around it, with the fractions at 0, 1,
                // 128 and 255 (so every edge's wrap is read), then random far positions.
                for (int j = -h - 1; j <= 2 * h; j++) {
                    for (int i = -w - 1; i <= 2 * w; i++) {
                        for (int f : new int[] {0, 1, 128, 255}) {
                            long px = (long) i * 256 + f;
                            long py = (long) j * 256 + (255 - f);
                            check(chain, lanes, d, px, py, pot, lv, o, w, h);
                        }
                    }
                }
                for (int n = 0; n < 2000; n++) {
                    long px = rnd.nextLong() >> rnd.nextInt(40);
                    long py = rnd.nextLong() >> rnd.nextInt(40);
                    check(chain, lanes, d, px, py, pot, lv, o, w, h);
                }
            }
        }
    }

    private static void check(MipChain chain, TexelLanes lanes, int d, long px, long py, boolean pot, int[] lv, int o,
                              int w, int h) {
        int want = expected(chain.texels(d), w, h, px, py);
        String where = w + "x" + h + " level " + d + " at " + px + "," + py;
        assertEquals(want, TexelLanes.argb(LaneSampler.bilinear(lanes.lanes(), lanes.offset(d), lanes.stride(d), w, h,
                px, py)), where);
        if (pot) {
            assertEquals(w - 1, lv[o + TexelLanes.WIDTH_MASK]);
            assertEquals(h - 1, lv[o + TexelLanes.HEIGHT_MASK]);
            assertEquals(want, TexelLanes.argb(LaneSampler.bilinearPowerOfTwo(lanes.lanes(), lanes.offset(d),
                    lanes.stride(d), w - 1, h - 1, px, py)), where);
        }
    }

    @Test
    void levelsOfAPowerOfTwoChainTakeLevelZeroCoordinatesShifted() {
        // levelPowerOfTwo at floor(256 s) is the level's sample at Sampler.position(s * scale): one floor
        // serves every level. 128x32: levels 128x32 .. 4x1, 2x1, 1x1 (shifts differ once t's side is 1).
        Texture tex = noise(128, 32, 4);
        MipChain chain = tex.mipChain();
        TexelLanes lanes = TexelLanes.of(chain);
        Random rnd = new Random(8);
        for (int n = 0; n < 50_000; n++) {
            double s = (rnd.nextDouble() - 0.5) * 1000;
            double t = (rnd.nextDouble() - 0.5) * 1000;
            long s8 = (long) Math.floor(s * 256);
            long t8 = (long) Math.floor(t * 256);
            for (int d = 0; d < chain.levels(); d++) {
                long want = LaneSampler.bilinear(lanes.lanes(), lanes.offset(d), lanes.stride(d), chain.width(d),
                        chain.height(d), Sampler.position(s * chain.scaleS(d)), Sampler.position(t * chain.scaleT(d)));
                assertEquals(want, LaneSampler.levelPowerOfTwo(lanes.lanes(), lanes.levels(), d, s8, t8),
                        "level " + d + " at " + s + "," + t);
            }
            int selection = Lod.select(rnd.nextDouble() * 9 - 1, chain.maxLevel());
            int d = Lod.level(selection);
            long c = LaneSampler.levelPowerOfTwo(lanes.lanes(), lanes.levels(), d, s8, t8);
            if (Lod.weight(selection) != 0) {
                c = LaneSampler.lerp(c, LaneSampler.levelPowerOfTwo(lanes.lanes(), lanes.levels(), d + 1, s8, t8),
                        Lod.weight(selection));
            }
            assertEquals(TexelLanes.argb(c), LaneSampler.trilinearPowerOfTwo(lanes.lanes(), lanes.levels(), selection,
                    s8, t8));
        }
    }

    @Test
    void aOneByOneLevelIsThatTexelEverywhere() {
        TexelLanes lanes = TexelLanes.of(Texture.solid("one", 0x7F123456).mipChain());
        for (long p : new long[] {0, 1, 255, 256, -1, -257, Long.MAX_VALUE, Long.MIN_VALUE}) {
            assertEquals(0xFF123456, TexelLanes.argb(LaneSampler.bilinearPowerOfTwo(lanes.lanes(), 0, 2, 0, 0, p, -p)));
            assertEquals(0xFF123456, TexelLanes.argb(LaneSampler.bilinear(lanes.lanes(), 0, 2, 1, 1, p, p / 3)));
        }
    }

    @Test
    void lanesAreBuiltOnceAndPaddedWithTheWrappedColumnAndRow() {
        // 2x2: image rows top (0) = a b, bottom (1) = c d. Lanes rows from the bottom: c d c / a b a / c d c.
        int a = 0xFF0000AA;
        int b = 0xFF00BB00;
        int c = 0xFFCC0000;
        int d = 0xFF0D0D0D;
        MipChain chain = new Texture("2x2", 2, 2, new int[] {a, b, c, d}).mipChain();
        TexelLanes lanes = TexelLanes.of(chain);
        long[] l = lanes.lanes();
        int[] want = {c, d, c, a, b, a, c, d, c};
        for (int k = 0; k < 9; k++) {
            assertEquals(TexelLanes.lanes(want[k]), l[k], "long " + k);
        }
        assertEquals(9, lanes.offset(1));
        assertEquals(2, lanes.stride(1));
        assertEquals(9 + 4, l.length);
        assertEquals(1, lanes.levels()[TexelLanes.LEVEL_INTS + TexelLanes.SHIFT_S]);
        assertTrue(TexelLanes.of(chain) == lanes, "built once");
    }
}
