package dev.trisect.raster;

import static dev.trisect.tessellate.VertexLayout.PROJECTED_STRIDE;
import static dev.trisect.tessellate.VertexLayout.S;
import static dev.trisect.tessellate.VertexLayout.SCREEN_X;
import static dev.trisect.tessellate.VertexLayout.SCREEN_Y;
import static dev.trisect.tessellate.VertexLayout.T;
import static dev.trisect.tessellate.VertexLayout.W;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Viewport;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.SplitPoint;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.tessellate.PieceSink;
import dev.trisect.tessellate.Tessellator;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The tessellated path's one-pass fill ({@link Rasterizer#fillTree}) against the per-pixel path and
 * the piece-by-piece fill, on random triangles split by the tessellator into random trees (both
 * policies, every split point, caps that stop the splitting now and then, fallback pieces, texel
 * coordinates now and then too large for fixed point), filled in bands of random height:
 *
 * <ul>
 * <li>coverage and depth equal the per-pixel path's, bit for bit (both come from the input triangle);</li>
 * <li>a pixel of an affine piece shows exactly the colour and texel coordinates that the piece
 * showed there filled alone, piece by piece, and a pixel of a per-pixel fallback piece exactly what
 * the per-pixel path shows there;</li>
 * <li>the only other pixels are those the piece filled alone did not cover by its snapped corners:
 * each lies within 1/64 pixel of the piece's own outline, and they are rare.</li>
 * </ul>
 */
class OnePassFillTest {
    private static final int WIDTH = 97;
    private static final int HEIGHT = 83;

    @ParameterizedTest
    @EnumSource(TextureFilter.class)
    void eachPixelShowsWhatItsPieceShowedAloneWithTheInputTrianglesCoverageAndDepth(TextureFilter filter) {
        check(filter, false, 200);
    }

    /**
     * Corners on a grid of half pixels, often two at the same height: edges along rows of pixel
     * centres, whose covered pixels lie on the pieces' edges there within the rounding of the cut
     * points (a cut point of an edge at y = 8.5 may lie at 8.500000000000004), so just outside them.
     */
    @ParameterizedTest
    @EnumSource(TextureFilter.class)
    void cornersOnHalfPixelsWithEdgesAlongRowsOfCentres(TextureFilter filter) {
        check(filter, true, 1000);
    }

