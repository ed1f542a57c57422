package dev.trisect.light;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.Framebuffer;
import org.junit.jupiter.api.Test;

/** The fog pass on hand-computed pixels, and its factor against OpenGL's equations at every depth. */
class FogPassTest {
    private static int channel(int argb, int shift) {
        return (argb >> shift) & 0xFF;
    }

    @Test
    void blendsCoveredPixelsTowardsTheFogByDepthAndLeavesTheBackground() {
        Framebuffer frame = new Framebuffer(3, 1);
        frame.clearRows(0, 1, 0x102030);
        int[] c = frame.colour();
        float[] d = frame.depth();
        // z = 4 between start 2 and end 10: f = 0.75. z = 1 (before the start): f = 1. Pixel 2: background.
        c[0] = 0xFFC86400;
        d[0] = 0.25f;
        c[1] = 0xFFC86400;
        d[1] = 1f;
        new FogPass(Fog.linear(2, 10, new Colour(0, 0, 1))).apply(frame, 0, 1);
        // 0.75·(200, 100, 0) + 0.25·(0, 0, 255) = (150, 75, 63.75)
        assertEquals(150, channel(c[0], 16));
        assertEquals(75, channel(c[0], 8));
        assertEquals(64, channel(c[0], 0));
        assertEquals(0xFF, channel(c[0], 24));
        assertEquals(0xFFC86400, c[1]);
        assertEquals(0xFF102030, c[2]);
        // A depth of -0 (bits unlike the background's +0, value alike) is background too, wherever it is.
        for (int at = 0; at < 3; at++) {
            Framebuffer row = new Framebuffer(3, 1);
            row.clearRows(0, 1, 0x102030);
            row.depth()[at] = -0f;
            new FogPass(Fog.exp(0.5, Colour.BLACK)).apply(row, 0, 1);
            assertEquals(0xFF102030, row.colour()[at]);
        }
    }

    @Test
    void rowsNearerThanTheStartAreLeftAndTheirNeighboursFogged() {
        // Linear fog from 2 to 10. Row 0: every covered pixel nearer than the start (z 0.5 to 2), so left at
        // once; row 1: the same with one gap of background, and its last pixel at z = 6 (f = 1/2). Row 0
        // stays as it was, bit for bit; in row 1 only the last pixel changes.
        int width = 40;
        Framebuffer frame = new Framebuffer(width, 2);
        frame.clearRows(0, 2, 0x102030);
        int[] c = frame.colour();
        float[] d = frame.depth();
        for (int y = 0; y < 2; y++) {
            for (int x = 3; x < width - 2; x++) {
                if (x != 17 || y == 0) {
                    c[y * width + x] = 0xFF000000 | (x * 0x050607);
                    d[y * width + x] = 1f / (0.5f + 1.5f * x / width);
                }
            }
        }
        d[width + width - 3] = 1f / 6;
        int[] before = c.clone();
        new FogPass(Fog.linear(2, 10, new Colour(1, 1, 1))).apply(frame, 0, 2);
        for (int i = 0; i < 2 * width; i++) {
            if (i != 2 * width - 3) {
                assertEquals(before[i], c[i], "pixel " + i);
            }
        }
        int was = before[2 * width - 3];
        for (int shift = 0; shift < 24; shift += 8) {
            double mixed = 0.5 * ((was >> shift) & 0xFF) + 0.5 * 255;
            assertTrue(Math.abs(channel(c[2 * width - 3], shift) - mixed) <= 0.6, "channel " + shift);
        }
    }

