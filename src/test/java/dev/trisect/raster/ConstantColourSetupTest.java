package dev.trisect.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.tessellate.VertexLayout;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The setup finds a triangle of one colour (the three corners' colour varyings within 2^-24) once,
 * takes the colour to 16 bits, and fits the colour planes only of the others; a setup of planes alone
 * (a split tree's pieces) fits them always.
 */
class ConstantColourSetupTest {
    private static ScreenTriangles one(double[] clip) {
        ScreenTriangles t = new ScreenTriangles();
        t.layout(PixelScenes.LAYOUT);
        int ps = PixelScenes.LAYOUT.projectedStride();
        t.add(PixelScenes.project(clip), 0, ps, 2 * ps, 0, 0, false, 0, ScreenTriangles.OUTER,
                ScreenTriangles.OUTER, ScreenTriangles.OUTER);
        return t;
    }

    @Test
    void oneColourIsTakenOnceAndOtherColoursArePlanes() {
        Random random = new Random(27);
        int constant = 0;
        int varying = 0;
        for (int n = 0; n < 200; n++) {
            boolean same = n % 2 == 0;
            double[] clip = PixelScenes.triangle(random, 100, (s, t) -> same ? new double[] {0.25, 0.5, 1}
                    : new double[] {(s + 50) / 100, 0.5, 1});
            if (same) {
                // A hair apart, well within 2^-24: still one colour.
                clip[2 * PixelScenes.LAYOUT.clipStride() + VertexLayout.varying(PixelState.COLOUR_SLOT)] += 0x1p-30;
            }
            ScreenTriangles t = one(clip);
            TriangleSetup setup = new TriangleSetup();
            Plane red = setup.planes[1 + PixelState.COLOUR_SLOT];
            red.base = Double.NaN;
            if (!setup.prepare(t, 0, true, 0, 0, PixelScenes.WIDTH, PixelScenes.HEIGHT)) {
                continue;
            }
            assertEquals(same, setup.constantColour, "triangle " + n);
            if (same) {
                assertEquals(Modulate.f16(0.25), setup.red16);
                assertEquals(Modulate.f16(0.5), setup.green16);
                assertEquals(Modulate.ONE, setup.blue16);
                assertTrue(Double.isNaN(red.base), "triangle " + n + ": its colour planes are not fitted");
                constant++;
            } else {
                assertTrue(Double.isFinite(red.base) && (red.dx != 0 || red.dy != 0),
                        "triangle " + n + ": red plane fitted");
                varying++;
            }
            TriangleSetup pieces = new TriangleSetup();
            assertTrue(pieces.affinePlanes(t, 0));
            assertFalse(pieces.constantColour, "planes alone are all fitted");
        }
        assertTrue(constant > 20 && varying > 20, constant + " one-colour, " + varying + " varying set up");
    }
}