    private static void check(TextureFilter filter, boolean grid, int scenes) {
        Random random = new Random(2026_11_26L + filter.ordinal() + (grid ? 100 : 0));
        Texture[] textures = {texture(random, 64, 32), texture(random, 48, 40)};
        Tessellator tess = new Tessellator();
        long checked = 0;
        long nearOutline = 0;
        long fallbackPixels = 0;
        long splitTrees = 0;
        for (int scene = 0; scene < scenes; scene++) {
            tess.configure(new Viewport(WIDTH, HEIGHT), settings(random));
            double[] input = grid ? gridTriangle(random) : triangle(random);
            int material = random.nextInt(2);
            ScreenTriangles pieces = new ScreenTriangles();
            tess.process(input, 0, 6, 12, true, sink(pieces, material));
            if (!tess.splitTree().complete() || tess.splitTree().leaves() == 0) {
                continue;
            }
            splitTrees += tess.splitTree().nodes() > 0 ? 1 : 0;
            SplitTrees trees = new SplitTrees();
            boolean single = tess.splitTree().nodes() == 0;
            if (!single) {
                int maxLevel = filter == TextureFilter.TRILINEAR ? textures[material].mipChain().maxLevel() : 0;
                double[] v = tess.vertices();
                int a = 0;
                int b = PROJECTED_STRIDE;
                int c = 2 * PROJECTED_STRIDE;
                trees.add(v[a + SCREEN_X], v[a + SCREEN_Y], 1 / v[a + W], v[a + S], v[a + T],
                        v[b + SCREEN_X], v[b + SCREEN_Y], 1 / v[b + W], v[b + S], v[b + T],
                        v[c + SCREEN_X], v[c + SCREEN_Y], 1 / v[c + W], v[c + S], v[c + T], 0, material,
                        tess.splitTree(), pieces, 0, maxLevel);
            }

            Framebuffer onePass = frame();
            Rasterizer r = new Rasterizer();
            r.filter(filter);
            int band = 1 + random.nextInt(HEIGHT);
            for (int y0 = 0; y0 < HEIGHT; y0 += band) {
                if (single) {
                    // Not split: its one piece is the input triangle, a TRIANGLE command.
                    r.fill(onePass, pieces, new int[] {0}, 0, 1, textures, false, 0, y0, WIDTH, Math.min(HEIGHT, y0 + band));
                } else {
                    r.fillTree(onePass, trees, 0, textures, 0, y0, WIDTH, Math.min(HEIGHT, y0 + band));
                }
            }
            Framebuffer perPixel = frame();
            r.fill(perPixel, single ? pieces : trees.inputs(), new int[] {0}, 0, 1, textures, true, 0, 0, WIDTH, HEIGHT);
            String what = "scene " + scene + ", " + filter + ", bands of " + band;
            assertArrayEquals(perPixel.depth(), onePass.depth(), what + ": coverage and depth");

            Framebuffer[] alone = new Framebuffer[pieces.count()];
            for (int p = 0; p < pieces.count(); p++) {
                alone[p] = frame();
                r.fill(alone[p], pieces, new int[] {p}, 0, 1, textures, false, 0, 0, WIDTH, HEIGHT);
            }
            TreeFill descent = new TreeFill();
            for (int y = 0; y < HEIGHT; y++) {
                for (int x = 0; x < WIDTH; x++) {
                    int i = y * WIDTH + x;
                    if (onePass.depth()[i] <= 0) {
                        continue;
                    }
                    int p = 0;
                    if (!single) {
                        int[] st = descent.stackFor(trees.nodeCount(0));
                        int n = TreeFill.descend(trees.roots()[0], x, x + 1, y, trees, st, descent.segments());
                        assertEquals(3, n, what + ": pixel (" + x + ", " + y + ") lies in one piece");
                        p = descent.segments()[2];
                    }
                    checked++;
                    Framebuffer expected;
                    if (single ? pieces.perPixel()[p] : trees.kinds()[p] == SplitTrees.PER_PIXEL) {
                        expected = perPixel;
                        fallbackPixels++;
                    } else if (alone[p].depth()[i] > 0) {
                        expected = alone[p];
                    } else {
                        double gap = outlineGap(pieces, p, x + 0.5, y + 0.5);
                        assertTrue(gap <= 1.0 / 64, what + ": pixel (" + x + ", " + y + ") of piece " + p
                                + " lies " + gap + " px off its outline");
                        nearOutline++;
                        continue;
                    }
                    String at = what + ", pixel (" + x + ", " + y + "), piece " + p;
                    assertEquals(expected.colour()[i], onePass.colour()[i], at + ": colour");
                    for (int k = 0; k < 3; k++) {
                        assertEquals(expected.uv()[3 * i + k], onePass.uv()[3 * i + k], at + ": uv " + k);
                    }
                }
            }
        }
        assertTrue(splitTrees > 100, "split trees " + splitTrees);
        assertTrue(checked > 100_000, "pixels " + checked);
        assertTrue(fallbackPixels > 500, "fallback pixels " + fallbackPixels);
        assertTrue(nearOutline < checked / 200, nearOutline + " of " + checked + " pixels off their piece");
    }

    private static TessellationSettings settings(Random random) {
        TessellationSettings s = TessellationSettings.defaults()
                .withSplitPoint(SplitPoint.values()[random.nextInt(SplitPoint.values().length)]);
        s = random.nextBoolean() ? s.withMaxEdge(3 + 25 * random.nextDouble())
                : s.withPolicy(SplitPolicy.ERROR).withMaxError(0.1 + random.nextDouble());
        if (random.nextInt(4) == 0) {
            s = s.withMaxDepth(1 + random.nextInt(4));
        }
        if (random.nextInt(4) == 0) {
            s = s.withMaxPieces(2 + random.nextInt(20));
        }
        return s;
    }

