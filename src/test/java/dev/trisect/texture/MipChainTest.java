package dev.trisect.texture;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Mipmap level sizes and contents: the 2x2 box for even sides, the exact box filter for odd ones. */
class MipChainTest {
    private static int grey(int v) {
        return 0xFF000000 | v << 16 | v << 8 | v;
    }

    private static int[] greys(int... v) {
        int[] out = new int[v.length];
        for (int i = 0; i < v.length; i++) {
            out[i] = grey(v[i]);
        }
        return out;
    }

    private static void assertSizes(int w, int h, int... expected) {
        MipChain m = new Texture("t", w, h, new int[w * h]).mipChain();
        assertEquals(expected.length / 2, m.levels(), w + "x" + h);
        for (int d = 0; d < m.levels(); d++) {
            assertEquals(expected[2 * d], m.width(d), "width of level " + d);
            assertEquals(expected[2 * d + 1], m.height(d), "height of level " + d);
            assertEquals(m.width(d) * m.height(d), m.texels(d).length);
        }
    }

    @Test
    void levelsHalveRoundingDownToOneByOne() {
        assertSizes(8, 8, 8, 8, 4, 4, 2, 2, 1, 1);
        assertSizes(5, 3, 5, 3, 2, 1, 1, 1);
        assertSizes(16, 1, 16, 1, 8, 1, 4, 1, 2, 1, 1, 1);
        assertSizes(3, 7, 3, 7, 1, 3, 1, 1);
        assertSizes(1, 1, 1, 1);
    }

    @Test
    void levelZeroIsTheTextureItself() {
        Texture t = new Texture("t", 4, 4, new int[16]);
        assertSame(t.argb(), t.mipChain().texels(0));
    }

    @Test
    void evenSidesAverageTwoByTwoRoundingRowsThenColumns() {
        // 4x2, image rows top then bottom.
        Texture t = new Texture("t", 4, 2, greys(
                10, 20, 100, 101,
                30, 41, 200, 200));
        MipChain m = t.mipChain();
        // Along x: bottom (30 + 41) / 2 = 35.5 -> 36, top (10 + 20) / 2 = 15; along y (36 + 15) / 2 = 25.5
        // -> 26 (Mesa's glGenerateMipmap gives the same; the one-step average 25.25 would be 25).
        // Right: (200 + 200) / 2 = 200, (100 + 101) / 2 = 100.5 -> 101; (200 + 101) / 2 = 150.5 -> 151.
        assertArrayEquals(greys(26, 151), m.texels(1));
        // Level 2, 1x1: (26 + 151) / 2 = 88.5 -> 89, then the 1-high column stays.
        assertArrayEquals(greys(89), m.texels(2));
    }

    @Test
    void oddSidesUseTheExactBoxFilter() {
        // 5 -> 2: n = 2, texel 0 = (2 a + 2 b + 1 c) / 5, texel 1 = (1 c + 2 d + 2 e) / 5.
        Texture t = new Texture("t", 5, 1, greys(0, 51, 100, 150, 200));
        // (0 + 102 + 100) / 5 = 40.4 -> 40; (100 + 300 + 400) / 5 = 160.
        assertArrayEquals(greys(40, 160), t.mipChain().texels(1));
        // 3 -> 1: (a + b + c) / 3.
        Texture three = new Texture("t", 3, 1, greys(10, 20, 61));
        assertArrayEquals(greys(30), three.mipChain().texels(1));
    }

    @Test
    void oddWeightsCountRowsFromTheBottom() {
        // A 1x5 column; image row 0 is the top, so from the bottom: 200, 150, 100, 50, 0.
        Texture t = new Texture("t", 1, 5, greys(0, 50, 100, 150, 200));
        // Level 1 is 1x2. Its bottom texel (image row 1) covers rows-from-bottom 0, 1 and 2/5 of 2:
        // (2 * 200 + 2 * 150 + 100) / 5 = 160; its top texel (image row 0): (100 + 2 * 50 + 2 * 0) / 5 = 40.
        assertArrayEquals(greys(40, 160), t.mipChain().texels(1));
    }

    @Test
    void oddByOddCombinesBothAxes() {
        // 3x3 -> 1x1: rows averaged (bottom 60, 70, 81 -> 70.33 -> 70; 30, 40, 50 -> 40; 0, 10, 20 -> 10),
        // then the column: (70 + 40 + 10) / 3 = 40.
        Texture t = new Texture("t", 3, 3, greys(0, 10, 20, 30, 40, 50, 60, 70, 81));
        assertArrayEquals(greys(40), t.mipChain().texels(1));
    }

    @Test
    void extraLevelsTakeAtMostAThird() {
        for (int[] size : new int[][] {{512, 512}, {513, 257}, {1000, 1000}, {255, 129}, {7, 7}}) {
            MipChain m = new Texture("t", size[0], size[1], new int[size[0] * size[1]]).mipChain();
            assertTrue(3 * m.extraTexels() <= (long) size[0] * size[1], size[0] + "x" + size[1]);
        }
        // Long thin textures: the levels after the short side reaches 1 add at most the long side.
        for (int[] size : new int[][] {{1024, 16}, {4096, 3}, {1, 4096}}) {
            MipChain m = new Texture("t", size[0], size[1], new int[size[0] * size[1]]).mipChain();
            long n = (long) size[0] * size[1];
            assertTrue(m.extraTexels() <= n / 3 + Math.max(size[0], size[1]), size[0] + "x" + size[1]);
        }
    }

    @Test
    void aStripHalvesAlongItsLengthOnly() {
        // Once a side is 1 only the other halves, so a 1-texel strip's levels add up to nearly its own
        // size, as in OpenGL: the 4/3 bound is for levels where both sides still halve.
        MipChain m = new Texture("t", 1, 4096, new int[4096]).mipChain();
        assertEquals(4095, m.extraTexels());
    }

    @Test
    void scalesAreLevelOverBaseSizes() {
        MipChain m = new Texture("t", 6, 12, new int[72]).mipChain();
        assertEquals(0.5, m.scaleS(1));
        assertEquals(1 / 6.0, m.scaleS(2));
        assertEquals(3 / 12.0, m.scaleT(2));
    }
}
