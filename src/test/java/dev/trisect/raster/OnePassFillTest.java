package dev.trisect.raster;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.render.Framebuffer;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The one-pass fill of the tessellated path ({@link Rasterizer#fillPieces}) against the
 * piece-by-piece fill ({@link Rasterizer#fill}, not perspective) on random triangles cut into random
 * piece trees: colour, depth and UV output equal bit for bit, for every filter, every texture shape
 * and every height of band (the bands are what threads divide). The trees are of two kinds: split
 * as the tessellator splits (an edge's cut depends on the edge alone, so the pieces meet without
 * T-junctions), and split at random (T-junctions, so pieces of one triangle can overlap on a row),
 * with random fallback pieces and some coordinates too large for fixed point.
 */
class OnePassFillTest {
    private static final int W = 97;
    private static final int H = 83;

    @ParameterizedTest
    @EnumSource(TextureFilter.class)
    void oneLoopPerRowFillsWhatThePiecesFillOneByOne(TextureFilter filter) {
        Random random = new Random(15_2 + filter.ordinal());
        Texture[] textures = {texture(random, 64, 32), texture(random, 48, 40)};
        long pieces = 0;
        long written = 0;
        for (int scene = 0; scene < 60; scene++) {
            ScreenTriangles t = new ScreenTriangles();
            int triangles = 1 + random.nextInt(6);
            for (int id = 0; id < triangles; id++) {
                addTriangle(t, random, id, random.nextInt(2));
            }
            pieces += t.count();
            Framebuffer expected = fill(t, textures, filter, H, false);
            written += count(expected);
            for (int band : new int[] {1, 7, 16, H}) {
                Framebuffer actual = fill(t, textures, filter, band, true);
                String what = "scene " + scene + ", bands of " + band + " rows, " + filter;
                assertArrayEquals(expected.color(), actual.color(), what);
                assertArrayEquals(expected.depth(), actual.depth(), what);
                assertArrayEquals(expected.uv(), actual.uv(), what);
            }
        }
        assertTrue(pieces > 2000, "pieces " + pieces);
        assertTrue(written > 50_000, "pixels " + written);
    }

    private static long count(Framebuffer f) {
        long n = 0;
        for (float d : f.depth()) {
            n += d > 0 ? 1 : 0;
        }
        return n;
    }

    private static Framebuffer fill(ScreenTriangles t, Texture[] textures, TextureFilter filter, int band,
                                    boolean onePass) {
        Framebuffer frame = new Framebuffer(W, H);
        frame.recordUv(true);
        frame.clearRows(0, H, 0);
        Rasterizer r = new Rasterizer();
        r.filter(filter);
        int[] order = new int[t.count()];
        for (int i = 0; i < order.length; i++) {
            order[i] = i;
        }
        long written = 0;
        for (int y0 = 0; y0 < H; y0 += band) {
            int y1 = Math.min(H, y0 + band);
            written += onePass ? r.fillPieces(frame, t, order, 0, order.length, textures, 0, y0, W, y1)
                    : r.fill(frame, t, order, 0, order.length, textures, false, 0, y0, W, y1);
        }
        assertEquals(count(frame) > 0, written > 0);
        return frame;
    }

    private static Texture texture(Random random, int w, int h) {
        int[] argb = new int[w * h];
        for (int i = 0; i < argb.length; i++) {
            argb[i] = random.nextInt();
        }
        return new Texture("random", w, h, argb);
    }

    /**
     * A random triangle partly off the frame, its corners' 1/w in (0.05, 1] and texel coordinates
     * (now and then beyond fixed point), cut into a tree of pieces, appended as triangle {@code id}.
     */
    private static void addTriangle(ScreenTriangles t, Random random, int id, int material) {
        double[] v = new double[3 * 5];
        boolean huge = random.nextInt(10) == 0;
        for (int k = 0; k < 3; k++) {
            v[5 * k] = -20 + random.nextDouble() * (W + 40);
            v[5 * k + 1] = -20 + random.nextDouble() * (H + 40);
            v[5 * k + 2] = 0.05 + 0.95 * random.nextDouble();
            double range = huge ? 3e9 : 300;
            v[5 * k + 3] = (random.nextDouble() - 0.5) * range;
            v[5 * k + 4] = (random.nextDouble() - 0.5) * range;
        }
        boolean conforming = random.nextBoolean();
        double maxEdge = 6 + random.nextDouble() * 30;
        split(t, random, v, 0, 5, 10, 0, conforming, maxEdge, id, material);
    }

    /** Splits the piece with corners at a, b, c of v (x, y, q, s, t each) until it is small or deep enough. */
    private static void split(ScreenTriangles t, Random random, double[] v, int a, int b, int c, int depth,
                              boolean conforming, double maxEdge, int id, int material) {
        double ab = length(v, a, b);
        double bc = length(v, b, c);
        double ca = length(v, c, a);
        int edge;
        if (conforming) {
            double longest = Math.max(ab, Math.max(bc, ca));
            edge = longest <= maxEdge || depth >= 14 ? -1 : longest == ab ? 0 : longest == bc ? 1 : 2;
        } else {
            edge = depth >= 6 || random.nextInt(5) == 0 ? -1 : random.nextInt(3);
        }
        if (edge < 0) {
            t.add(v[a], v[a + 1], v[a + 2], v[a + 3], v[a + 4], v[b], v[b + 1], v[b + 2], v[b + 3], v[b + 4],
                    v[c], v[c + 1], v[c + 2], v[c + 3], v[c + 4], id, material, random.nextInt(8) == 0, depth);
            return;
        }
        int p = edge == 0 ? a : edge == 1 ? b : c;
        int q = edge == 0 ? b : edge == 1 ? c : a;
        int r = edge == 0 ? c : edge == 1 ? a : b;
        // The conforming cut is symmetric in p and q, as the tessellator's; the random one is not.
        double kp = conforming ? v[q + 2] : random.nextDouble() + 0.1;
        double kq = conforming ? v[p + 2] : random.nextDouble() + 0.1;
        int m = v.length;
        double[] w = java.util.Arrays.copyOf(v, m + 5);
        for (int k = 0; k < 5; k++) {
            w[m + k] = (v[p + k] * kp + v[q + k] * kq) / (kp + kq);
        }
        split(t, random, w, p, m, r, depth + 1, conforming, maxEdge, id, material);
        split(t, random, w, m, q, r, depth + 1, conforming, maxEdge, id, material);
    }

    private static double length(double[] v, int a, int b) {
        return Math.hypot(v[a] - v[b], v[a + 1] - v[b + 1]);
    }
}
