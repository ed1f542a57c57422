package dev.trisect.raster;

import static dev.trisect.raster.PixelScenes.HEIGHT;
import static dev.trisect.raster.PixelScenes.WIDTH;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.raster.PixelScenes.Path;
import dev.trisect.render.Framebuffer;
import dev.trisect.texture.Texture;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The writes of {@link PixelState} on every path, with either colour, against the same triangle drawn
 * opaque (the same colour) over the same frame: that frame says which pixels pass the depth test and
 * what colour and texel coordinates each fragment has; the texel's alpha is read here from the
 * texture at those coordinates.
 * <ul>
 * <li>{@link PixelState#ALPHA_TEST}: where the texel's alpha is at least 128 the pixel is the opaque
 * frame's (colour, depth, UV output); below, the frame's own, untouched — no depth written;</li>
 * <li>{@link PixelState#BLEND}: the colour is {@code round((src * a + dst * (255 - a)) / 255)} per
 * channel of the fragment over the frame's colour, computed here by a division; depth and UV output
 * are the frame's own, untouched;</li>
 * <li>everywhere else both leave the frame alone.</li>
 * </ul>
 */
class WriteSeamTest {
    @ParameterizedTest
    @EnumSource(Path.class)
    void alphaTestDrawsExactlyTheTexelsOfAlphaFrom128(Path path) {
        check(path, PixelState.ALPHA_TEST);
    }

    @ParameterizedTest
    @EnumSource(Path.class)
    void blendMixesByTheTexelsAlphaAndWritesNoDepthNorUv(Path path) {
        check(path, PixelState.BLEND);
    }

    @Test
    void divisionBy255RoundsToNearestEverywhere() {
        for (int v = 0; v <= 255 * 255; v++) {
            assertEquals((int) Math.round(v / 255.0), Blend.divide255(v), "v = " + v);
        }
        assertEquals(0xFF123456, Blend.over(0xFF123456, 0xFFABCDEF), "alpha 255: the source");
        assertEquals(0xFFABCDEF, Blend.over(0x00123456, 0xFFABCDEF), "alpha 0: the frame");
    }

    private static void check(Path path, int write) {
        Random random = new Random(2026_11_30L + path.ordinal() + 10L * write);
        long[] counts = new long[3];
        for (int scene = 0; scene < 60; scene++) {
            int colour = scene % 2 == 0 ? PixelState.TEXEL : PixelState.MODULATE;
            double[] clip = PixelScenes.triangle(random, 200, (s, t) -> new double[] {random.nextDouble(), random.nextDouble(),
                    random.nextDouble()});
            Texture texture = scene % 4 < 2 ? PixelScenes.texture(random, 32, 16) : PixelScenes.texture(random, 24, 20);
            Framebuffer background = PixelScenes.frame(random);
            Framebuffer opaque = PixelScenes.copy(background);
            Framebuffer tested = PixelScenes.copy(background);
            long seed = random.nextLong();
            PixelScenes.draw(path, clip, texture, colour | PixelState.OPAQUE, opaque, new Random(seed));
            long written = PixelScenes.draw(path, clip, texture, colour | write, tested, new Random(seed));
            long expectedWritten = 0;
            for (int i = 0; i < WIDTH * HEIGHT; i++) {
                String at = path + ", scene " + scene + ", pixel " + i;
                boolean drawn = opaque.uv()[3 * i + 2] == 1;
                int alpha = drawn ? texelAt(texture, opaque.uv()[3 * i], opaque.uv()[3 * i + 1]) >>> 24 : 0;
                Framebuffer expected = background;
                int expectedColour = background.colour()[i];
                if (drawn && write == PixelState.ALPHA_TEST && alpha >= 128) {
                    expected = opaque;
                    expectedColour = opaque.colour()[i];
                    expectedWritten++;
                    counts[1]++;
                } else if (drawn && write == PixelState.BLEND) {
                    expectedColour = blend(opaque.colour()[i], alpha, background.colour()[i]);
                    expectedWritten++;
                    counts[2]++;
                } else {
                    counts[0] += drawn ? 1 : 0;
                }
                assertEquals(Integer.toHexString(expectedColour), Integer.toHexString(tested.colour()[i]), at + ": colour");
                assertEquals(expected.depth()[i], tested.depth()[i], at + ": depth");
                for (int k = 0; k < 3; k++) {
                    assertEquals(expected.uv()[3 * i + k], tested.uv()[3 * i + k], at + ": UV output " + k);
                }
            }
            assertEquals(expectedWritten, written, path + ", scene " + scene + ": pixels written");
        }
        if (write == PixelState.ALPHA_TEST) {
            assertTrue(counts[0] > 5000 && counts[1] > 5000, "discarded " + counts[0] + ", drawn " + counts[1]);
        } else {
            assertTrue(counts[2] > 10_000, "blended " + counts[2]);
        }
    }

    /** The texel of texture coordinates (s, t), nearest, wrapped; texel row 0 is the image's bottom row. */
    private static int texelAt(Texture texture, double s, double t) {
        int w = texture.width();
        int h = texture.height();
        int column = Math.floorMod((int) Math.floor(s), w);
        int row = Math.floorMod((int) Math.floor(t), h);
        return texture.argb()[(h - 1 - row) * w + column];
    }

    /** Channel by channel, round((src * a + dst * (255 - a)) / 255), by a division; alpha 255. */
    private static int blend(int src, int a, int dst) {
        int out = 0xFF000000;
        for (int shift = 0; shift < 24; shift += 8) {
            int s = src >> shift & 0xFF;
            int d = dst >> shift & 0xFF;
            out |= (int) Math.round((s * a + d * (255 - a)) / 255.0) << shift;
        }
        return out;
    }
}
