package dev.trisect.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.light.FogPass;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.Framebuffer;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The quads' coverage rule, nearest texel, alpha test, blend, depth and fog, on hand-worked cases. */
class QuadRasterTest {
    private static final int W = 8;
    private static final int H = 4;

    /** Draws the quads as the frame does: QUAD commands in the order added, band by band. */
    private static int[] draw(QuadRaster quads, int[] colour, float[] depth) {
        return draw(quads, colour, depth, null);
    }

    /** As {@link #draw(QuadRaster, int[], float[])}, in a frame fogged by {@code fog} (or none). */
    private static int[] draw(QuadRaster quads, int[] colour, float[] depth, FogPass fog) {
        quads.setUp(W, H, fog);
        Commands list = new Commands().quads(quads);
        for (int s = 0; s < quads.count(); s++) {
            list.add(Commands.QUAD, s, quads.firstRow(s), quads.lastRow(s) + 1);
        }
        list.bin(H, 2);
        for (int b = 0; b < 2; b++) {
            for (int k = list.bins().start(b); k < list.bins().start(b + 1); k++) {
                quads.rows(Commands.ref(list.command(list.bins().items()[k])), colour, depth, 2 * b, 2 * b + 2);
            }
        }
        return colour;
    }

    @Test
    void coversThePixelsWhoseCentresItHoldsWithTheNearestTexel() {
        QuadRaster quads = new QuadRaster();
        // Columns whose centres are in [1.5, 5.5): 1..4; rows in [0.5, 2.5): 0 and 1 (row 2's centre is 2.5).
        int[] texels = {0xFF000001, 0xFF000002, 0x00000003, 0xFF000004};
        quads.add(1.5, 0.5, 5.5, 2.5, 1, texels, 4, 0, 4, 1, QuadRaster.TEST, 0, QuadRaster.BILLBOARD);
        int[] c = draw(quads, new int[W * H], new float[W * H]);
        int[] row = Arrays.copyOfRange(c, 0, W);
        // Texel of column x: floor((x + 0.5 - 1.5) * 4 / 4); texel 2 has alpha 0 and is not drawn.
        assertEquals(Arrays.toString(new int[] {0, 0xFF000001, 0xFF000002, 0, 0xFF000004, 0, 0, 0}),
                Arrays.toString(row));
        assertEquals(Arrays.toString(row), Arrays.toString(Arrays.copyOfRange(c, W, 2 * W)));
        assertEquals(0, Arrays.stream(c, 2 * W, 4 * W).sum());
        assertEquals(3, quads.count(QuadRaster.BILLBOARD) + 2);
    }

    @Test
    void depthTestsBlendsAndDrawsOnTop() {
        QuadRaster quads = new QuadRaster();
        int[] colour = new int[W * H];
        Arrays.fill(colour, 0xFF000000 | 200 << 16 | 100);
        float[] depth = new float[W * H];
        Arrays.fill(depth, 0.5f);
        int[] half = {0x80FFFFFF};
        // Behind the frame (1/w 0.25 < 0.5): not drawn; in front, blended: 255 * 128/255 + 200 * 127/255.
        quads.add(0, 0, 1, 1, 0.25, half, 1, 0, 1, 1, QuadRaster.BLEND, 0xFFFFFFFF, QuadRaster.OTHER);
        quads.add(1, 0, 2, 1, 1.0, half, 1, 0, 1, 1, QuadRaster.BLEND, 0xFFFFFFFF, QuadRaster.OTHER);
        // On top, behind: drawn anyway, tinted, depth left alone.
        quads.add(2, 0, 3, 1, 0.25, new int[] {0xFFFFFFFF}, 1, 0, 1, 1, QuadRaster.TEST | QuadRaster.ON_TOP
                | QuadRaster.TINT, 0x00FF00, QuadRaster.GLYPH);
        draw(quads, colour, depth);
        assertEquals(0xFF000000 | 200 << 16 | 100, colour[0]);
        int r = (255 * 128 + 200 * 127 + 127) / 255;
        int b = (255 * 128 + 100 * 127 + 127) / 255;
        int g = (255 * 128 + 127) / 255;
        assertEquals(0xFF000000 | r << 16 | g << 8 | b, colour[1]);
        assertEquals(0.5f, depth[1], "a blended quad writes no depth");
        assertEquals(0xFF00FF00, colour[2]);
        assertEquals(0.5f, depth[2]);
    }

    /** The fogged channel in doubles: f·c + (1 - f)·fog, fog in 0..255. */
    private static double mix(int argb, int shift, double f, double fog) {
        return f * ((argb >> shift) & 0xFF) + (1 - f) * fog;
    }