    /**
     * A random triangle in clip space ({@link dev.trisect.tessellate.VertexLayout}: x, y, z, w, s, t per
     * corner), partly off screen now and then, its w from 0.2 to 5 and its texel coordinates now and then
     * beyond fixed point.
     */
    private static double[] triangle(Random random) {
        double[] v = new double[18];
        double range = random.nextInt(12) == 0 ? 3e9 : 200;
        for (int k = 0; k < 3; k++) {
            double w = 0.2 + 4.8 * random.nextDouble();
            v[6 * k] = (2.4 * random.nextDouble() - 1.2) * w;
            v[6 * k + 1] = (2.4 * random.nextDouble() - 1.2) * w;
            v[6 * k + 2] = (0.1 + 0.8 * random.nextDouble()) * w;
            v[6 * k + 3] = w;
            v[6 * k + 4] = (random.nextDouble() - 0.5) * range;
            v[6 * k + 5] = (random.nextDouble() - 0.5) * range;
        }
        return v;
    }

    /**
     * A random triangle whose corners lie on screen at multiples of half a pixel (pixel centres and
     * corners), partly off screen now and then, its w 1 or from 0.25 to 4, half the time with its
     * third corner at its first one's height; texel coordinates as in {@link #triangle}.
     */
    private static double[] gridTriangle(Random random) {
        double[] v = new double[18];
        boolean flat = random.nextBoolean();
        double range = random.nextInt(12) == 0 ? 3e9 : 200;
        double firstY = 0;
        for (int k = 0; k < 3; k++) {
            double w = flat ? 1 : 0.25 * (1 + random.nextInt(16));
            double x = 0.5 * (random.nextInt(2 * WIDTH + 80) - 40);
            double y = k == 2 && random.nextBoolean() ? firstY : 0.5 * (random.nextInt(2 * HEIGHT + 80) - 40);
            firstY = k == 0 ? y : firstY;
            v[6 * k] = (x / (0.5 * WIDTH) - 1) * w;
            v[6 * k + 1] = (1 - y / (0.5 * HEIGHT)) * w;
            v[6 * k + 2] = 0.5 * w;
            v[6 * k + 3] = w;
            v[6 * k + 4] = (random.nextDouble() - 0.5) * range;
            v[6 * k + 5] = (random.nextDouble() - 0.5) * range;
        }
        return v;
    }

    /** Appends each piece to {@code out} as the pipeline's sink does (input triangle 0). */
    private static PieceSink sink(ScreenTriangles out, int material) {
        return (v, a, b, c, level, fallback, links) -> out.add(v[a + SCREEN_X], v[a + SCREEN_Y], 1 / v[a + W],
                v[a + S], v[a + T], v[b + SCREEN_X], v[b + SCREEN_Y], 1 / v[b + W], v[b + S], v[b + T],
                v[c + SCREEN_X], v[c + SCREEN_Y], 1 / v[c + W], v[c + S], v[c + T], 0, material, fallback, level);
    }

    /** The distance in pixels from (x, y) to the outline of piece p (its unsnapped corners). */
    private static double outlineGap(ScreenTriangles t, int p, double x, double y) {
        double[] sc = t.screen();
        int s = p * ScreenTriangles.SCREEN_STRIDE;
        double gap = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            int e = (k + 1) % 3;
            gap = Math.min(gap, segmentGap(sc[s + 2 * k], sc[s + 2 * k + 1], sc[s + 2 * e], sc[s + 2 * e + 1], x, y));
        }
        return gap;
    }

    private static double segmentGap(double ax, double ay, double bx, double by, double x, double y) {
        double dx = bx - ax;
        double dy = by - ay;
        double len2 = dx * dx + dy * dy;
        double u = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((x - ax) * dx + (y - ay) * dy) / len2));
        return Math.hypot(ax + u * dx - x, ay + u * dy - y);
    }

    private static Framebuffer frame() {
        Framebuffer f = new Framebuffer(WIDTH, HEIGHT);
        f.recordUv(true);
        f.clearRows(0, HEIGHT, 0);
        return f;
    }

    private static Texture texture(Random random, int w, int h) {
        int[] argb = new int[w * h];
        for (int i = 0; i < argb.length; i++) {
            argb[i] = random.nextInt();
        }
        return new Texture("random", w, h, argb);
    }
}
