package dev.trisect.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The pixel-centre bounds taken by shifts ({@link FixedPoint#firstCentre}, {@link FixedPoint#endCentre})
 * are the divisions they replace, for every sign, every sub-pixel phase and the ends of the int range.
 */
class FixedPointTest {
    private static int firstByDivision(int v) {
        return -Math.floorDiv(-(v - FixedPoint.HALF), FixedPoint.ONE);
    }

    private static int endByDivision(int v) {
        return Math.floorDiv(v - FixedPoint.HALF, FixedPoint.ONE) + 1;
    }

    private static void check(int v) {
        assertEquals(firstByDivision(v), FixedPoint.firstCentre(v), () -> "firstCentre(" + v + ")");
        assertEquals(endByDivision(v), FixedPoint.endCentre(v), () -> "endCentre(" + v + ")");
    }

    @Test
    void shiftsGiveTheDivisionsBoundsEverywhere() {
        // Every sub-pixel position of some pixels either side of 0, so every phase and both signs.
        for (int v = -16 * FixedPoint.ONE; v <= 16 * FixedPoint.ONE; v++) {
            check(v);
        }
        for (int v : new int[] {Integer.MIN_VALUE, Integer.MIN_VALUE + 1, Integer.MIN_VALUE + FixedPoint.HALF,
                Integer.MAX_VALUE, Integer.MAX_VALUE - 1, Integer.MAX_VALUE - FixedPoint.HALF}) {
            check(v);
        }
        Random random = new Random(26);
        for (int i = 0; i < 1_000_000; i++) {
            check(random.nextInt());
        }
    }

    @Test
    void aCentreExactlyOnTheBoundIsInside() {
        // Pixel 3's centre is at 3.5 pixels: a bound there starts and ends at pixel 3.
        int centre = 3 * FixedPoint.ONE + FixedPoint.HALF;
        assertEquals(3, FixedPoint.firstCentre(centre));
        assertEquals(4, FixedPoint.endCentre(centre));
        assertEquals(4, FixedPoint.firstCentre(centre + 1));
        assertEquals(3, FixedPoint.endCentre(centre - 1));
    }
}
