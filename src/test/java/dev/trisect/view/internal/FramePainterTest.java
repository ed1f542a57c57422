package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.render.BorderStyle;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** What the view paints over a frame: the outline legend and the split view's names (issue 18, defect 6). */
class FramePainterTest {
    private static int changed(RenderSettings render) {
        FrameSlot f = new FrameSlot(400, 300);
        Arrays.fill(f.frame.color(), 0xFF808080);
        f.render = render;
        BufferedImage v = new BufferedImage(400, 300, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = v.createGraphics();
        FramePainter.paint(g, f, 400, 300, false);
        g.dispose();
        int n = 0;
        for (int y = 200; y < 300; y++) {
            for (int x = 0; x < 200; x++) {
                n += (v.getRGB(x, y) & 0xFFFFFF) != 0x808080 ? 1 : 0;
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
    void theSplitViewGivesThePerPixelPathOneName() {
        assertArrayEquals(new String[] {"per-pixel (this path)", "per-pixel (reference)"},
                FramePainter.splitLabels(RenderMode.PERSPECTIVE));
        assertArrayEquals(new String[] {"tessellated", "per-pixel"}, FramePainter.splitLabels(RenderMode.TESSELLATED));
    }
}
