package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.raster.OverlayColours;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** What the view paints over a frame: the outline legend (in each path) and the split view's names (issue 18, defect 6). */
class FramePainterTest {
    private static int changed(RenderSettings render) {
        return count(render, rgb -> rgb != 0x808080);
    }

    /** Pixels of the bottom-left 200 x 100 (where the outline legend goes) that {@code test} accepts. */
    private static int count(RenderSettings render, java.util.function.IntPredicate test) {
        FrameSlot f = new FrameSlot(400, 300);
        Arrays.fill(f.frame.colour(), 0xFF808080);
        f.render = render;
        BufferedImage v = new BufferedImage(400, 300, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = v.createGraphics();
        FramePainter.paint(g, f, 400, 300, false);
        g.dispose();
        int n = 0;
        for (int y = 200; y < 300; y++) {
            for (int x = 0; x < 200; x++) {
                n += test.test(v.getRGB(x, y) & 0xFFFFFF) ? 1 : 0;
            }
        }
        return n;
    }

    @Test
    void yellowOutlinesHaveALegendToo() {
        RenderSettings yellow = RenderSettings.defaults().withBorders(true)
                .withBorderStyle(new BorderStyle(BorderStyle.Colouring.YELLOW, true));
        assertTrue(changed(yellow) > 500, "a legend in the bottom left, with no fallback piece in the frame");
        assertTrue(changed(yellow.withBorders(false)) == 0, "and none without outlines");
    }

    @Test
    void theSpanPathsLegendNamesItsTrianglesAndKnotsNotPieces() {
        for (BorderStyle.Colouring c : BorderStyle.Colouring.values()) {
            RenderSettings spans = RenderSettings.defaults().withBorders(true).withMode(RenderMode.SPANS)
                    .withBorderStyle(new BorderStyle(c, true));
            BorderLegend legend = BorderLegend.of(spans, 0);
            String words = legend.swatches().stream().map(BorderLegend.Swatch::text)
                    .collect(java.util.stream.Collectors.joining(" | ")) + " | " + legend.left() + " | " + legend.right();
            assertTrue(words.contains("knot") && words.contains("triangle outline"), c + ": " + words);
            assertFalse(words.contains("piece") || words.contains("affinely") || words.contains("per pixel"),
                    c + ": the span path fills no pieces: " + words);
            assertTrue(legend.swatches().stream().noneMatch(s -> s.colour() == OverlayColours.FALLBACK), c.toString());
            assertEquals(0, count(spans, rgb -> rgb == (OverlayColours.FALLBACK & 0xFFFFFF)), c + ": no magenta drawn");
            assertTrue(changed(spans) > 300, c + ": but a legend all the same");
            // The same settings in the tessellated path keep the pieces' legend, magenta entry included
            // when the frame has fallback pieces.
            RenderSettings pieces = spans.withMode(RenderMode.TESSELLATED);
            assertTrue(BorderLegend.of(pieces, 5).swatches().stream().anyMatch(s -> s.colour() == OverlayColours.FALLBACK),
                    c.toString());
        }
        assertTrue(BorderLegend.of(RenderSettings.defaults().withBorders(true), 3).swatches().stream()
                .anyMatch(s -> s.text().startsWith("3 pieces filled per pixel")));
    }

    @Test
    void thePerPixelAndAffinePathsLegendsNameTrianglesAndNoFallback() {
        for (RenderMode mode : new RenderMode[] {RenderMode.PERSPECTIVE, RenderMode.AFFINE}) {
            for (BorderStyle.Colouring c : BorderStyle.Colouring.values()) {
                RenderSettings r = RenderSettings.defaults().withBorders(true).withMode(mode)
                        .withBorderStyle(new BorderStyle(c, true));
                BorderLegend legend = BorderLegend.of(r, 0);
                String words = legend.swatches().stream().map(BorderLegend.Swatch::text)
                        .collect(java.util.stream.Collectors.joining(" | ")) + " | " + legend.left();
                assertFalse(words.contains("piece"), mode + " " + c + ": nothing is split: " + words);
                assertTrue(legend.swatches().stream().noneMatch(s -> s.colour() == OverlayColours.FALLBACK),
                        mode + " " + c);
                assertTrue(changed(r) > 300, mode + " " + c + ": a legend all the same");
            }
            String yellow = BorderLegend.of(RenderSettings.defaults().withBorders(true).withMode(mode)
                    .withBorderStyle(new BorderStyle(BorderStyle.Colouring.YELLOW, true)), 0).swatches().get(0).text();
            assertEquals(mode == RenderMode.AFFINE ? "triangle outline (filled affinely)"
                    : "triangle outline (filled per pixel, perspective-correct)", yellow);
        }
    }

    @Test
    void withOnlyTheFallbackPiecesOutlinedTheLegendNamesThemAlone() {
        for (RenderMode mode : RenderMode.values()) {
            RenderSettings r = RenderSettings.defaults().withBorders(true).withMode(mode)
                    .withBorderStyle(BorderStyle.fallbackOnly());
            BorderLegend legend = BorderLegend.of(r, 3);
            if (mode == RenderMode.TESSELLATED) {
                assertEquals(1, legend.swatches().size(), legend.toString());
                assertEquals(OverlayColours.FALLBACK, legend.swatches().get(0).colour());
                assertTrue(legend.swatches().get(0).text().startsWith("3 pieces filled per pixel"));
            } else {
                assertTrue(legend.swatches().isEmpty() && legend.ramp() == null, mode + ": nothing is outlined");
            }
        }
    }

    @Test
    void aFrameWithoutFallbackPiecesHasNoMagentaEntry() {
        // CubeWindow's cube, seen whole, has no fallback piece, and its legend still named magenta outlines.
        for (BorderStyle.Colouring c : BorderStyle.Colouring.values()) {
            RenderSettings r = RenderSettings.defaults().withBorders(true).withBorderStyle(new BorderStyle(c, true));
            assertTrue(BorderLegend.of(r, 0).swatches().stream().noneMatch(s -> s.colour() == OverlayColours.FALLBACK),
                    c + ": " + BorderLegend.of(r, 0));
            assertTrue(BorderLegend.of(r, 2).swatches().stream().anyMatch(s -> s.colour() == OverlayColours.FALLBACK
                    && s.text().startsWith("2 pieces filled per pixel")), c.toString());
        }
    }

    @Test
    void theErrorBoundColouringSaysWhereItsScaleComesFrom() {
        RenderSettings edge = RenderSettings.defaults().withBorders(true)
                .withBorderStyle(new BorderStyle(BorderStyle.Colouring.BOUND, true));
        String words = BorderLegend.of(edge, 0).swatches().get(0).text();
        assertTrue(words.contains("Max error, 0.500 px") && words.contains("Edge does not hold it"), words);
        RenderSettings error = edge.withTessellation(edge.tessellation().withPolicy(dev.trisect.render.SplitPolicy.ERROR));
        assertTrue(BorderLegend.of(error, 0).swatches().get(0).text().contains("the Error policy holds it"));
    }

    @Test
    void theSplitViewGivesThePerPixelPathOneName() {
        assertArrayEquals(new String[] {"per-pixel (this path)", "per-pixel (reference)"},
                FramePainter.splitLabels(RenderMode.PERSPECTIVE));
        assertArrayEquals(new String[] {"tessellated", "per-pixel"}, FramePainter.splitLabels(RenderMode.TESSELLATED));
    }
}
