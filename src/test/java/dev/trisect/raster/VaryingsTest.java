package dev.trisect.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Viewport;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.tessellate.Tessellator;
import dev.trisect.tessellate.VertexLayout;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Varyings by layout: a vertex layout with more slots than s and t carries each extra slot through
 * the tessellator, the screen triangles, the setup planes and the split trees' piece planes exactly
 * as s and t are carried. Slots 2 and 3 hold copies of s and t, so every stage must give them the
 * very bits it gives s and t (the same arithmetic on the same values); slot 4 holds a constant,
 * which must stay that constant (up to the rounding of a cut's weighted mean) with flat affine planes.
 */
class VaryingsTest {
    private static final int WIDTH = 160;
    private static final int HEIGHT = 120;
    private static final VertexLayout LAYOUT = VertexLayout.of(5);

    @Test
    void layoutsDescribeTheirOffsets() {
        assertEquals(VertexLayout.TEXTURED, VertexLayout.of(2));
        assertEquals(VertexLayout.CLIP_STRIDE, VertexLayout.TEXTURED.clipStride());
        assertEquals(VertexLayout.SCREEN_X, VertexLayout.TEXTURED.screenX());
        assertEquals(VertexLayout.PROJECTED_STRIDE, VertexLayout.TEXTURED.projectedStride());
        assertEquals(9, LAYOUT.clipStride());
        assertEquals(9, LAYOUT.screenX());
        assertEquals(11, LAYOUT.projectedStride());
        assertEquals(LAYOUT, VertexLayout.of(5));
        assertThrows(IllegalArgumentException.class, () -> VertexLayout.of(1));
        assertThrows(IllegalArgumentException.class, () -> VertexLayout.of(VertexLayout.MAX_VARYINGS + 1));
    }

    @Test
    void extraSlotsTravelExactlyAsTexelCoordinates() {
        Random random = new Random(2026_11_28L);
        Tessellator tess = new Tessellator();
        tess.layout(LAYOUT);
        int ps = LAYOUT.projectedStride();
        int cs = LAYOUT.clipStride();
        long planesChecked = 0;
        long piecesChecked = 0;
        for (int scene = 0; scene < 300; scene++) {
            TessellationSettings settings = TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR)
                    .withMaxError(0.05 + random.nextDouble());
            tess.configure(new Viewport(WIDTH, HEIGHT), settings);
            // s, t, then copies of s and t, then 7.25.
            double[] input = PixelScenes.triangle(random, 400, (s, t) -> new double[] {s, t, 7.25});
            ScreenTriangles pieces = new ScreenTriangles();
            pieces.layout(LAYOUT);
            tess.process(input, 0, cs, 2 * cs, true,
                    (v, a, b, c, level, fallback, links) -> pieces.add(v, a, b, c, 0, 0, fallback, level,
                            ScreenTriangles.OUTER, ScreenTriangles.OUTER, ScreenTriangles.OUTER));
            double[] at = pieces.attributes();
            for (int k = 0; k < 3 * pieces.count(); k++) {
                int o = k * pieces.cornerStride();
                assertEquals(at[o + 1], at[o + 3], "s copy, corner " + k);
                assertEquals(at[o + 2], at[o + 4], "t copy, corner " + k);
                assertEquals(7.25, at[o + 5], 1e-12, "constant (the cut's weighted mean rounds), corner " + k);
            }
            TriangleSetup setup = new TriangleSetup();
            for (int p = 0; p < pieces.count(); p++) {
                for (boolean perspective : new boolean[] {false, true}) {
                    if (setup.prepare(pieces, p, perspective, 0, 0, WIDTH, HEIGHT)) {
                        assertEquals(6, setup.planeCount);
                        same(setup.planes[1], setup.planes[3]);
                        same(setup.planes[2], setup.planes[4]);
                        if (!perspective) {
                            assertEquals(0, setup.planes[5].dx, 1e-9, "a constant's affine plane is flat");
                            assertEquals(0, setup.planes[5].dy, 1e-9, "a constant's affine plane is flat");
                        }
                        planesChecked++;
                    }
                }
            }
            if (!tess.splitTree().complete() || tess.splitTree().nodes() == 0) {
                continue;
            }
            SplitTrees trees = new SplitTrees();
            trees.layout(LAYOUT);
            trees.add(tess.vertices(), 0, ps, 2 * ps, 0, 0, tess.splitTree(), pieces, 0, 0);
            assertEquals(5 * SplitTrees.PLANE, trees.planeStride());
            double[] planes = trees.planes();
            for (int p = 0; p < pieces.count(); p++) {
                int o = p * trees.planeStride();
                for (int k = 0; k < 2 * SplitTrees.PLANE; k++) {
                    assertEquals(planes[o + k], planes[o + 2 * SplitTrees.PLANE + k], "piece " + p + ", value " + k);
                }
                piecesChecked++;
            }
            assertEquals(1, trees.inputs().count());
        }
        assertTrue(planesChecked > 1000, "planes checked: " + planesChecked);
        assertTrue(piecesChecked > 1000, "split pieces checked: " + piecesChecked);
    }

    @Test
    void texturedAdditionRefusedOnAWiderLayout() {
        ScreenTriangles t = new ScreenTriangles();
        t.layout(LAYOUT);
        assertThrows(IllegalStateException.class,
                () -> t.add(0, 0, 1, 0, 0, 10, 0, 1, 0, 0, 0, 10, 1, 0, 0, 0, 0));
    }

    private static void same(Plane expected, Plane actual) {
        assertEquals(expected.base, actual.base);
        assertEquals(expected.dx, actual.dx);
        assertEquals(expected.dy, actual.dy);
    }
}
