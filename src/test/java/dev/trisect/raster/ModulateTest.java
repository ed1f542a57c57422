package dev.trisect.raster;

import static dev.trisect.raster.PixelScenes.HEIGHT;
import static dev.trisect.raster.PixelScenes.LAYOUT;
import static dev.trisect.raster.PixelScenes.WIDTH;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.raster.PixelScenes.Path;
import dev.trisect.render.Framebuffer;
import dev.trisect.tessellate.VertexLayout;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.api.Test;

/**
 * The modulated colour ({@link PixelState#MODULATE}, GL_MODULATE): a lit-like frame built by hand —
 * the colour varyings 2..4 set per corner — drawn by each path with a random filter, against the same triangle drawn with
 * the texel alone (state 0), which gives each pixel's texel, depth and UV output. Every pixel must
 * keep the state-0 frame's depth and UV output and take each channel of its texel times the colour,
 * rounded to nearest, where the colour at the pixel is computed here independently, as each path
 * promises (PIXEL_CONTRACT section 6, docs/conventions.md "Colour and writes"):
 * <ul>
 * <li>constant colours (the same at the three corners, so filled by the {@link PixelState#CONSTANT}
 * loops, the colour taken once per triangle): exactly {@code round(c * f)}, on every path; the colours
 * are thirds and sevenths, so that no product lies near a tie;</li>
 * <li>varying colours: per pixel, the perspective-correct interpolation of the corners' colours at
 * the pixel centre; affine, the screen-linear one; the span and tessellated paths interpolate the
 * colour exactly as they interpolate s and t, so with a colour that is an affine function of s and t
 * at the corners, the colour at a pixel is that function of the pixel's s and t in the UV output.</li>
 * </ul>
 */
class ModulateTest {
    private static final double[] EXACT = {0, 1.0 / 3, 2.0 / 3, 1.0 / 7, 4.0 / 7, 1};
    private static final int[][] FRACTIONS = {{0, 1}, {1, 3}, {2, 3}, {1, 7}, {4, 7}, {1, 1}};

    @ParameterizedTest
    @EnumSource(Path.class)
    void constantColoursModulateEveryTexelExactly(Path path) {
        Random random = new Random(2026_11_28L + path.ordinal());
        long checked = 0;
        for (int scene = 0; scene < 80; scene++) {
            int[] pick = {random.nextInt(EXACT.length), random.nextInt(EXACT.length), random.nextInt(EXACT.length)};
            double[] clip = PixelScenes.triangle(random, 200, (s, t) -> new double[] {EXACT[pick[0]], EXACT[pick[1]],
                    EXACT[pick[2]]});
            Texture texture = scene % 2 == 0 ? PixelScenes.texture(random, 32, 16) : PixelScenes.texture(random, 24, 20);
            Framebuffer[] frames = drawBoth(path, clip, texture, random);
            int[] texel = frames[0].colour();
            int[] lit = frames[1].colour();
            for (int i = 0; i < WIDTH * HEIGHT; i++) {
                if (frames[0].uv()[3 * i + 2] != 1) {
                    continue;
                }
                int expected = 0xFF000000;
                for (int c = 0; c < 3; c++) {
                    int shift = 16 - 8 * c;
                    int[] f = FRACTIONS[pick[c]];
                    int t = texel[i] >> shift & 0xFF;
                    // round(t * num / den), in integers: no tie, den being odd.
                    expected |= (2 * t * f[0] + f[1]) / (2 * f[1]) << shift;
                }
                assertEquals(Integer.toHexString(expected), Integer.toHexString(lit[i]),
                        path + ", scene " + scene + ", pixel " + i);
                checked++;
            }
        }
        assertTrue(checked > 20_000, "pixels checked: " + checked);
    }

    @ParameterizedTest
    @EnumSource(Path.class)
    void varyingColoursAreInterpolatedAsThePathInterpolates(Path path) {
        Random random = new Random(2026_11_29L + path.ordinal());
        long checked = 0;
        double worst = 0;
        for (int scene = 0; scene < 80; scene++) {
            // Corner colours that are an affine function of the corner's s and t: r = (s + 100) / 200,
            // g = (t + 100) / 200, b = (r + g) / 2, each in [0, 1] as s, t are in [-100, 100].
            double[] clip = PixelScenes.triangle(random, 200, ModulateTest::colourOf);
            Texture texture = scene % 2 == 0 ? PixelScenes.texture(random, 32, 16) : PixelScenes.texture(random, 24, 20);
            Framebuffer[] frames = drawBoth(path, clip, texture, random);
            double[] projected = PixelScenes.project(clip);
            for (int y = 0; y < HEIGHT; y++) {
                for (int x = 0; x < WIDTH; x++) {
                    int i = y * WIDTH + x;
                    if (frames[0].uv()[3 * i + 2] != 1) {
                        continue;
                    }
                    double[] colour = switch (path) {
                        case PER_PIXEL -> interpolate(projected, x + 0.5, y + 0.5, true);
                        case FIXED -> interpolate(projected, x + 0.5, y + 0.5, false);
                        default -> colourOf(frames[0].uv()[3 * i], frames[0].uv()[3 * i + 1]);
                    };
                    for (int c = 0; c < 3; c++) {
                        int shift = 16 - 8 * c;
                        double exact = Math.max(0, Math.min(255, (frames[0].colour()[i] >> shift & 0xFF) * colour[c]));
                        int got = frames[1].colour()[i] >> shift & 0xFF;
                        // The channel rounds the product to nearest with the colour in 16 fractional
                        // bits (Modulate): within half a unit of the exact product, and at most
                        // 255 / 2^17 more.
                        double off = Math.abs(got - exact);
                        worst = Math.max(worst, off);
                        assertTrue(off <= 0.5 + 255.0 / (1 << 17) + 1e-6, path + ", scene " + scene + ", pixel (" + x + ", " + y
                                + "), channel " + c + ": " + got + " for " + exact);
                    }
                    checked++;
                }
            }
        }
        assertTrue(checked > 20_000, "pixels checked: " + checked + ", worst " + worst);
    }

