package dev.trisect.raster;

import dev.trisect.math.Viewport;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.tessellate.PieceSink;
import dev.trisect.tessellate.Tessellator;
import dev.trisect.tessellate.VertexLayout;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.texture.Texture;
import java.util.HashMap;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The overlay's plan from the tessellator's links ({@link ScreenTriangles#links()}) on random piece
 * trees: every shared edge of an input triangle's pieces walked exactly once, every other edge of an
 * outlined piece (the input triangles' outer edges among them) walked too, and the whole plan the
 * one that matching every edge by its corners gives, so the pixels are the same.
 */
class OutlineLinksTest {
    private static final int W = 160;
    private static final int H = 120;
    private static final Viewport VP = new Viewport(W, H);
    private static final Texture[] GREY = {Texture.solid("grey", 0xFF808080)};
    private static final int BAND_ROWS = 16;

    @Test
    void sharedEdgesAreWalkedOnceAndEveryOtherEdgeToo() {
        Random random = new Random(4);
        int sharedWalks = 0;
        for (int trial = 0; trial < 60; trial++) {
            TessellationSettings settings = settings(random);
            double[][] grid = grid(random);
            ScreenTriangles linked = tessellate(grid, settings, Mode.LINKED);
            ScreenTriangles byCorners = tessellate(grid, settings, Mode.OUTER);
            ScreenTriangles unmatched = tessellate(grid, settings, Mode.INNER);
            for (BorderStyle style : new BorderStyle[] {BorderStyle.plain(),
                    new BorderStyle(BorderStyle.Colouring.DEPTH, true), BorderStyle.fallbackOnly()}) {
                OutlinePlan plan = plan(linked, style);
                OutlinePlan oracle = plan(byCorners, style);
                OutlinePlan every = plan(unmatched, style);
                sharedWalks += checkWalks(linked, plan, every);
                assertSamePlan(oracle, plan, "trial " + trial + " " + style);
                assertArrayEquals(draw(byCorners, oracle).colour(), draw(linked, plan).colour(), "trial " + trial);
            }
        }
        assertTrue(sharedWalks > 2000, "the trials share edges: " + sharedWalks);
    }

    private enum Mode { LINKED, OUTER, INNER }

    private static TessellationSettings settings(Random random) {
        TessellationSettings s = random.nextBoolean()
                ? TessellationSettings.defaults().withMaxEdge(5 + random.nextDouble() * 30)
                : TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.05 + random.nextDouble() / 2);
        return s.withMaxDepth(3 + random.nextInt(10)).withMaxPieces(random.nextInt(3) == 0 ? 5 + random.nextInt(30) : 4096);
    }

    /** A 4 x 3 grid of input vertices over the frame and beyond it, jittered, at random depths: (x, y, w, s, t). */
    private static double[][] grid(Random random) {
        double[][] g = new double[20][];
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 5; i++) {
                g[5 * j + i] = new double[] {-20 + i * 50 + random.nextGaussian() * 8, -15 + j * 50 + random.nextGaussian() * 8,
                    0.3 + random.nextDouble() * 8, random.nextDouble() * 64, random.nextDouble() * 64};
            }
        }
        return g;
    }

    /** The grid's triangles (two per cell, sharing its vertices), tessellated into screen triangles. */
    private static ScreenTriangles tessellate(double[][] grid, TessellationSettings settings, Mode mode) {
        Tessellator t = new Tessellator();
        t.configure(VP, settings);
        ScreenTriangles out = new ScreenTriangles();
        int[] id = {0};
        PieceSink sink = (v, a, b, c, level, fallback, links) -> {
            int index = out.count();
            int[] l = new int[3];
            for (int e = 0; e < 3; e++) {
                l[e] = switch (mode) {
                    case LINKED -> ScreenTriangles.link(links[e], index);
                    case OUTER -> ScreenTriangles.OUTER;
                    case INNER -> ScreenTriangles.INNER;
                };
            }
            int x = VertexLayout.SCREEN_X;
            int y = VertexLayout.SCREEN_Y;
            int w = VertexLayout.W;
            int s = VertexLayout.S;
            int tt = VertexLayout.T;
            out.add(v[a + x], v[a + y], 1 / v[a + w], v[a + s], v[a + tt], v[b + x], v[b + y], 1 / v[b + w], v[b + s],
                    v[b + tt], v[c + x], v[c + y], 1 / v[c + w], v[c + s], v[c + tt], id[0], 0, fallback, level,
                    l[0], l[1], l[2]);
        };
        for (int j = 0; j < 3; j++) {
            for (int i = 0; i < 4; i++) {
                int p = 5 * j + i;
                int[][] triangles = {{p, p + 5, p + 1}, {p + 1, p + 5, p + 6}};
                for (int[] tri : triangles) {
                    double[] in = new double[3 * VertexLayout.CLIP_STRIDE];
                    for (int k = 0; k < 3; k++) {
                        double[] g = grid[tri[k]];
                        double wk = g[2];
                        int o = k * VertexLayout.CLIP_STRIDE;
                        in[o + VertexLayout.X] = (2 * g[0] / W - 1) * wk;
                        in[o + VertexLayout.Y] = (1 - 2 * g[1] / H) * wk;
                        in[o + VertexLayout.Z] = 0.5 * wk;
                        in[o + VertexLayout.W] = wk;
                        in[o + VertexLayout.S] = g[3];
                        in[o + VertexLayout.T] = g[4];
                    }
                    t.process(in, 0, VertexLayout.CLIP_STRIDE, 2 * VertexLayout.CLIP_STRIDE, true, sink);
                    id[0]++;
                }
            }
        }
        return out;
    }

    private static OutlinePlan plan(ScreenTriangles t, BorderStyle style) {
        OutlinePlan plan = new OutlinePlan();
        plan.prepare(t, style, 6, 0.5, H, BAND_ROWS);
        return plan;
    }

    /**
     * Checks that each edge {@code every} walks (each outlined piece's every edge that lights a
     * pixel) is walked by {@code plan} exactly once: as its own, or as the earlier side of an edge
     * the piece across it walks, as the links say for a piece of the same input triangle. Returns
     * the walks of edges shared within an input triangle.
     */
    private static int checkWalks(ScreenTriangles t, OutlinePlan plan, OutlinePlan every) {
        Map<String, Integer> drawn = new HashMap<>();
        int shared = 0;
        for (int k = 0; k < plan.edgeCount(); k++) {
            int owner = plan.owner(k);
            int earlier = plan.earlier(k);
            drawn.merge(line(plan, k, owner), 1, Integer::sum);
            if (earlier >= 0) {
                drawn.merge(line(plan, k, earlier), 1, Integer::sum);
                if (t.ids()[earlier] == t.ids()[owner]) {
                    shared++;
                    assertTrue(linked(t, owner, earlier), "a walk shared within an input triangle follows a link");
                }
            }
        }
        for (int k = 0; k < every.edgeCount(); k++) {
            String key = line(every, k, every.owner(k));
            assertEquals(1, drawn.getOrDefault(key, 0), "edge " + key + " is walked once");
            drawn.remove(key);
        }
        assertTrue(drawn.isEmpty(), "nothing else is walked: " + drawn.keySet());
        return shared;
    }

    /** Whether an edge of triangle {@code later} links to one of triangle {@code earlier}. */
    private static boolean linked(ScreenTriangles t, int later, int earlier) {
        for (int e = 0; e < 3; e++) {
            int link = t.links()[3 * later + e];
            if (link >= 0 && link / 3 == earlier) {
                return true;
            }
        }
        return false;
    }

    /** Walk k of the plan as drawn for triangle {@code tri}: the triangle and the walk's line. */
    private static String line(OutlinePlan plan, int k, int tri) {
        return tri + ":" + plan.line(k, 0) + "," + plan.line(k, 1) + "," + plan.line(k, 2);
    }

    private static void assertSamePlan(OutlinePlan expected, OutlinePlan actual, String what) {
        assertEquals(expected.edgeCount(), actual.edgeCount(), what);
        for (int k = 0; k < expected.edgeCount(); k++) {
            assertEquals(expected.owner(k), actual.owner(k), what + " walk " + k);
            assertEquals(expected.earlier(k), actual.earlier(k), what + " walk " + k);
            for (int i = 0; i < 3; i++) {
                assertEquals(expected.line(k, i), actual.line(k, i), what + " walk " + k);
            }
        }
    }

    /** The triangles filled per pixel over a black frame, then outlined from {@code plan} band by band. */
    private static Framebuffer draw(ScreenTriangles t, OutlinePlan plan) {
        Framebuffer fb = new Framebuffer(W, H);
        fb.clearRows(0, H, 0);
        int[] order = new int[t.count()];
        for (int i = 0; i < order.length; i++) {
            order[i] = i;
        }
        new Rasterizer().fill(fb, t, order, 0, t.count(), GREY, true, 0, 0, W, H);
        BorderOverlay overlay = new BorderOverlay();
        for (int y = 0, band = 0; y < H; y += BAND_ROWS, band++) {
            overlay.draw(fb, plan, band, y, Math.min(H, y + BAND_ROWS));
        }
        return fb;
    }
}