    @Test
    void oneThreadsRowsServeFramesOfEveryWidthAlike() {
        FogPass pass = new FogPass(Fog.exp(0.2, new Colour(0.3, 0.9, 0.5)));
        FogPass.Rows rows = new FogPass.Rows();
        for (int width : new int[] {5, 70, 3, 70}) {
            Framebuffer mine = new Framebuffer(width, 4);
            Framebuffer fresh = new Framebuffer(width, 4);
            for (Framebuffer f : new Framebuffer[] {mine, fresh}) {
                for (int i = 0; i < width * 4; i++) {
                    f.colour()[i] = 0xFF000000 | (i * 0x3F1D27 & 0xFFFFFF);
                    f.depth()[i] = i % 7 == 0 ? 0 : 1f / (1 + i % 23);
                }
            }
            pass.apply(mine, 1, 4, rows);
            pass.apply(fresh, 1, 4);
            assertEquals(java.util.Arrays.toString(fresh.colour()), java.util.Arrays.toString(mine.colour()));
            // Row 0 is left alone; a covered pixel of the fogged rows changes, the background does not.
            assertEquals(0xFF000000, mine.colour()[0]);
            assertTrue(mine.colour()[width + 1] != (0xFF000000 | ((width + 1) * 0x3F1D27 & 0xFFFFFF)));
            assertEquals(0xFF000000 | (7 * 0x3F1D27 & 0xFFFFFF), mine.colour()[7]);
        }
    }

    @Test
    void theFactorFollowsEveryEquationWithinItsBound() {
        Fog[] fogs = {Fog.linear(0.5, 40, Colour.BLACK), Fog.exp(0.07, Colour.BLACK), Fog.exp2(0.05, Colour.BLACK),
            Fog.exp(3, Colour.BLACK), Fog.linear(100, 101, Colour.BLACK), Fog.exp(1e-4, Colour.BLACK),
            Fog.exp2(2, Colour.BLACK), Fog.linear(1, 1.001, Colour.BLACK), Fog.exp2(40, Colour.BLACK)};
        for (Fog fog : fogs) {
            FogPass pass = new FogPass(fog);
            // The background is left as it is; a pixel far beyond the fog is all fog, however far (no
            // quotient or product overflows into the background's mark).
            assertEquals(4096, pass.weight(0f), fog.toString());
            for (float q : new float[] {1e-9f, 1e-30f, 1e-37f, Float.MIN_NORMAL, 1 / Float.MAX_VALUE * 2}) {
                assertEquals(0, pass.weight(q), fog + " at 1/w = " + q);
            }
            // The bounds FogPass states: rounding to 4096ths, plus the floats' error, linear
            // E·2^-11 + 2^-10 with E = end/(end - start), exp and exp2 the polynomial's and the floats' 0.082.
            double bound = (fog.mode() == Fog.Mode.LINEAR
                    ? 0.5 + fog.end() / (fog.end() - fog.start()) / 2048 + 1.0 / 1024 : 0.59) / 4096;
            for (double z = 0.001; z < 1e6; z *= 1.0007) {
                float q = (float) (1 / z);
                double exact = fog.factor(1.0 / q);
                double found = pass.weight(q) / 4096.0;
                assertTrue(Math.abs(found - exact) <= bound, fog + " at z = " + z + ": " + found + " for " + exact);
            }
        }
    }


    @Test
    void fogFactorsAreOpenGLs() {
        Fog linear = Fog.linear(2, 10, Colour.BLACK);
        assertEquals(0.75, linear.factor(4), 1e-12);
        assertEquals(1, linear.factor(1), 1e-12);
        assertEquals(0, linear.factor(11), 1e-12);
        assertEquals(Math.exp(-0.5), Fog.exp(0.25, Colour.BLACK).factor(2), 1e-12);
        assertEquals(Math.exp(-0.25), Fog.exp2(0.25, Colour.BLACK).factor(2), 1e-12);
        assertThrows(IllegalArgumentException.class, () -> Fog.linear(3, 3, Colour.BLACK));
        assertThrows(IllegalArgumentException.class, () -> Fog.exp(-1, Colour.BLACK));
        assertThrows(IllegalArgumentException.class, () -> new Colour(0, -1, 0));
        assertEquals(0x9DB8D3, Colour.of(0x9DB8D3).rgb());
    }
}