    @Test
    void anOpaqueFoggedQuadIsWhatTheFogPassMakesOfItsTexelsAtItsDepth() {
        Random random = new Random(27);
        Colour haze = new Colour(0.6, 0.7, 0.8);
        for (Fog fog : new Fog[] {Fog.linear(2, 30, haze), Fog.exp(0.15, haze), Fog.exp2(0.1, haze)}) {
            FogPass pass = new FogPass(fog);
            for (int trial = 0; trial < 20; trial++) {
                int[] texels = new int[W * H];
                for (int i = 0; i < texels.length; i++) {
                    texels[i] = 0xFF000000 | random.nextInt(0x1000000);
                }
                double z = 1 + 30 * random.nextDouble();
                QuadRaster quads = new QuadRaster();
                // One texel a pixel over the whole frame, at eye depth z.
                quads.add(0, 0, W, H, 1 / z, texels, W, 0, W, H, QuadRaster.TEST | QuadRaster.FOG, 0,
                        QuadRaster.BILLBOARD);
                int[] colour = draw(quads, new int[W * H], new float[W * H], pass);
                // The same texels written at the same depth, then fogged by the pass.
                Framebuffer frame = new Framebuffer(W, H);
                System.arraycopy(texels, 0, frame.colour(), 0, W * H);
                Arrays.fill(frame.depth(), (float) (1 / z));
                pass.apply(frame, 0, H);
                assertEquals(Arrays.toString(frame.colour()), Arrays.toString(colour), fog + " at z " + z);
                // OpenGL's factor at the depth the quad's 1/w stands for as a float (as the depth buffer holds it).
                double f = fog.factor(1 / (double) (float) (1 / z));
                for (int i = 0; i < W * H; i++) {
                    for (int shift = 0; shift <= 16; shift += 8) {
                        double want = mix(texels[i], shift, f, 255 * (shift == 16 ? 0.6 : shift == 8 ? 0.7 : 0.8));
                        assertTrue(Math.abs(((colour[i] >> shift) & 0xFF) - want) <= 0.6,
                                fog + " z " + z + " pixel " + i + ": " + ((colour[i] >> shift) & 0xFF) + " vs " + want);
                    }
                }
            }
        }
    }

    @Test
    void fogColoursFragmentsBeforeTheAlphaTestAndTheBlend() {
        Fog fog = Fog.linear(2, 10, new Colour(0, 0, 1));
        FogPass pass = new FogPass(fog);
        int[] colour = new int[W * H];
        Arrays.fill(colour, 0xFF000000 | 200 << 16 | 100);
        float[] depth = new float[W * H];
        Arrays.fill(depth, 0.125f);
        QuadRaster quads = new QuadRaster();
        // At z = 4: f = (10 - 4)/(10 - 2) = 0.75. Alpha-tested: the transparent texel leaves the frame alone.
        quads.add(0, 0, 2, 1, 0.25, new int[] {0xFFC86400, 0x00FFFFFF}, 2, 0, 2, 1, QuadRaster.TEST | QuadRaster.FOG,
                0, QuadRaster.BILLBOARD);
        // Blended, half alpha, at z = 4: the fogged texel (150, 75, 64) over (200, 0, 100), not the texel fogged
        // by the depth behind it (z = 8).
        quads.add(2, 0, 3, 1, 0.25, new int[] {0x80C86400}, 1, 0, 1, 1, QuadRaster.BLEND | QuadRaster.FOG,
                0xFFFFFFFF, QuadRaster.BILLBOARD);
        // Tinted and fogged: the tint's colour fogged (0.75·255 + 0.25·0 = 191.25 red; blue 63.75).
        quads.add(3, 0, 4, 1, 0.25, new int[] {0xFFFFFFFF}, 1, 0, 1, 1, QuadRaster.TEST | QuadRaster.TINT
                | QuadRaster.FOG, 0xFF0000, QuadRaster.OTHER);
        // Not flagged: not fogged, though the frame has fog (labels, screen text).
        quads.add(4, 0, 5, 1, 0.25, new int[] {0xFFC86400}, 1, 0, 1, 1, QuadRaster.TEST, 0, QuadRaster.GLYPH);
        // Flagged at 1/w 0 (no depth: on top of everything, as screen text): not fogged.
        quads.add(5, 0, 6, 1, 0, new int[] {0xFFC86400}, 1, 0, 1, 1, QuadRaster.TEST | QuadRaster.ON_TOP
                | QuadRaster.FOG, 0, QuadRaster.OTHER);
        draw(quads, colour, depth, pass);
        assertEquals(0xFF000000 | 150 << 16 | 75 << 8 | 64, colour[0]);
        assertEquals(0.25f, depth[0]);
        assertEquals(0xFF000000 | 200 << 16 | 100, colour[1], "alpha-tested out");
        assertEquals(0.125f, depth[1]);
        assertEquals(QuadRaster.blend(0xFF000000 | 150 << 16 | 75 << 8 | 64, colour[7], 128), colour[2]);
        assertEquals(0xFF000000 | (150 * 128 + 200 * 127 + 127) / 255 << 16 | (75 * 128 + 127) / 255 << 8
                | (64 * 128 + 100 * 127 + 127) / 255, colour[2]);
        assertEquals(0.125f, depth[2], "a blended quad writes no depth");
        assertEquals(0xFF000000 | 191 << 16 | 64, colour[3]);
        assertEquals(0xFFC86400, colour[4]);
        assertEquals(0xFFC86400, colour[5]);
    }

    @Test
    void withoutFogTheFogFlagChangesNothing() {
        Random random = new Random(5);
        int[] texels = new int[W * H];
        for (int i = 0; i < texels.length; i++) {
            texels[i] = random.nextInt();
        }
        for (int mode : new int[] {QuadRaster.TEST, QuadRaster.BLEND, QuadRaster.TEST | QuadRaster.TINT,
                QuadRaster.BLEND | QuadRaster.TINT}) {
            int[][] frames = new int[2][];
            for (int flag = 0; flag < 2; flag++) {
                QuadRaster quads = new QuadRaster();
                quads.add(0.3, 0.2, W - 0.7, H - 0.1, 0.5, texels, W, 0, W, H, mode | flag * QuadRaster.FOG,
                        0x80405060, QuadRaster.BILLBOARD);
                int[] colour = new int[W * H];
                Arrays.fill(colour, 0xFF123456);
                frames[flag] = draw(quads, colour, new float[W * H], null);
            }
            assertEquals(Arrays.toString(frames[0]), Arrays.toString(frames[1]), "mode " + mode);
        }
    }
}
