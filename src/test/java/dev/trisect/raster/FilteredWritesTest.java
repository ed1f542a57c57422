package dev.trisect.raster;

import static dev.trisect.raster.PixelScenes.HEIGHT;
import static dev.trisect.raster.PixelScenes.WIDTH;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.raster.PixelScenes.Path;
import dev.trisect.render.Framebuffer;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The alpha test and blend of {@link PixelState} with bilinear and trilinear filtering, on every path
 * and with either colour: the fragment's alpha is the filtered alpha of its texels, blended by the
 * same weights as its colour. The textures here have each texel's alpha equal to its blue, so the
 * filtered alpha at a pixel is the blue of the same triangle drawn opaque with the texel colour —
 * the lanes filter each channel alike — and the test reads it from there:
 * <ul>
 * <li>{@link PixelState#ALPHA_TEST}: where that alpha is at least 128 the pixel is the opaque
 * frame's (colour, depth, UV output), elsewhere the frame's own;</li>
 * <li>{@link PixelState#BLEND}: the colour is {@code round((src * a + dst * (255 - a)) / 255)} per
 * channel of the opaque fragment over the frame's colour; depth and UV output stay the frame's.</li>
 * </ul>
 */
class FilteredWritesTest {
    static Stream<Arguments> cases() {
        Stream.Builder<Arguments> b = Stream.builder();
        for (Path path : Path.values()) {
            for (TextureFilter filter : new TextureFilter[] {TextureFilter.BILINEAR, TextureFilter.TRILINEAR}) {
                for (int write : new int[] {PixelState.ALPHA_TEST, PixelState.BLEND}) {
                    b.add(Arguments.of(path, filter, write));
                }
            }
        }
        return b.build();
    }

    @ParameterizedTest
    @MethodSource("cases")
    void theFragmentsAlphaIsItsTexelsFilteredAlpha(Path path, TextureFilter filter, int write) {
        Random random = new Random(2026_11_28L + 7L * path.ordinal() + 31L * filter.ordinal() + write);
        long tested = 0;
        long passed = 0;
        long failed = 0;
        for (int scene = 0; scene < 12; scene++) {
            int colour = scene % 2 == 0 ? PixelState.TEXEL : PixelState.MODULATE;
            double[] clip = PixelScenes.triangle(random, 120, (s, t) -> new double[] {random.nextDouble(),
                    random.nextDouble(), random.nextDouble()});
            Texture texture = scene % 4 < 2 ? blueAlpha(random, 32, 16) : blueAlpha(random, 24, 20);
            Framebuffer background = PixelScenes.frame(random);
            Framebuffer texel = PixelScenes.copy(background);
            Framebuffer opaque = PixelScenes.copy(background);
            Framebuffer drawn = PixelScenes.copy(background);
            long seed = random.nextLong();
            PixelScenes.draw(path, filter, clip, texture, PixelState.TEXEL | PixelState.OPAQUE, texel, new Random(seed));
            PixelScenes.draw(path, filter, clip, texture, colour | PixelState.OPAQUE, opaque, new Random(seed));
            long written = PixelScenes.draw(path, filter, clip, texture, colour | write, drawn, new Random(seed));
            long expectedWritten = 0;
            for (int i = 0; i < WIDTH * HEIGHT; i++) {
                String at = path + " " + filter + ", scene " + scene + ", pixel " + i;
                boolean covered = opaque.uv()[3 * i + 2] == 1;
                int alpha = texel.colour()[i] & 0xFF;
                Framebuffer expected = background;
                int expectedColour = background.colour()[i];
                if (covered && write == PixelState.ALPHA_TEST) {
                    if (alpha >= 128) {
                        expected = opaque;
                        expectedColour = opaque.colour()[i];
                        expectedWritten++;
                        passed++;
                    } else {
                        failed++;
                    }
                } else if (covered) {
                    expectedColour = over(opaque.colour()[i], alpha, background.colour()[i]);
                    expectedWritten++;
                    passed += alpha == 255 ? 0 : 1;
                    failed += alpha == 255 ? 1 : 0;
                }
                assertEquals(expectedColour, drawn.colour()[i], at + ": colour");
                assertEquals(expected.depth()[i], drawn.depth()[i], at + ": depth");
                for (int k = 0; k < 3; k++) {
                    assertEquals(expected.uv()[3 * i + k], drawn.uv()[3 * i + k], at + ": UV output " + k);
                }
            }
            assertEquals(expectedWritten, written, "pixels written, scene " + scene);
            tested += expectedWritten;
        }
        // Not vacuous: fragments on both sides of the alpha test, or blended with alpha below 255.
        assertTrue(passed > 200 && failed > 0 || write == PixelState.BLEND && passed > 200,
                "passed " + passed + ", failed " + failed + ", of " + tested);
    }

    /** A random texture whose every texel has its blue as its alpha. */
    private static Texture blueAlpha(Random random, int w, int h) {
        int[] argb = new int[w * h];
        for (int i = 0; i < argb.length; i++) {
            int rgb = random.nextInt(0x1000000);
            argb[i] = (rgb & 0xFF) << 24 | rgb;
        }
        return new Texture("blue alpha", w, h, argb);
    }

    /** {@code src} (its alpha {@code a}) over {@code dst}, per channel rounded to nearest, alpha 255. */
    private static int over(int src, int a, int dst) {
        int out = 0xFF000000;
        for (int shift = 0; shift < 24; shift += 8) {
            int s = src >>> shift & 0xFF;
            int d = dst >>> shift & 0xFF;
            out |= (int) Math.round((s * a + d * (255 - a)) / 255.0) << shift;
        }
        return out;
    }
}