    @Test
    void aModulatingMaterialOnATexturedLayoutIsRefused() {
        ScreenTriangles t = new ScreenTriangles();
        t.add(0, 0, 1, 0, 0, 10, 0, 1, 0, 0, 0, 10, 1, 0, 0, 0, 0);
        Rasterizer r = new Rasterizer();
        r.states(new int[] {PixelState.MODULATE});
        Texture[] textures = {PixelScenes.texture(new Random(1), 4, 4)};
        assertThrows(IllegalStateException.class, () -> r.fill(new Framebuffer(16, 16), t, new int[] {0}, 0, 1,
                textures, true, 0, 0, 16, 16));
    }

    @Test
    void statesAreCheckedFieldByField() {
        for (int colour : new int[] {PixelState.TEXEL, PixelState.MODULATE}) {
            for (int write : new int[] {PixelState.OPAQUE, PixelState.ALPHA_TEST, PixelState.BLEND}) {
                int state = colour | write;
                assertTrue(PixelState.valid(state));
                assertEquals(colour, PixelState.colour(state));
                assertEquals(write, PixelState.write(state));
            }
        }
        for (int bad : new int[] {2, 3, 3 << 2, 16, -1}) {
            assertTrue(!PixelState.valid(bad), "state " + bad);
            assertThrows(IllegalArgumentException.class, () -> PixelState.check(bad));
        }
    }

    @Test
    void aChannelRoundsToNearestAndStaysWithinRange() {
        for (int c = 0; c < 256; c++) {
            assertEquals(c, Modulate.channel(c, 1));
            assertEquals(0, Modulate.channel(c, 0));
            assertEquals(Math.round(c * 0.3), Modulate.channel(c, 0.3), "channel " + c);
            assertEquals(c, Modulate.channel(c, 1.001), "a colour a hair above 1 is 1");
            assertEquals(0, Modulate.channel(c, -0.001), "a hair below 0 is 0");
        }
        assertEquals(0x80404010, Modulate.argb(0x80804020, 0.5, 1, 0.5), "alpha kept, channels halved");
    }

    /** The colour of texel coordinates (s, t): r = (s + 100) / 200, g = (t + 100) / 200, b = (r + g) / 2. */
    private static double[] colourOf(double s, double t) {
        double r = (s + 100) / 200;
        double g = (t + 100) / 200;
        return new double[] {r, g, (r + g) / 2};
    }

    /**
     * The colour varyings of the projected triangle at screen point (px, py): barycentric weights of the
     * point in the screen triangle, then either the perspective-correct mean (weights over w) or the
     * screen-linear one.
     */
    private static double[] interpolate(double[] v, double px, double py, boolean perspective) {
        int ps = LAYOUT.projectedStride();
        int sx = LAYOUT.screenX();
        double[] x = new double[3];
        double[] y = new double[3];
        for (int k = 0; k < 3; k++) {
            x[k] = v[k * ps + sx];
            y[k] = v[k * ps + sx + 1];
        }
        double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
        double[] weight = new double[3];
        double total = 0;
        for (int k = 0; k < 3; k++) {
            int a = (k + 1) % 3;
            int b = (k + 2) % 3;
            weight[k] = ((x[b] - x[a]) * (py - y[a]) - (px - x[a]) * (y[b] - y[a])) / area;
            if (perspective) {
                weight[k] /= v[k * ps + VertexLayout.W];
            }
            total += weight[k];
        }
        double[] c = new double[3];
        for (int j = 0; j < 3; j++) {
            for (int k = 0; k < 3; k++) {
                c[j] += weight[k] / total * v[k * ps + VertexLayout.varying(PixelState.COLOUR_SLOT + j)];
            }
        }
        return c;
    }

    /** The triangle drawn by {@code path} over the same frame with state 0 and with {@code MODULATE}. */
    private static Framebuffer[] drawBoth(Path path, double[] clip, Texture texture, Random random) {
        Framebuffer background = PixelScenes.frame(random);
        Framebuffer texel = PixelScenes.copy(background);
        Framebuffer lit = PixelScenes.copy(background);
        long seed = random.nextLong();
        // Every filter: the colour multiplies whatever texel the source gives.
        TextureFilter filter = TextureFilter.values()[random.nextInt(TextureFilter.values().length)];
        long a = PixelScenes.draw(path, filter, clip, texture, PixelState.TEXEL, texel, new Random(seed));
        long b = PixelScenes.draw(path, filter, clip, texture, PixelState.MODULATE, lit, new Random(seed));
        assertEquals(a, b, "pixels written");
        assertArrayEquals(texel.depth(), lit.depth(), "depth");
        assertArrayEquals(texel.uv(), lit.uv(), "UV output");
        return new Framebuffer[] {texel, lit};
    }
}
