package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.texture.Texture;
import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Billboards are fogged as OpenGL fogs fragments: each pixel's colour blended towards the fog by the
 * factor of the billboard's own eye depth before the alpha test and the blend (opaque, alpha-tested and
 * blended billboards at known depths, against the equation); labels and screen text are not fogged.
 */
class BillboardFogTest {
    private static final int W = 200;
    private static final int H = 150;
    private static final Colour HAZE = new Colour(0.6, 0.7, 0.8);

    /** Column of the centre of a point at eye x {@code x} and eye depth {@code z}, camera at (0, 0, 10). */
    private static int column(Camera camera, double x, double z) {
        double focal = H / 2.0 / Math.tan(Math.toRadians(camera.fovY()) / 2);
        return (int) Math.floor(W / 2.0 + x / z * focal);
    }

    private static double channel(int rgb, int shift) {
        return (rgb >> shift) & 0xFF;
    }

    /** OpenGL's fogged channel: f·c + (1 - f)·fog. */
    private static double fogged(int rgb, int shift, double f) {
        double fog = 255 * (shift == 16 ? HAZE.r() : shift == 8 ? HAZE.g() : HAZE.b());
        return f * channel(rgb, shift) + (1 - f) * fog;
    }

    @Test
    void opaqueAlphaTestedAndBlendedBillboardsAreFoggedByTheirOwnDepth() {
        Camera camera = Camera.looking(new Vec3(0, 0, 10), Vec3.ZERO);
        int opaque = 0xFFC86432;
        int tested = 0xFF3080F0;
        int blended = 0x80F0F020;
        // The tested one's top-left texel is transparent: the top-left quarter of its 20 x 20 pixels.
        Texture testedTexture = new Texture("tested", 2, 2, new int[] {0, tested, tested, tested});
        Scene scene = new Scene();
        // A box behind the blended billboard: front face at z = -1, eye depth 11.
        scene.add(new SceneObject(Primitives.box(2, 2, 2), Material.colour(0x4060A0), Transform.translation(3, 0, -2)));
        for (Fog fog : new Fog[] {Fog.exp(0.08, HAZE), Fog.linear(2, 20, HAZE), Fog.exp2(0.07, HAZE)}) {
            scene.setFog(fog);
            scene.setScreenText(List.of());
            BufferedImage behind = SceneRenderer.renderImage(scene, camera, W, H);
            // Eye depths 10, 15 and 7.
            SceneObject sprites = SceneObject.billboards(List.of(
                    Billboard.pixels(Texture.solid("opaque", opaque), new Vec3(-3, 0, 0), 20, 20),
                    Billboard.pixels(testedTexture, new Vec3(0, 0, -5), 20, 20),
                    Billboard.pixels(Texture.solid("blended", blended), new Vec3(3, 0, 3), 20, 20)));
            scene.add(sprites);
            BufferedImage image = SceneRenderer.renderImage(scene, camera, W, H);
            scene.remove(sprites);
            int y = H / 2;
            for (int shift = 0; shift <= 16; shift += 8) {
                int at = image.getRGB(column(camera, -3, 10), y);
                assertEquals(fogged(opaque, shift, fog.factor(10)), channel(at, shift), 0.6, fog + " opaque");
                at = image.getRGB(column(camera, 0, 15) + 5, y + 5);
                assertEquals(fogged(tested, shift, fog.factor(15)), channel(at, shift), 0.6, fog + " tested");
                int x = column(camera, 3, 7);
                at = image.getRGB(x, y);
                // The fogged texel over the (fogged) box: fogged by 7, its own depth, not by the box's 11.
                double a = 128 / 255.0;
                double want = a * fogged(blended, shift, fog.factor(7)) + (1 - a) * channel(behind.getRGB(x, y), shift);
                assertEquals(want, channel(at, shift), 1.1, fog + " blended");
            }
            int x = column(camera, 0, 15) - 5;
            assertEquals(behind.getRGB(x, y - 5), image.getRGB(x, y - 5), "alpha-tested out: what was behind");
            assertNotEquals(opaque | 0xFF000000, image.getRGB(column(camera, -3, 10), y), "fogged");
        }
    }

    @Test
    void labelsAndScreenTextAreNotFogged() {
        Camera camera = Camera.looking(new Vec3(0, 0, 10), Vec3.ZERO);
        Scene scene = new Scene();
        scene.add(SceneObject.labels(List.of(Label.of("WWW", new Vec3(0, 0, 1)).withColour(0x00FF00)
                .withBackground(0x80FF00FF))));
        scene.setScreenText(List.of(ScreenText.of(ScreenText.Corner.TOP_LEFT, "HUD").withColour(0xFFFF00)));
        BufferedImage clear = SceneRenderer.renderImage(scene, camera, W, H);
        scene.setFog(Fog.exp(0.3, HAZE));
        BufferedImage fogged = SceneRenderer.renderImage(scene, camera, W, H);
        int changed = 0;
        int label = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                changed += clear.getRGB(x, y) != fogged.getRGB(x, y) ? 1 : 0;
                label += (clear.getRGB(x, y) & 0xFFFFFF) == 0x00FF00 ? 1 : 0;
            }
        }
        assertTrue(label > 20, "the label shows: " + label + " pixels");
        assertEquals(0, changed, "text over the background alone: fog changes no pixel");
        // In front of a fogged box, the label's glyphs keep their colour where they are drawn.
        scene.add(new SceneObject(Primitives.box(4, 4, 1), Material.colour(0x808080)));
        scene.setFog(null);
        BufferedImage boxClear = SceneRenderer.renderImage(scene, camera, W, H);
        scene.setFog(Fog.exp(0.3, HAZE));
        BufferedImage boxFogged = SceneRenderer.renderImage(scene, camera, W, H);
        int glyphs = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int c = boxClear.getRGB(x, y) & 0xFFFFFF;
                if (c == 0x00FF00 || c == 0xFFFF00) {
                    glyphs++;
                    assertEquals(boxClear.getRGB(x, y), boxFogged.getRGB(x, y), "text pixel " + x + ", " + y);
                }
            }
        }
        assertTrue(glyphs > label, "label and screen text over the box: " + glyphs);
        assertNotEquals(boxClear.getRGB(W / 2 + 15, H / 2 + 15), boxFogged.getRGB(W / 2 + 15, H / 2 + 15), "the box is fogged");
    }
}
