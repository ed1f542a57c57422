package dev.trisect.raster;

import static dev.trisect.raster.PixelScenes.HEIGHT;
import static dev.trisect.raster.PixelScenes.WIDTH;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.raster.PixelScenes.Path;
import dev.trisect.render.Framebuffer;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The ids output ({@link Framebuffer#ids()}, PIXEL_CONTRACT section 9): on every path, filter and
 * write, a frame recording the ids alone gets the colours and depths of a frame recording the UV
 * output, and its ids are exactly the UV output's third channel (the triangle's index + 1, 0 for the
 * background) — which a frame with the UV output records as ids too. Blended fragments write no id.
 */
class IdsOutputTest {
    @ParameterizedTest
    @EnumSource(Path.class)
    void idsAloneAreTheUvOutputsThirdChannel(Path path) {
        Random random = new Random(2026_12_01L + path.ordinal());
        long drawn = 0;
        for (int scene = 0; scene < 40; scene++) {
            Texture texture = PixelScenes.texture(random, 32, 16);
            TextureFilter filter = TextureFilter.values()[scene % TextureFilter.values().length];
            int state = new int[] {PixelState.OPAQUE, PixelState.ALPHA_TEST, PixelState.BLEND}[scene % 3];
            Framebuffer withUv = PixelScenes.frame(random);
            Framebuffer idsAlone = new Framebuffer(WIDTH, HEIGHT);
            idsAlone.recordIds(true);
            System.arraycopy(withUv.colour(), 0, idsAlone.colour(), 0, WIDTH * HEIGHT);
            System.arraycopy(withUv.depth(), 0, idsAlone.depth(), 0, WIDTH * HEIGHT);
            int[] before = new int[WIDTH * HEIGHT];
            for (int i = 0; i < before.length; i++) {
                before[i] = random.nextInt(4);
                withUv.uv()[3 * i + 2] = before[i];
            }
            System.arraycopy(before, 0, withUv.ids(), 0, before.length);
            System.arraycopy(before, 0, idsAlone.ids(), 0, before.length);
            double[] clip = PixelScenes.triangle(random, 200, (s, t) -> new double[] {1, 1, 1});
            long seed = random.nextLong();
            long a = PixelScenes.draw(path, filter, clip, texture, state, withUv, new Random(seed));
            long b = PixelScenes.draw(path, filter, clip, texture, state, idsAlone, new Random(seed));
            String what = path + ", " + filter + ", state " + state + ", scene " + scene;
            assertEquals(a, b, what + ": pixels written");
            assertNull(idsAlone.uv(), what);
            assertArrayEquals(withUv.colour(), idsAlone.colour(), what + ": colour");
            assertArrayEquals(withUv.depth(), idsAlone.depth(), what + ": depth");
            assertArrayEquals(withUv.ids(), idsAlone.ids(), what + ": ids");
            for (int i = 0; i < WIDTH * HEIGHT; i++) {
                assertEquals((int) withUv.uv()[3 * i + 2], withUv.ids()[i], what + ", pixel " + i);
                drawn += withUv.ids()[i] == 1 && before[i] != 1 ? 1 : 0;
                if (state == PixelState.BLEND) {
                    assertEquals(before[i], withUv.ids()[i], what + ", pixel " + i + ": a blended fragment writes no id");
                }
            }
        }
        assertTrue(drawn > 10_000, "pixels given the triangle's id: " + drawn);
    }

    @Test
    void idsAreKeptWhileEitherAsksAndClearedWithTheRows() {
        Framebuffer f = new Framebuffer(4, 3);
        assertNull(f.ids());
        f.recordUv(true);
        assertNotNull(f.ids(), "the UV output brings the ids");
        f.recordIds(true);
        f.recordUv(false);
        assertNotNull(f.ids(), "asked for alone, they stay");
        java.util.Arrays.fill(f.ids(), 7);
        f.clearRows(1, 2, 0);
        assertArrayEquals(new int[] {7, 7, 7, 7, 0, 0, 0, 0, 7, 7, 7, 7}, f.ids());
        f.recordIds(false);
        assertNull(f.ids());
    }
}
