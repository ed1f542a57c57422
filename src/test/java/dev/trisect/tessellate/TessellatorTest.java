package dev.trisect.tessellate;

import dev.trisect.render.SplitPoint;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Viewport;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import java.util.stream.Stream;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

class TessellatorTest {
    private static final Viewport VP = new Viewport(256, 256);
    private static final int S = VertexLayout.PROJECTED_STRIDE;

    private static Pieces run(Tessellator t, double[] tri, TessellationSettings settings) {
        t.configure(VP, settings);
        t.resetStatistics();
        Pieces out = new Pieces();
        t.process(tri, 0, 6, 12, true, out);
        return out;
    }

    /** A(0,0) B(128,0) C(64,64) on screen, all at depth 1: a right isosceles triangle, hypotenuse 128. */
    private static double[] rightTriangle() {
        return Pieces.triangle(
                Pieces.vertex(VP, 0, 0, 1, 0, 0),
                Pieces.vertex(VP, 128, 0, 1, 1, 0),
                Pieces.vertex(VP, 64, 64, 1, 0, 1));
    }

    private static TessellationSettings edge(double maxEdge) {
        return TessellationSettings.defaults().withMaxEdge(maxEdge);
    }

    private static TessellationSettings error(double maxError) {
        return TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(maxError);
    }

    @Test
    void rightTriangleWithHypotenuseFourTimesMaxEdgeBecomesSixteenPieces() {
        // A(0,0) B(128,0) C(64,64): hypotenuse 128, legs 90.5. Longest-edge bisection halves it into
        // right isosceles triangles; the hypotenuse shrinks by sqrt(2) per level: 128, 90.5, 64, 45.3,
        // 32. Four levels of splits: 1 + 2 + 4 + 8 = 15 splits, 16 pieces with hypotenuse exactly 32,
        // which is not longer than maxEdge. The legs of the root are halved once, its hypotenuse twice.
        double[] tri = rightTriangle();
        Tessellator t = new Tessellator();
        Pieces out = run(t, tri, edge(32));
        assertEquals(16, out.pieces.size());
        assertEquals(15, t.splits());
        assertEquals(2, t.deepestLevel());
        assertEquals(0, t.capsReached());
        for (double[] p : out.pieces) {
            assertEquals(32.0 * 32.0 / 4, Math.abs(Pieces.area2(p)) / 2, 1e-9, "every piece is a quarter of 32x32");
        }
    }

    @Test
    void eachPieceComesWithItsSplitLevel() {
        double[] tri = rightTriangle();
        Tessellator t = new Tessellator();
        Pieces out = run(t, tri, edge(32));
        // The level of a piece is that of its most-halved edge: the root's hypotenuse is halved twice
        // (see above), and every piece has an edge cut from it or from a leg (halved once).
        assertEquals(16, out.levels.size());
        assertEquals(t.deepestLevel(), out.levels.stream().mapToInt(Integer::intValue).max().orElseThrow());
        assertTrue(out.levels.stream().allMatch(l -> l >= 1 && l <= 2), out.levels.toString());
        // 4 pieces per quarter of the triangle: the 8 pieces along the hypotenuse are at level 2.
        assertTrue(out.levels.stream().filter(l -> l == 2).count() >= 8, out.levels.toString());
        // Passed on whole, a triangle is at level 0.
        t.configure(VP, edge(32));
        Pieces whole = new Pieces();
        t.process(tri, 0, VertexLayout.CLIP_STRIDE, 2 * VertexLayout.CLIP_STRIDE, false, whole);
        assertEquals(java.util.List.of(0), whole.levels);
    }

    @Test
    void thresholdJustBelowAPieceEdgeAddsALevel() {
        double[] tri = rightTriangle();
        Tessellator t = new Tessellator();
        // Hypotenuse 32 now fails: one more level, 32 pieces with hypotenuse 22.6.
        assertEquals(32, run(t, tri, edge(31.99)).pieces.size());
        // Exactly 128 long: not longer than 128, so nothing splits.
        assertEquals(1, run(t, tri, edge(128)).pieces.size());
        assertEquals(2, run(t, tri, edge(127.99)).pieces.size());
    }

    @Test
    void triangleFacingTheCameraIsNeverSplitByTheErrorPolicy() {
        // Equal depths: affine is exact, the bound is 0 for every edge however long.
        double[] tri = Pieces.triangle(
                Pieces.vertex(VP, 10, 10, 5, 0, 0),
                Pieces.vertex(VP, 250, 20, 5, 9, 0),
                Pieces.vertex(VP, 30, 240, 5, 0, 9));
        Tessellator t = new Tessellator();
        assertEquals(1, run(t, tri, error(0.01)).pieces.size());
        assertEquals(0, t.splits());
    }

