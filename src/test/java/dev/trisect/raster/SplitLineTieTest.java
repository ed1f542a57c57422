package dev.trisect.raster;

import static dev.trisect.tessellate.VertexLayout.PROJECTED_STRIDE;
import static dev.trisect.tessellate.VertexLayout.S;
import static dev.trisect.tessellate.VertexLayout.SCREEN_X;
import static dev.trisect.tessellate.VertexLayout.SCREEN_Y;
import static dev.trisect.tessellate.VertexLayout.T;
import static dev.trisect.tessellate.VertexLayout.W;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Viewport;
import dev.trisect.render.TessellationSettings;
import dev.trisect.tessellate.SplitTree;
import dev.trisect.tessellate.Tessellator;
import org.junit.jupiter.api.Test;

/**
 * The one-pass fill's tie rule for pixel centres exactly on a horizontal split line: they go to the
 * piece below it (docs/conventions.md, "The fill: one pass per input triangle"), whatever the row and
 * wherever the line lies along it.
 */
class SplitLineTieTest {
    private static final int WIDTH = 1024;
    private static final int HEIGHT = 64;

    @Test
    void centresOnAHorizontalSplitLineGoToThePieceBelowIt() {
        Tessellator tess = new Tessellator();
        // Edges p-q of 60 px and p-r, q-r of 50 px: only p-q is split (at its midpoint m, as every split
        // point cuts it with w = 1), and the line from m to r is horizontal, through row Y's centres.
        tess.configure(new Viewport(WIDTH, HEIGHT), TessellationSettings.defaults().withMaxEdge(55));
        TreeFill descent = new TreeFill();
        int checked = 0;
        for (int row : new int[] {0, 1, 2, 3, 5, 9, 30}) {
            double y = row + 0.5;
            for (double mx : new double[] {3, 130, 300, 400, 530, 700, 900}) {
                for (int direction : new int[] {-1, 1}) {
                    double rx = mx + 40 * direction;
                    if (rx < 0 || rx > WIDTH) {
                        continue;
                    }
                    double[] input = new double[18];
                    corner(input, 0, mx, y - 30);
                    corner(input, 6, mx, y + 30);
                    corner(input, 12, rx, y);
                    ScreenTriangles pieces = new ScreenTriangles();
                    tess.process(input, 0, 6, 12, true, (v, a, b, c, level, fallback, links) -> pieces.add(
                            v[a + SCREEN_X], v[a + SCREEN_Y], 1 / v[a + W], v[a + S], v[a + T],
                            v[b + SCREEN_X], v[b + SCREEN_Y], 1 / v[b + W], v[b + S], v[b + T],
                            v[c + SCREEN_X], v[c + SCREEN_Y], 1 / v[c + W], v[c + S], v[c + T], 0, 0, fallback, level));
                    SplitTree tree = tess.splitTree();
                    String what = "row " + row + ", cut point x " + mx + ", line towards " + rx;
                    assertEquals(1, tree.nodes(), what + ": one split");
                    assertEquals(2, pieces.count(), what + ": two pieces");
                    double[] v = tess.vertices();
                    int b = PROJECTED_STRIDE;
                    int c = 2 * PROJECTED_STRIDE;
                    SplitTrees trees = new SplitTrees();
                    trees.add(v[SCREEN_X], v[SCREEN_Y], 1 / v[W], v[S], v[T],
                            v[b + SCREEN_X], v[b + SCREEN_Y], 1 / v[b + W], v[b + S], v[b + T],
                            v[c + SCREEN_X], v[c + SCREEN_Y], 1 / v[c + W], v[c + S], v[c + T], 0, 0,
                            tree, pieces, 0, 0);
                    int below = lowest(pieces, 0) > lowest(pieces, 1) ? 0 : 1;
                    // The pixels whose centres lie on the line strictly between its ends.
                    int from = (int) Math.min(mx, rx) + 1;
                    int to = (int) Math.max(mx, rx) - 1;
                    int[] st = descent.stackFor(trees.nodeCount(0));
                    int n = TreeFill.descend(trees.roots()[0], from, to, row, trees, st, descent.segments());
                    int[] segs = descent.segments();
                    for (int g = 0; g < n; g += 3) {
                        assertEquals(below, segs[g + 2], what + ": columns " + segs[g] + ".." + segs[g + 1]
                                + " take the piece above the line");
                        checked += segs[g + 1] - segs[g];
                    }
                }
            }
        }
        assertTrue(checked > 1000, "pixels checked " + checked);
    }

    /** Corner at offset o: screen (x, y) pixels, w = 1 (clip x, y exact for these values), texel (x, y). */
    private static void corner(double[] input, int o, double x, double y) {
        input[o] = x / (WIDTH / 2.0) - 1;
        input[o + 1] = 1 - y / (HEIGHT / 2.0);
        input[o + 2] = 0.5;
        input[o + 3] = 1;
        input[o + 4] = x;
        input[o + 5] = y;
    }

    /** The largest screen y of piece p's corners. */
    private static double lowest(ScreenTriangles t, int p) {
        double[] sc = t.screen();
        int s = p * ScreenTriangles.SCREEN_STRIDE;
        return Math.max(sc[s + 1], Math.max(sc[s + 3], sc[s + 5]));
    }
}
