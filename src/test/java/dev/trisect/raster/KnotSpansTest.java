package dev.trisect.raster;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.render.Framebuffer;
import dev.trisect.texture.internal.LaneSampler;
import dev.trisect.texture.internal.Lod;
import dev.trisect.texture.internal.TexelLanes;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The span path's loops against their definition, pixel by pixel: on every covered row the first and
 * the last covered pixels are knots; each next knot is where {@link KnotSpacing#next} puts it, and is
 * the farthest the bound allows (one pixel more would break it) unless the row or the longest segment
 * ends first; a knot shows the per-pixel path's texel coordinates floored to 2^-32; a pixel between
 * knots shows the chord of the two knots' 32.32 values stepped by {@link KnotSpacing#step}; rows of one
 * pixel are knots; coverage and depth are the per-pixel path's; the filters and tiles change no UV.
 */
class KnotSpansTest {
    private static final int W = 160;
    private static final int H = 100;
    private static final double FIXED = KnotLoops.FIXED_SCALE;

    private static Texture noise(int w, int h, long seed) {
        Random rnd = new Random(seed);
        int[] px = new int[w * h];
        for (int i = 0; i < px.length; i++) {
            px[i] = 0xFF000000 | rnd.nextInt(0x1000000);
        }
        return new Texture("noise", w, h, px);
    }

    private static final Texture[] TEXTURES = {noise(64, 64, 1), noise(37, 23, 2)};

    /** One random triangle with depths up to 40x apart, texel coordinates in the hundreds. */
    private static ScreenTriangles triangle(Random rnd, int k) {
        ScreenTriangles t = new ScreenTriangles();
        add(t, rnd, k);
        return t;
    }

    private static void add(ScreenTriangles t, Random rnd, int k) {
        double x = rnd.nextDouble() * W;
        double y = rnd.nextDouble() * H;
        double spread = rnd.nextBoolean() ? 60 : 5;
        t.add(x, y, Math.pow(40, -rnd.nextDouble()), 300 * rnd.nextDouble() - 150, 300 * rnd.nextDouble(),
                x + rnd.nextGaussian() * spread * 2, y + rnd.nextGaussian() * spread, Math.pow(40, -rnd.nextDouble()),
                300 * rnd.nextDouble(), -20, x + rnd.nextGaussian() * spread * 2, y + rnd.nextGaussian() * spread,
                Math.pow(40, -rnd.nextDouble()), -90, 400 * rnd.nextDouble(), k, k % 2);
    }

    private static Framebuffer fill(ScreenTriangles t, TextureFilter filter, double knotError, Rasterizer r) {
        Framebuffer fb = new Framebuffer(W, H);
        fb.recordUv(true);
        fb.clearRows(0, H, 0);
        r.filter(filter);
        r.spans(knotError);
        r.fill(fb, t, all(t), 0, t.count(), TEXTURES, true, 0, 0, W, H);
        return fb;
    }

    private static int[] all(ScreenTriangles t) {
        int[] order = new int[t.count()];
        for (int i = 0; i < order.length; i++) {
            order[i] = i;
        }
        return order;
    }

    @Test
    void knotsAreWhereTheSpacingPutsThemAndShowExactCoordinates() {
        Random rnd = new Random(15);
        double[] errors = {0.05, 0.5, 3};
        int knots = 0;
        int maximal = 0;
        int between = 0;
        int oneColumnRows = 0;
        for (int k = 0; k < 300; k++) {
            ScreenTriangles t = triangle(rnd, k);
            double error = errors[k % errors.length];
            Framebuffer perPixel = fill(t, TextureFilter.NEAREST, 0, new Rasterizer());
            Rasterizer r = new Rasterizer();
            Framebuffer spans = fill(t, TextureFilter.NEAREST, error, r);
            assertArrayEquals(perPixel.depth(), spans.depth(), "coverage and depth are the per-pixel path's");
            TriangleSetup setup = r.setup();
            if (setup.rowStart >= setup.rowEnd) {
                continue;
            }
            int[] sp = r.spans();
            double qDx = setup.qPlane.dx;
            double scale = KnotSpacing.scale(qDx, error);
            double offset = KnotSpacing.offset(qDx, error);
            double unbounded = KnotSpacing.unbounded(qDx, error);
            double[] a = perPixel.uv();
            double[] b = spans.uv();
            for (int y = setup.rowStart, j = 0; y < setup.rowEnd; y++, j += 2) {
                int first = sp[j];
                int last = sp[j + 1] - 1;
                if (first > last) {
                    continue;
                }
                oneColumnRows += first == last ? 1 : 0;
                double qRow = setup.qPlane.base + setup.qPlane.dy * y;
                int knot = first;
                while (true) {
                    int i = y * W + knot;
                    String where = "triangle " + k + " row " + y + " knot " + knot;
                    for (int c = 0; c < 2; c++) {
                        assertEquals(Math.floor(a[3 * i + c] * FIXED) / FIXED, b[3 * i + c], where);
                    }
                    knots++;
                    if (knot == last) {
                        break;
                    }
                    double q = qRow + qDx * knot;
                    int next = KnotSpacing.next(knot, q, qRow, qDx, scale, offset, unbounded, last);
                    double qNext = qRow + qDx * next;
                    int length = next - knot;
                    assertTrue(length >= 1 && next <= last, where);
                    // (Adjacent knots have no pixel between them: no bound to keep.)
                    assertTrue(length == 1 || KnotSpacing.bound(q, qNext, length) <= error * (1 + 1e-12), where + ": bound "
                            + KnotSpacing.bound(q, qNext, length));
                    if (next < last && length < KnotSpacing.MAX_LENGTH) {
                        // The farthest the bound allows.
                        assertTrue(KnotSpacing.bound(q, qRow + qDx * (next + 1), length + 1) > error * (1 - 1e-12),
                                where + ": one pixel more is within the bound too");
                        maximal++;
                    }
                    // Between the knots, the chord of their fixed-point values.
                    int n = y * W + next;
                    for (int c = 0; c < 2; c++) {
                        long from = Math.round(b[3 * i + c] * FIXED);
                        long to = (long) Math.floor(a[3 * n + c] * FIXED);
                        long step = KnotSpacing.step(from, to, length);
                        for (int x = knot + 1; x < next; x++) {
                            assertEquals((from + step * (x - knot)) / FIXED, b[3 * (y * W + x) + c], where + " column " + x);
                            between++;
                        }
                    }
                    knot = next;
                }
            }
        }
        String summary = knots + " knots, " + maximal + " maximal, " + between + " values between, "
                + oneColumnRows + " one-pixel rows";
        assertTrue(knots > 10_000 && maximal > 3_000 && between > 20_000 && oneColumnRows > 20, summary);
    }

    @Test
    void aPixelBetweenKnotsIsWithinTheBoundOfTheKnotsSegment() {
        // The chord's texel coordinates carried back to the screen along the row, with the row's exact
        // map s(x) = S(x) / Q(x) inverted on the segment: the horizontal displacement of each pixel.
        Random rnd = new Random(4);
        double worstRatio = 0;
        for (int k = 0; k < 200; k++) {
            ScreenTriangles t = triangle(rnd, k);
            double error = 0.25 + k % 4;
            Rasterizer r = new Rasterizer();
            Framebuffer spans = fill(t, TextureFilter.NEAREST, error, r);
            TriangleSetup setup = r.setup();
            int[] sp = r.spans();
            for (int y = setup.rowStart, j = 0; y < setup.rowEnd; y++, j += 2) {
                double qRow = setup.qPlane.base + setup.qPlane.dy * y;
                double sRow = setup.sPlane.base + setup.sPlane.dy * y;
                double sDx = setup.sPlane.dx;
                double qDx = setup.qPlane.dx;
                for (int x = sp[j]; x < sp[j + 1]; x++) {
                    double s = spans.uv()[3 * (y * W + x)];
                    // s = (sRow + sDx X) / (qRow + qDx X) solved for X, where the exact map shows s.
                    double denominator = sDx - s * qDx;
                    if (Math.abs(denominator) < 1e-6) {
                        continue;
                    }
                    double shown = (s * qRow - sRow) / denominator;
                    worstRatio = Math.max(worstRatio, Math.abs(shown - x) / error);
                }
            }
        }
        assertTrue(worstRatio <= 1 + 1e-6 && worstRatio > 0.9, "worst displacement over the error: " + worstRatio);
    }

    /**
     * Trilinear takes one level of detail per segment, the mean of its knots' lambdas (each OpenGL's
     * lambda from the exact derivatives there; the row's last pixel, a knot that starts no segment, its
     * own), and samples the chord's coordinates: every pixel is that rule, bit for bit.
     */
    @Test
    void trilinearTakesTheMeanOfTheKnotsLambdasPerSegment() {
        Random rnd = new Random(21);
        Texture texture = TEXTURES[0];
        TexelLanes lanes = TexelLanes.of(texture.mipChain());
        int maxLevel = texture.mipChain().maxLevel();
        long pixels = 0;
        for (int k = 0; k < 200; k++) {
            ScreenTriangles t = new ScreenTriangles();
            add(t, rnd, 2 * k);
            Rasterizer r = new Rasterizer();
            double error = k % 2 == 0 ? 0.5 : 2;
            Framebuffer fb = fill(t, TextureFilter.TRILINEAR, error, r);
            TriangleSetup setup = r.setup();
            int[] sp = r.spans();
            double sDx = setup.sPlane.dx;
            double sDy = setup.sPlane.dy;
            double tDx = setup.tPlane.dx;
            double tDy = setup.tPlane.dy;
            double qDx = setup.qPlane.dx;
            double qDy = setup.qPlane.dy;
            for (int y = setup.rowStart, j = 0; y < setup.rowEnd; y++, j += 2) {
                if (sp[j] >= sp[j + 1]) {
                    continue;
                }
                RowKnots knots = RowKnots.of(t, 0, W, y, error);
                double qRow = setup.qPlane.base + qDy * y;
                double sRow = setup.sPlane.base + sDy * y;
                double tRow = setup.tPlane.base + tDy * y;
                int[] lambdas = new int[knots.columns().length];
                for (int n = 0; n < lambdas.length; n++) {
                    int x = knots.columns()[n];
                    double rq = 1 / (qRow + qDx * x);
                    lambdas[n] = LodRuns.lambdaAt((sRow + sDx * x) * rq, (tRow + tDx * x) * rq, rq, sDx, sDy,
                            tDx, tDy, qDx, qDy, maxLevel);
                }
                for (int x = sp[j]; x < sp[j + 1]; x++) {
                    // The last knot at or before the pixel starts its segment; the row's last knot starts
                    // none and keeps its own lambda.
                    int found = java.util.Arrays.binarySearch(knots.columns(), x);
                    int seg = found >= 0 ? found : -found - 2;
                    int a = lambdas[seg];
                    int b = lambdas[Math.min(seg + 1, lambdas.length - 1)];
                    int selection = a == Lod.NO_LAMBDA || b == Lod.NO_LAMBDA ? 0 : Lod.select(a + b >> 1, maxLevel);
                    int i = y * W + x;
                    long s8 = Math.round(fb.uv()[3 * i] * FIXED) >> 24;
                    long t8 = Math.round(fb.uv()[3 * i + 1] * FIXED) >> 24;
                    assertEquals(LaneSampler.trilinearPowerOfTwo(lanes.lanes(), lanes.levels(), selection, s8, t8),
                            fb.colour()[i], "triangle " + k + " pixel " + x + "," + y);
                    pixels++;
                }
            }
        }
        assertTrue(pixels > 50_000, pixels + " pixels");
    }

    @Test
    void fillingInTilesGivesTheSamePixelsWithEveryFilter() {
        Random rnd = new Random(5);
        ScreenTriangles t = new ScreenTriangles();
        for (int k = 0; k < 60; k++) {
            add(t, rnd, k);
        }
        for (TextureFilter filter : TextureFilter.values()) {
            Framebuffer whole = fill(t, filter, 0.5, new Rasterizer());
            Framebuffer tiled = new Framebuffer(W, H);
            tiled.recordUv(true);
            tiled.clearRows(0, H, 0);
            Rasterizer r = new Rasterizer();
            r.filter(filter);
            r.spans(0.5);
            for (int ty = 0; ty < H; ty += 7) {
                for (int tx = 0; tx < W; tx += 11) {
                    r.fill(tiled, t, all(t), 0, t.count(), TEXTURES, true, tx, ty, Math.min(W, tx + 11),
                            Math.min(H, ty + 7));
                }
            }
            assertArrayEquals(whole.colour(), tiled.colour(), filter.id());
            assertArrayEquals(whole.uv(), tiled.uv(), filter.id());
            assertArrayEquals(whole.depth(), tiled.depth(), filter.id());
            // The UV output does not depend on the filter.
            assertArrayEquals(fill(t, TextureFilter.NEAREST, 0.5, new Rasterizer()).uv(), whole.uv());
        }
    }
}
