package dev.trisect.tessellate;

import dev.trisect.math.Viewport;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The links handed on with each piece ({@link PieceSink}) against the pieces' corners, on random
 * triangles and random piece trees: random depths, both policies, low depth and piece caps (which
 * leave T-junctions inside a triangle) and triangles reaching off screen (whose pieces there are
 * dropped).
 */
class PieceLinksTest {
    private static final Viewport VP = new Viewport(320, 240);
    private static final int S = VertexLayout.PROJECTED_STRIDE;

    @Test
    void linksNameExactlyThePiecesThatShareAnEdgeAndOuterExactlyTheBoundary() {
        Random random = new Random(15);
        int linked = 0;
        int capped = 0;
        for (int trial = 0; trial < 400; trial++) {
            double[] tri = Pieces.triangle(corner(random), corner(random), corner(random));
            TessellationSettings settings = (random.nextBoolean()
                    ? TessellationSettings.defaults().withMaxEdge(4 + random.nextDouble() * 60)
                    : TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.05 + random.nextDouble()))
                    .withMaxDepth(2 + random.nextInt(12)).withMaxPieces(random.nextInt(4) == 0 ? 3 + random.nextInt(40) : 4096);
            Tessellator t = new Tessellator();
            t.configure(VP, settings);
            Pieces out = new Pieces();
            t.process(tri, 0, VertexLayout.CLIP_STRIDE, 2 * VertexLayout.CLIP_STRIDE, true, out);
            capped += t.capsReached();
            linked += check(tri, out);
        }
        assertTrue(linked > 5000, "the trials share many edges: " + linked);
        assertTrue(capped > 20, "and caps stop some of them short: " + capped);
    }

    @Test
    void withLinksOffEveryEdgeIsOuterAndThePiecesAreTheSame() {
        Random random = new Random(16);
        for (int trial = 0; trial < 50; trial++) {
            double[] tri = Pieces.triangle(corner(random), corner(random), corner(random));
            TessellationSettings settings = TessellationSettings.defaults().withMaxEdge(8 + random.nextDouble() * 30);
            Tessellator t = new Tessellator();
            t.configure(VP, settings);
            Pieces on = new Pieces();
            t.process(tri, 0, VertexLayout.CLIP_STRIDE, 2 * VertexLayout.CLIP_STRIDE, true, on);
            t.links(false);
            Pieces off = new Pieces();
            t.process(tri, 0, VertexLayout.CLIP_STRIDE, 2 * VertexLayout.CLIP_STRIDE, true, off);
            assertEquals(on.pieces.size(), off.pieces.size());
            for (int p = 0; p < on.pieces.size(); p++) {
                assertTrue(Arrays.equals(on.pieces.get(p), off.pieces.get(p)), "piece " + p);
                assertTrue(Arrays.equals(new int[] {PieceSink.OUTER, PieceSink.OUTER, PieceSink.OUTER}, off.links.get(p)));
            }
        }
    }

    /** A random input vertex, mostly on screen, some far off it, at random depths. */
    private static double[] corner(Random r) {
        return Pieces.vertex(VP, -100 + r.nextDouble() * 520, -80 + r.nextDouble() * 400, 0.2 + r.nextDouble() * 20,
                r.nextDouble() * 256, r.nextDouble() * 256);
    }

    /** Checks one triangle's pieces; returns the number of links to earlier pieces. */
    private static int check(double[] tri, Pieces out) {
        List<double[]> pieces = out.pieces;
        // Every directed edge by its two corners, bit for bit: piece * 3 + edge.
        Map<String, Integer> byCorners = new HashMap<>();
        for (int p = 0; p < pieces.size(); p++) {
            for (int e = 0; e < 3; e++) {
                byCorners.put(key(pieces.get(p), e, false), 3 * p + e);
            }
        }
        int linked = 0;
        boolean[] linkedTo = new boolean[3 * pieces.size()];
        for (int p = 0; p < pieces.size(); p++) {
            int[] links = out.links.get(p);
            for (int e = 0; e < 3; e++) {
                int link = links[e];
                // The same two corners the other way round: the piece across this edge, if any was handed on.
                Integer across = byCorners.get(key(pieces.get(p), e, true));
                boolean onBoundary = onBoundary(tri, pieces.get(p), e);
                String where = "piece " + p + " edge " + e + " link " + link;
                if (link == PieceSink.OUTER) {
                    assertTrue(onBoundary, where + ": an outer edge lies on the input triangle's boundary");
                    continue;
                }
                assertFalse(onBoundary, where + ": an inner edge does not");
                if (link == PieceSink.INNER) {
                    assertTrue(across == null || across / 3 > p, where + ": no earlier piece shares it");
                    continue;
                }
                assertTrue(link >= 3, where);
                int earlier = 3 * (p - link / 3) + link % 3;
                assertTrue(earlier >= 0 && across != null && across == earlier, where + ": the earlier piece has its corners");
                assertEquals(PieceSink.INNER, out.links.get(earlier / 3)[earlier % 3], where + ": which saw no earlier sharer");
                assertFalse(linkedTo[earlier], where + ": an edge is shared once");
                linkedTo[earlier] = true;
                linked++;
            }
        }
        // Every inner edge some later piece has the same corners as was linked to by it.
        for (int p = 0; p < pieces.size(); p++) {
            for (int e = 0; e < 3; e++) {
                Integer across = byCorners.get(key(pieces.get(p), e, true));
                if (across != null && across / 3 > p) {
                    assertTrue(linkedTo[3 * p + e], "piece " + p + " edge " + e + " is shared with piece " + across / 3);
                }
            }
        }
        return linked;
    }

    /** The corners of edge e of a piece (from corner e to corner e + 1, or reversed), bit for bit. */
    private static String key(double[] piece, int e, boolean reversed) {
        int a = e * S;
        int b = (e + 1) % 3 * S;
        if (reversed) {
            int t = a;
            a = b;
            b = t;
        }
        return Arrays.toString(Arrays.copyOfRange(piece, a, a + S)) + Arrays.toString(Arrays.copyOfRange(piece, b, b + S));
    }

    /** Whether both ends of the piece's edge e lie on one edge of the input triangle (clip-space x, y, w). */
    private static boolean onBoundary(double[] tri, double[] piece, int e) {
        int a = e * S;
        int b = (e + 1) % 3 * S;
        for (int k = 0; k < 3; k++) {
            int p = k * VertexLayout.CLIP_STRIDE;
            int q = (k + 1) % 3 * VertexLayout.CLIP_STRIDE;
            if (onLine(tri, p, q, piece, a) && onLine(tri, p, q, piece, b)) {
                return true;
            }
        }
        return false;
    }

    /** Whether the vertex at v lies on the line through input corners p and q, in homogeneous (x, y, w). */
    private static boolean onLine(double[] tri, int p, int q, double[] piece, int v) {
        int x = VertexLayout.X;
        int y = VertexLayout.Y;
        int w = VertexLayout.W;
        // The determinant of the three points' (x, y, w), against the scale of its terms.
        double det = tri[p + x] * (tri[q + y] * piece[v + w] - piece[v + y] * tri[q + w])
                - tri[p + y] * (tri[q + x] * piece[v + w] - piece[v + x] * tri[q + w])
                + tri[p + w] * (tri[q + x] * piece[v + y] - piece[v + x] * tri[q + y]);
        double scale = (Math.abs(tri[p + x]) + Math.abs(tri[p + y]) + Math.abs(tri[p + w]))
                * (Math.abs(tri[q + x]) + Math.abs(tri[q + y]) + Math.abs(tri[q + w]))
                * (Math.abs(piece[v + x]) + Math.abs(piece[v + y]) + Math.abs(piece[v + w]));
        return Math.abs(det) <= 1e-9 * scale;
    }
}