    @Test
    void errorPolicySplitsASingleDeepEdgeAsTheBoundPredicts() {
        // Corner A at depth 1, B and C at depth 4: edges AB and AC have bound L * (2-1)/(2+1) = L/3.
        // A 60 px edge gives 20 px; BC (equal depths) gives 0.
        double[] tri = Pieces.triangle(
                Pieces.vertex(VP, 100, 100, 1, 0, 0),
                Pieces.vertex(VP, 160, 100, 4, 1, 0),
                Pieces.vertex(VP, 100, 160, 4, 0, 1));
        assertEquals(20.0, EdgeBound.affineError(60, 1, 4), 1e-12);
        Tessellator t = new Tessellator();
        // Threshold above 20: one piece. Just below: AB (or AC, the tie goes to the first) is split.
        assertEquals(1, run(t, tri, error(20.0001)).pieces.size());
        Pieces out = run(t, tri, error(19.9999));
        assertTrue(out.pieces.size() > 1);
    }

    static Stream<Arguments> policiesAndPoints() {
        return Stream.of(SplitPolicy.values())
                .flatMap(policy -> Stream.of(SplitPoint.values()).map(point -> Arguments.of(policy, point)));
    }

    @ParameterizedTest(name = "{0} at {1}")
    @MethodSource("policiesAndPoints")
    void randomTrianglesObeyEveryInvariant(SplitPolicy policy, SplitPoint point) {
        Random rnd = new Random(policy.ordinal() * 7919L + 17);
        Tessellator t = new Tessellator();
        for (int n = 0; n < 300; n++) {
            double[] tri = randomTriangle(rnd);
            double[] thresholds = policy == SplitPolicy.EDGE
                    ? new double[] {200, 64, 32, 16, 8}
                    : new double[] {8, 2, 1, 0.5, 0.25};
            int previous = 0;
            for (double th : thresholds) {
                TessellationSettings settings = (policy == SplitPolicy.EDGE ? edge(th) : error(th))
                        .withSplitPoint(point);
                Pieces out = run(t, tri, settings);
                assertEquals(0, t.capsReached(), "no cap is reached by these triangles");
                for (int i = 0; i < out.pieces.size(); i++) {
                    assertEquals(thin(out.pieces.get(i)), out.fallback.get(i), "only slivers fall back");
                }
                assertTrue(out.pieces.size() >= previous, "pieces never fall as the threshold falls");
                previous = out.pieces.size();
                assertEquals(out.pieces.size(), t.pieces());
                assertEquals(out.pieces.size() - 1, t.splits(), "each split adds exactly one piece");
                checkPieces(tri, out, policy, th);
            }
        }
    }

    private static double[] randomTriangle(Random rnd) {
        double[][] v = new double[3][];
        for (int k = 0; k < 3; k++) {
            double w = 0.5 + 60 * rnd.nextDouble() * rnd.nextDouble();
            v[k] = Pieces.vertex(VP, 256 * rnd.nextDouble(), 256 * rnd.nextDouble(), w,
                    200 * rnd.nextGaussian(), 200 * rnd.nextGaussian());
        }
        return Pieces.triangle(v[0], v[1], v[2]);
    }

    /** Policy, area, barycentric position and UV of every piece against the input triangle. */
    private static void checkPieces(double[] tri, Pieces out, SplitPolicy policy, double threshold) {
        Tessellator probe = new Tessellator();
        Pieces whole = new Pieces();
        probe.configure(VP, TessellationSettings.defaults());
        probe.process(tri, 0, 6, 12, false, whole);
        double wholeArea = Math.abs(Pieces.area2(whole.pieces.get(0)));
        double sum = 0;
        for (double[] p : out.pieces) {
            sum += Math.abs(Pieces.area2(p));
            assertTrue(Math.signum(Pieces.area2(p)) == Math.signum(Pieces.area2(whole.pieces.get(0)))
                    || Math.abs(Pieces.area2(p)) < 1e-9 * wholeArea, "pieces keep the winding");
            for (int e = 0; e < 3; e++) {
                int a = e * S;
                int b = ((e + 1) % 3) * S;
                double len = Math.hypot(p[a + 6] - p[b + 6], p[a + 7] - p[b + 7]);
                double measure = policy == SplitPolicy.EDGE ? len : EdgeBound.affineError(len, p[a + 3], p[b + 3]);
                assertTrue(measure <= threshold * (1 + 1e-12), () -> "edge passes the policy: " + measure + " > " + threshold);
            }
            for (int k = 0; k < 3; k++) {
                checkOnTriangle(tri, p, k * S);
            }
        }
        assertEquals(wholeArea, sum, 1e-9 * wholeArea, "piece areas sum to the triangle's");
    }

