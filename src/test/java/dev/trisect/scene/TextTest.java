package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Labels and screen text against AWT's own drawing of the same string (same font, no antialiasing),
 * and where screen text lands.
 */
class TextTest {
    private static final int W = 320;
    private static final int H = 120;

    /** The frame of {@code scene} from a camera looking down -z at the origin, on black. */
    private static Framebuffer render(Scene scene) {
        Framebuffer f = new Framebuffer(W, H);
        try (SceneRenderer r = new SceneRenderer(2)) {
            r.render(scene, Camera.looking(new Vec3(0, 0, 5), Vec3.ZERO), RenderSettings.defaults(), f);
        }
        return f;
    }

    /** {@code text} as AWT draws it, white on black, its pen at (x, baseline). */
    private static int[] awt(String text, Font font, int x, int baseline) {
        BufferedImage image = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_OFF);
        g.setRenderingHint(RenderingHints.KEY_FRACTIONALMETRICS, RenderingHints.VALUE_FRACTIONALMETRICS_OFF);
        g.setFont(font);
        g.setColor(java.awt.Color.WHITE);
        g.drawString(text, x, baseline);
        g.dispose();
        return image.getRGB(0, 0, W, H, null, 0, W);
    }

    /** Pixels lit in either image, and of those the ones lit in one only. */
    private static int[] differing(int[] a, int[] b) {
        int lit = 0;
        int differ = 0;
        for (int i = 0; i < a.length; i++) {
            boolean la = (a[i] & 0xFFFFFF) != 0;
            boolean lb = (b[i] & 0xFFFFFF) != 0;
            lit += la || lb ? 1 : 0;
            differ += la != lb ? 1 : 0;
        }
        return new int[] {lit, differ};
    }

    @Test
    void aLabelOf16PixelGlyphsIsWhatAwtDraws() {
        for (Font font : List.of(Label.DEFAULT_FONT, new Font(Font.SERIF, Font.BOLD, 16),
                new Font(Font.MONOSPACED, Font.PLAIN, 16))) {
            String text = "Trisect: 16-px glyphs, ÄÖÜ ß π ж";
            Scene scene = new Scene();
            scene.add(SceneObject.labels(List.of(Label.of(text, Vec3.ZERO).withFont(font).onTop())));
            Framebuffer f = render(scene);
            // Where the label puts its pen: the text's width centred on the point (the frame's centre),
            // the box's bottom (descent below the baseline) on it.
            var atlas = dev.trisect.texture.internal.GlyphAtlas.of(font);
            int width = 0;
            for (int k = 0; k < text.length(); k = text.offsetByCodePoints(k, 1)) {
                width += atlas.glyph(text.codePointAt(k)).advance();
            }
            int left = (int) Math.round(W / 2.0 - width / 2.0);
            int baseline = H / 2 - atlas.lineHeight() + atlas.ascent();
            int[] d = differing(f.colour(), awt(text, font, left, baseline));
            assertTrue(d[0] > 200, font + ": the label lit " + d[0] + " pixels");
            assertTrue(d[1] <= 0.02 * d[0], font + ": " + d[1] + " of " + d[0] + " pixels differ from AWT's");
        }
    }

    @Test
    void screenTextSitsInItsCornerAndCountsItsGlyphs() {
        Scene scene = new Scene();
        scene.setScreenText(List.of(ScreenText.of(ScreenText.Corner.BOTTOM_RIGHT, "III").withColour(0xFF0000),
                ScreenText.of(ScreenText.Corner.TOP_LEFT, "H").withMargin(0)));
        Framebuffer f = new Framebuffer(W, H);
        FrameStats stats;
        try (SceneRenderer r = new SceneRenderer(1)) {
            stats = r.render(scene, Camera.looking(new Vec3(0, 0, 5), Vec3.ZERO), RenderSettings.defaults(), f);
        }
        assertEquals(4, stats.glyphs());
        assertEquals(0, stats.billboards());
        int maxX = -1;
        int maxY = -1;
        int minX = W;
        int minY = H;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int c = f.colour()[y * W + x] & 0xFFFFFF;
                if (c == 0xFF0000) {
                    maxX = Math.max(maxX, x);
                    maxY = Math.max(maxY, y);
                } else if (c == 0xFFFFFF) {
                    minX = Math.min(minX, x);
                    minY = Math.min(minY, y);
                }
            }
        }
        // The red text ends within its margin (8 px) and a glyph's side bearing of the bottom-right corner.
        assertTrue(maxX < W - 8 && maxX >= W - 8 - 4, "red text's right column " + maxX);
        assertTrue(maxY < H - 8 && maxY >= H - 8 - 8, "red text's bottom row " + maxY);
        // The white H, margin 0: within a few pixels of the top-left corner, not off it.
        assertTrue(minX >= 0 && minX <= 3 && minY >= 0 && minY <= 6, "white text's corner " + minX + ", " + minY);
    }

    @Test
    void aDepthTestedLabelHidesBehindASurfaceAndAnOnTopOneDoesNot() {
        Scene scene = new Scene();
        scene.add(new SceneObject(Primitives.box(4, 4, 0.1), Material.colour(0x0000FF)));
        scene.add(SceneObject.labels(List.of(Label.of("behind", new Vec3(-1, 0, -1)).withColour(0xFF0000),
                Label.of("over", new Vec3(1, 0, -1)).withColour(0x00FF00).onTop())));
        int[] c = render(scene).colour();
        long red = java.util.Arrays.stream(c).filter(p -> (p & 0xFFFFFF) == 0xFF0000).count();
        long green = java.util.Arrays.stream(c).filter(p -> (p & 0xFFFFFF) == 0x00FF00).count();
        assertEquals(0, red, "the depth-tested label behind the box");
        assertTrue(green > 20, "the label on top shows: " + green + " pixels");
    }

    @Test
    void aTextPanelDrawsEachCellInItsColoursAndShowsChangesInTheNextFrame() {
        TextPanel panel = new TextPanel(4, 2, new Font(Font.MONOSPACED, Font.PLAIN, 16), 0.5);
        long before = panel.object().materials().get(0).texture().argb().length;
        panel.write(1, 1, "Hi!!!", 0x00FF00, 0x0000FF);
        assertEquals('H', panel.charAt(1, 1));
        assertEquals('!', panel.charAt(3, 1));
        assertEquals(' ', panel.charAt(0, 1));
        int[] texels = panel.object().materials().get(0).texture().argb();
        assertEquals(before, texels.length);
        long green = java.util.Arrays.stream(texels).filter(t -> t == 0xFF00FF00).count();
        long blue = java.util.Arrays.stream(texels).filter(t -> t == 0xFF0000FF).count();
        long black = java.util.Arrays.stream(texels).filter(t -> t == 0xFF000000).count();
        assertTrue(green > 20 && blue > green && black > blue, green + " green, " + blue + " blue, " + black + " black");
        Scene scene = new Scene();
        scene.add(panel.object());
        long version = scene.version();
        panel.clear(0xFF0000);
        assertTrue(scene.version() > version, "a change to the panel is a change to the scene");
        int[] c = render(scene).colour();
        assertTrue(java.util.Arrays.stream(c).filter(p -> (p & 0xFFFFFF) == 0xFF0000).count() > 200);
    }
}
