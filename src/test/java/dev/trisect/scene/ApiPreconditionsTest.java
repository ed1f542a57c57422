package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import dev.trisect.mesh.Lines;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.texture.ProceduralTextures;
import java.awt.Font;
import org.junit.jupiter.api.Test;

/**
 * The preconditions the public API of lines, labels, billboards, text panels, fog and lights documents
 * are checked where the value is given, with a message naming it, not found (or silently dropped)
 * frames later.
 */
class ApiPreconditionsTest {
    private static final double NAN = Double.NaN;

    @Test
    void linePointsMustBeFiniteFloatsAsMeshPositionsAre() {
        Lines.Builder b = Lines.builder();
        for (double bad : new double[] {NAN, Double.POSITIVE_INFINITY, 1e39}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> b.point(0, bad, 0));
            assertTrue(e.getMessage().startsWith("line point (0.0, " + bad + ", 0.0) is not a finite float"),
                    e.getMessage());
            assertThrows(IllegalArgumentException.class, () -> b.segment(new Vec3(bad, 0, 0), Vec3.ZERO, 0));
        }
        assertEquals(0, b.build().pointCount(), "a refused point adds nothing");
        assertEquals("point is null", assertThrows(NullPointerException.class, () -> b.point(null)).getMessage());
        assertEquals("corners is null",
                assertThrows(NullPointerException.class, () -> b.polyline(0, (Vec3[]) null)).getMessage());
        assertEquals("corners is null",
                assertThrows(NullPointerException.class, () -> b.polyline(0, (int[]) null)).getMessage());
        assertEquals(1, b.segment(new Vec3(3.4e38, 0, 0), Vec3.ZERO, 0).build().segmentCount());
    }

    @Test
    void labelsAndBillboardsStandOnFinitePoints() {
        Vec3 nan = new Vec3(NAN, 0, 0);
        Vec3 far = new Vec3(0, Double.NEGATIVE_INFINITY, 0);
        for (Vec3 bad : new Vec3[] {nan, far}) {
            assertTrue(assertThrows(IllegalArgumentException.class, () -> Label.of("x", bad)).getMessage()
                    .startsWith("a label's position must be finite"));
            assertTrue(assertThrows(IllegalArgumentException.class,
                    () -> Billboard.world(ProceduralTextures.crate(8), bad, 1, 1)).getMessage()
                    .startsWith("a billboard's position must be finite"));
            assertThrows(IllegalArgumentException.class, () -> Billboard.pixels(ProceduralTextures.crate(8), bad, 8, 8));
        }
    }

    @Test
    void aTextPanelNamesAMissingOrEmptyFont() {
        assertEquals("font is null", assertThrows(NullPointerException.class,
                () -> new TextPanel(2, 2, null, 1)).getMessage());
        assertEquals("a font for text must be 1 to 512 pixels, got 0.0 (SansSerif)", assertThrows(
                IllegalArgumentException.class, () -> new TextPanel(2, 2, new Font(Font.SANS_SERIF, Font.PLAIN, 0), 1))
                .getMessage());
        TextPanel p = new TextPanel(2, 2, Label.DEFAULT_FONT, 1);
        assertEquals("text is null", assertThrows(NullPointerException.class, () -> p.write(0, 0, null, 0, 0))
                .getMessage());
    }

    @Test
    void aFogHoldsOnlyTheValuesItsEquationUses() {
        assertThrows(IllegalArgumentException.class, () -> new Fog(Fog.Mode.EXP, 5, 1, 0.1, Colour.BLACK));
        assertThrows(IllegalArgumentException.class, () -> new Fog(Fog.Mode.EXP2, 0, 1, 0.1, Colour.BLACK));
        assertThrows(IllegalArgumentException.class, () -> new Fog(Fog.Mode.LINEAR, 1, 5, -5, Colour.BLACK));
        // Finite values whose sum overflows are finite; a range wider than the doubles is refused.
        Fog far = Fog.linear(1e308, 1.5e308, Colour.BLACK);
        assertEquals(0.5, far.factor(1.25e308), 1e-12);
        assertTrue(assertThrows(IllegalArgumentException.class, () -> Fog.linear(-1e308, 1e308, Colour.BLACK))
                .getMessage().contains("end - start must be finite"));
        assertEquals(Fog.exp(0.1, Colour.BLACK), new Fog(Fog.Mode.EXP, 0, 0, 0.1, Colour.BLACK));
    }

    @Test
    void aDirectionalLightTakesAnyFiniteNonZeroLength() {
        assertEquals(new Vec3(1, 0, 0), Light.directional(new Vec3(1e-200, 0, 0), Colour.WHITE).vector());
        Vec3 v = Light.directional(new Vec3(1e200, 1e200, 0), Colour.WHITE).vector();
        assertEquals(1, v.length(), 1e-15);
        assertEquals(v.x(), v.y());
        Light l = Light.directional(new Vec3(0, 1, 0), Colour.WHITE);
        l.setVector(new Vec3(0, 0, 1e300));
        assertEquals(new Vec3(0, 0, 1), l.vector());
        assertThrows(IllegalArgumentException.class, () -> Light.directional(Vec3.ZERO, Colour.WHITE));
        assertThrows(IllegalArgumentException.class, () -> Light.directional(new Vec3(NAN, 1, 0), Colour.WHITE));
        // Within the plain formula's range, bit for bit what it was.
        Vec3 d = new Vec3(2, 3, 1);
        assertEquals(d.scale(1 / d.length()), Light.directional(d, Colour.WHITE).vector());
    }

    @Test
    void aNullInALabelBillboardOrScreenTextListNamesTheListAndWhere() {
        java.util.List<Label> labels = java.util.Arrays.asList(Label.of("a", Vec3.ZERO), null);
        assertEquals("labels holds null at index 1",
                assertThrows(NullPointerException.class, () -> SceneObject.labels(labels)).getMessage());
        assertEquals("billboards holds null at index 0", assertThrows(NullPointerException.class,
                () -> SceneObject.billboards(java.util.Collections.singletonList(null))).getMessage());
        assertEquals("texts holds null at index 0", assertThrows(NullPointerException.class,
                () -> new Scene().setScreenText(java.util.Collections.singletonList(null))).getMessage());
        assertEquals("labels is null: use List.of()",
                assertThrows(NullPointerException.class, () -> SceneObject.labels(null)).getMessage());
    }

    @Test
    void textFontsAreOneTo512PixelsAndAGlyphWiderThanTheAtlasIsCutNotAFailedFrame() {
        Font huge = new Font(Font.SANS_SERIF, Font.PLAIN, 3000);
        assertEquals("a font for text must be 1 to 512 pixels, got 3000.0 (SansSerif)", assertThrows(
                IllegalArgumentException.class, () -> Label.of("x", Vec3.ZERO).withFont(huge)).getMessage());
        assertThrows(IllegalArgumentException.class,
                () -> ScreenText.of(ScreenText.Corner.TOP_LEFT, "x").withFont(huge));
        assertThrows(IllegalArgumentException.class, () -> new TextPanel(2, 2, huge, 1));
        // At 512 px the per-ten-thousand sign is wider than the 512-texel atlas: it was an exception in
        // every frame that drew it (the label was accepted, the frame failed).
        Font largest = new Font(Font.SANS_SERIF, Font.PLAIN, 512);
        var glyph = dev.trisect.texture.internal.GlyphAtlas.of(largest).glyph(0x2031);
        org.junit.jupiter.api.Assumptions.assumeTrue(glyph.advance() > dev.trisect.texture.internal.GlyphAtlas.WIDTH,
                "this machine's sans-serif font has a narrow or no U+2031");
        assertEquals(dev.trisect.texture.internal.GlyphAtlas.WIDTH, glyph.width(), "cut to the atlas");
        Scene scene = new Scene();
        scene.add(SceneObject.labels(java.util.List.of(Label.of("\u2031", Vec3.ZERO).withFont(largest).onTop())));
        scene.setScreenText(java.util.List.of(ScreenText.of(ScreenText.Corner.TOP_LEFT, "\u2031").withFont(largest)));
        var image = SceneRenderer.renderImage(scene, Camera.looking(new Vec3(0, 0, 5), Vec3.ZERO), 64, 48);
        assertEquals(64, image.getWidth());
    }

    @Test
    void aLightPlacedBeyondDoubleRangeDoesNotShineRatherThanFailingEveryFrame() {
        Camera camera = Camera.looking(new Vec3(3, 2.4, 4), new Vec3(0, 0.4, 0));
        java.util.function.Function<Light, int[]> frame = light -> {
            Scene s = new Scene();
            s.add(new SceneObject(dev.trisect.mesh.Primitives.box(1, 1, 1), dev.trisect.scene.Material.colour(0xC08040)
                    .withShading(dev.trisect.render.Shading.SMOOTH)), Light.ambient(Colour.grey(0.3)));
            if (light != null) {
                double k = light.kind() == Light.Kind.POINT ? 1e200 : 1e-200;
                Group outer = new Group();
                Group inner = new Group();
                outer.setTransform(dev.trisect.math.Transform.scale(k));
                inner.setTransform(dev.trisect.math.Transform.scale(light.kind() == Light.Kind.POINT ? 1 : k));
                inner.add(light);
                outer.add(inner);
                s.add(outer);
            }
            var image = SceneRenderer.renderImage(s, camera, 48, 32);
            return image.getRGB(0, 0, 48, 32, null, 0, 48);
        };
        int[] without = frame.apply(null);
        // The direction through two scales of 1e-200 underflows to zero; the position 1e200 x 1e200 overflows.
        assertTrue(java.util.Arrays.equals(without, frame.apply(Light.directional(new Vec3(0, 1, 0), Colour.WHITE))));
        assertTrue(java.util.Arrays.equals(without, frame.apply(Light.point(new Vec3(1e200, 0, 0), Colour.WHITE))));
    }
}