    /**
     * The vertex is a convex combination of the input corners in clip space (x, y, w), and its z
     * and texel coordinates are the same combination: it lies on the triangle with the UV that
     * barycentric interpolation gives there.
     */
    private static void checkOnTriangle(double[] tri, double[] p, int o) {
        // Solve [x;y;w] = b0*P0 + b1*P1 + b2*P2 by Cramer's rule.
        double[][] m = new double[3][3];
        for (int k = 0; k < 3; k++) {
            m[0][k] = tri[6 * k];
            m[1][k] = tri[6 * k + 1];
            m[2][k] = tri[6 * k + 3];
        }
        double[] rhs = {p[o], p[o + 1], p[o + 3]};
        double det = det3(m);
        double[] b = new double[3];
        for (int k = 0; k < 3; k++) {
            double[][] mk = new double[3][];
            for (int r = 0; r < 3; r++) {
                mk[r] = m[r].clone();
                mk[r][k] = rhs[r];
            }
            b[k] = det3(mk) / det;
        }
        assertEquals(1.0, b[0] + b[1] + b[2], 1e-9);
        for (double bk : b) {
            assertTrue(bk >= -1e-9, () -> "inside the triangle: " + bk);
        }
        for (int c : new int[] {2, 4, 5}) {
            double expect = b[0] * tri[c] + b[1] * tri[6 + c] + b[2] * tri[12 + c];
            assertEquals(expect, p[o + c], 1e-9 * (1 + Math.abs(expect)), "an attribute");
        }
    }

    private static double det3(double[][] m) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    }

    @Test
    void depthCapStopsSplittingAndIsCounted() {
        double[] tri = Pieces.triangle(
                Pieces.vertex(VP, 0, 0, 1, 0, 0),
                Pieces.vertex(VP, 250, 3, 1, 1, 0),
                Pieces.vertex(VP, 7, 250, 1, 0, 1));
        Tessellator t = new Tessellator();
        for (int depth = 0; depth <= 6; depth++) {
            Pieces out = run(t, tri, edge(1).withMaxDepth(depth));
            assertTrue(t.deepestLevel() <= depth, "no edge halved more than maxDepth times");
            assertEquals(1, t.capsReached());
            assertFallbackFlagsExactlyTheFailingPieces(t, out, 1);
        }
        assertEquals(1, run(t, tri, edge(1).withMaxDepth(0)).pieces.size(), "depth 0 never splits");
    }

    /** Whether the piece is a sliver: least altitude below the limit and below an eighth of its longest edge. */
    private static boolean thin(double[] p) {
        double longest = 0;
        for (int e = 0; e < 3; e++) {
            int a = e * S;
            int b = ((e + 1) % 3) * S;
            longest = Math.max(longest, Math.hypot(p[a + 6] - p[b + 6], p[a + 7] - p[b + 7]));
        }
        double altitude = Math.abs(Pieces.area2(p)) / longest;
        return altitude < Slivers.SLIVER_PIXELS && altitude * 8 < longest;
    }

    /**
     * Under the edge policy: a piece is flagged for the per-pixel fallback exactly when an edge is too
     * long or it is a sliver.
     */
    private static void assertFallbackFlagsExactlyTheFailingPieces(Tessellator t, Pieces out, double maxEdge) {
        long flagged = 0;
        for (int i = 0; i < out.pieces.size(); i++) {
            double[] p = out.pieces.get(i);
            boolean fails = false;
            for (int e = 0; e < 3; e++) {
                int a = e * S;
                int b = ((e + 1) % 3) * S;
                fails |= Math.hypot(p[a + 6] - p[b + 6], p[a + 7] - p[b + 7]) > maxEdge;
            }
            assertEquals(fails || thin(p), out.fallback.get(i), "piece " + i + " is flagged exactly when it fails");
            flagged += fails || thin(p) ? 1 : 0;
        }
        assertTrue(flagged > 0, "the cap left failing pieces");
        assertEquals(flagged, t.fallbackPieces());
    }

    @Test
    void pieceCapBoundsWorkAndIsCounted() {
        double[] tri = Pieces.triangle(
                Pieces.vertex(VP, 0, 0, 1, 0, 0),
                Pieces.vertex(VP, 256, 0, 30, 1, 0),
                Pieces.vertex(VP, 0, 256, 1, 0, 1));
        Tessellator t = new Tessellator();
        for (int cap : new int[] {1, 2, 10, 1000}) {
            Pieces out = run(t, tri, edge(0.01).withMaxPieces(cap).withMaxDepth(30));
            assertEquals(cap, out.pieces.size(), "exactly the cap when the policy wants more");
            assertEquals(1, t.capsReached());
            assertFallbackFlagsExactlyTheFailingPieces(t, out, 0.01);
        }
    }

    @Test
    void enormousTriangleWithTinyThresholdEndsWithoutStackOverflow() {
        // The defaults bound it: depth 16 per edge and 65536 pieces.
        double[] tri = Pieces.triangle(
                Pieces.vertex(VP, -8000, -8000, 0.1, 0, 0),
                Pieces.vertex(VP, 8000, -7000, 900, 1e6, 0),
                Pieces.vertex(VP, 100, 9000, 0.2, 0, 1e6));
        Tessellator t = new Tessellator();
        Pieces out = run(t, tri, edge(0.001));
        assertTrue(out.pieces.size() <= TessellationSettings.DEFAULT_MAX_PIECES);
        assertEquals(1, t.capsReached());
    }

    @Test
    void piecesWhollyOffScreenAreNeitherSplitNorFilled() {
        double[] tri = Pieces.triangle(
                Pieces.vertex(VP, 300, 10, 1, 0, 0),
                Pieces.vertex(VP, 900, 10, 1, 1, 0),
                Pieces.vertex(VP, 300, 600, 1, 0, 1));
        Tessellator t = new Tessellator();
        Pieces out = run(t, tri, edge(4));
        assertEquals(0, out.pieces.size());
        assertEquals(0, t.splits());
        assertEquals(1, t.culledOffScreen());
    }

    @Test
    void sharedEdgeIsCutAtTheSamePointsFromBothSides() {
        // Two triangles sharing the edge P-Q, given in opposite directions, at different depths.
        double[] p = Pieces.vertex(VP, 20, 30, 1, 0, 0);
        double[] q = Pieces.vertex(VP, 230, 200, 25, 5, 5);
        double[] r1 = Pieces.vertex(VP, 240, 10, 3, 5, 0);
        double[] r2 = Pieces.vertex(VP, 10, 250, 9, 0, 5);
        for (SplitPoint point : SplitPoint.values()) {
            for (TessellationSettings settings : new TessellationSettings[] {edge(10), error(0.3)}) {
                TessellationSettings s = settings.withSplitPoint(point);
                Tessellator t = new Tessellator();
                // Both windings of each triangle, so the edge comes in both orders from either side.
                java.util.Set<String> onEdge1 = verticesOnLine(run(t, Pieces.triangle(p, q, r1), s), p, q);
                java.util.Set<String> onEdge2 = verticesOnLine(run(t, Pieces.triangle(q, p, r2), s), p, q);
                java.util.Set<String> onEdge3 = verticesOnLine(run(t, Pieces.triangle(r1, q, p), s), p, q);
                java.util.Set<String> onEdge4 = verticesOnLine(run(t, Pieces.triangle(p, r2, q), s), p, q);
                assertTrue(onEdge1.size() > 2, "the shared edge was split");
                assertEquals(onEdge1, onEdge2, point + ": bit-identical cut points on both sides");
                assertEquals(onEdge1, onEdge3, point + ": whichever order the ends come in");
                assertEquals(onEdge1, onEdge4, point + ": whichever order the ends come in");
            }
        }
    }

    @Test
    void cutPointsLieWhereEachSplitPointPutsThem() {
        // One long edge P-Q from depth 1 to depth 100 and a far-off third corner that keeps the other
        // edges passing: a threshold between the two halves' measures and the whole makes exactly one cut.
        double wp = 1;
        double wq = 100;
        double[] p = Pieces.vertex(VP, 10, 128, wp, 0, 0);
        double[] q = Pieces.vertex(VP, 246, 128, wq, 640, 0);
        double[] r = Pieces.vertex(VP, 128, 129, 30, 320, 1);
        for (SplitPoint point : SplitPoint.values()) {
            Pieces out = run(new Tessellator(), Pieces.triangle(p, q, r), edge(235).withSplitPoint(point));
            assertEquals(2, out.pieces.size(), point + ": one cut");
            double[] m = cutVertex(out, p, q);
            double expectedW = switch (point) {
                case MIDPOINT -> (wp + wq) / 2;
                case SCREEN -> 2 * wp * wq / (wp + wq);
                case GEOMETRIC -> Math.sqrt(wp * wq);
            };
            assertEquals(expectedW, m[3], 1e-12 * expectedW, point + ": view depth of the cut");
            // On the 3D edge: the same convex combination for clip x, y, z, w and the texel coordinates.
            double k = (m[3] - wp) / (wq - wp);
            for (int c = 0; c < VertexLayout.CLIP_STRIDE; c++) {
                assertEquals(p[c] + k * (q[c] - p[c]), m[c], 1e-9 * (1 + Math.abs(m[c])), point + ": attribute " + c);
            }
            double screenFraction = (m[6] - 10) / (246 - 10);
            if (point == SplitPoint.SCREEN) {
                assertEquals(0.5, screenFraction, 1e-12, "projects to the screen midpoint");
            }
            if (point == SplitPoint.GEOMETRIC) {
                // The screen point a P + (1 - a) Q with a = sqrt(qQ) / (sqrt(qP) + sqrt(qQ)).
                double a = Math.sqrt(1 / wq) / (Math.sqrt(1 / wp) + Math.sqrt(1 / wq));
                assertEquals(1 - a, screenFraction, 1e-12, "the geometric-mean-depth point");
            }
        }
    }

    /** The one vertex of the pieces that is neither P nor Q nor the third corner but lies on P-Q. */
    private static double[] cutVertex(Pieces out, double[] p, double[] q) {
        for (double[] piece : out.pieces) {
            for (int k = 0; k < 3; k++) {
                double[] v = java.util.Arrays.copyOfRange(piece, k * S, (k + 1) * S);
                if (v[3] != p[3] && v[3] != q[3] && Math.abs(v[7] - 128) < 1e-9) {
                    return v;
                }
            }
        }
        throw new AssertionError("no cut vertex on the edge");
    }

    @Test
    void screenMidpointCutsConvergeWhereTheThreeDMidpointStalls() {
        // An edge from just beyond the near plane (w = 0.01) to 10 km: the 3D midpoint keeps the near
        // half almost as long on screen at every level, so the depth cap stops it with the bound far
        // above the threshold; screen-midpoint cuts halve the screen length and converge.
        double[] tri = Pieces.triangle(
                Pieces.vertex(VP, -4000, 300, 0.01, 0, 0),
                Pieces.vertex(VP, 128, 100, 10000, 1e5, 0),
                Pieces.vertex(VP, 4000, 300, 0.01, 0, 1));
        Tessellator t = new Tessellator();
        run(t, tri, error(0.5).withSplitPoint(SplitPoint.MIDPOINT));
        assertEquals(1, t.capsReached(), "the 3D midpoint reaches the depth cap");
        run(t, tri, error(0.5).withSplitPoint(SplitPoint.SCREEN));
        assertEquals(0, t.capsReached(), "the screen midpoint converges within it");
    }

    /** Exact clip-space vertices of the pieces that lie on segment p-q (collinear in x, y, w). */
    private static java.util.Set<String> verticesOnLine(Pieces out, double[] p, double[] q) {
        java.util.Set<String> found = new java.util.TreeSet<>();
        for (double[] piece : out.pieces) {
            for (int k = 0; k < 3; k++) {
                int o = k * S;
                double[] v = {piece[o], piece[o + 1], piece[o + 3]};
                double[] a = {p[0], p[1], p[3]};
                double[] b = {q[0], q[1], q[3]};
                double cx = (v[1] - a[1]) * (b[2] - a[2]) - (v[2] - a[2]) * (b[1] - a[1]);
                double cy = (v[2] - a[2]) * (b[0] - a[0]) - (v[0] - a[0]) * (b[2] - a[2]);
                double cz = (v[0] - a[0]) * (b[1] - a[1]) - (v[1] - a[1]) * (b[0] - a[0]);
                if (Math.abs(cx) + Math.abs(cy) + Math.abs(cz) < 1e-9) {
                    found.add(Double.doubleToLongBits(piece[o]) + ":" + Double.doubleToLongBits(piece[o + 1])
                            + ":" + Double.doubleToLongBits(piece[o + 3]));
                }
            }
        }
        return found;
    }
}
