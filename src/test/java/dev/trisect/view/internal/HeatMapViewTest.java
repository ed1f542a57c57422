package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.metrics.HeatMap;
import dev.trisect.metrics.HeatScale;
import dev.trisect.render.RenderMode;
import dev.trisect.render.SplitPolicy;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/** The view's heat map (the Difference view): its top, and the legend painted over it. */
class HeatMapViewTest {
    /** The newest heat map the loop draws once a measurement of {@code settings} exists. */
    private static FrameSlot heatMap(ViewSettings settings, ViewState.Measurement[] measured) throws Exception {
        ViewState state = new ViewState(DemoScenes.demo());
        state.viewSize(320, 180);
        state.settings(settings);
        state.toolsOpen(true);
        TripleBuffer buffers = new TripleBuffer();
        FrameSlot[] shown = new FrameSlot[1];
        return LoopRun.until(state, buffers, 2, "heat map", () -> {
            ViewState.Measurement m = state.measurement();
            shown[0] = buffers.acquire(shown[0]);
            FrameSlot s = shown[0];
            if (m != null && s != null && s.serial > m.frame() && s.view == ViewKind.DIFFERENCE) {
                measured[0] = m;
                return s;
            }
            return null;
        });
    }

    @Test
    void theTopIsTheFramesLargestDisplacementUntilTheUserSetsOne() throws Exception {
        ViewSettings d = ViewSettings.defaults();
        ViewSettings settings = d.withView(ViewKind.DIFFERENCE).withRender(d.render().withMode(RenderMode.TESSELLATED)
                .withTessellation(d.render().tessellation().withPolicy(SplitPolicy.ERROR).withMaxError(0.5)));
        assertTrue(settings.heatTopFitted(), "fitted by default");
        ViewState.Measurement[] m = new ViewState.Measurement[1];
        FrameSlot fitted = heatMap(settings, m);
        // A still camera: every heat map after the measurement shows the same displacements.
        assertEquals(m[0].comparison().maxDisplacement(), fitted.heatScale.maxPixels(), 1e-6,
                "the legend's top is the measured max displacement (was 2 px whatever the frame)");
        ViewSettings set = settings.withHeatScale(HeatScale.log(3));
        assertTrue(!set.heatTopFitted(), "a top the user sets is kept");
        assertEquals(HeatScale.log(3), heatMap(set, m).heatScale);
    }

    @Test
    void theLegendIsAPanelWithReadableTextAndSaysWhatBlackAndGreyMean() {
        BufferedImage image = new BufferedImage(640, 360, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, 640, 360);
        FramePainter.paintLegend(g, HeatScale.linear(2));
        g.dispose();
        assertTrue(FramePainter.LEGEND_TEXT_PX >= 12, "text of at least 12 px: " + FramePainter.LEGEND_TEXT_PX);
        int panel = 0;
        int black = 0;
        int grey = 0;
        for (int y = 0; y < 120; y++) {
            for (int x = 0; x < 640; x++) {
                int rgb = image.getRGB(x, y) | 0xFF000000;
                // The panel's colour over white at its alpha: dark, bluish, not black.
                panel += (rgb & 0xFF) < 0x60 && (rgb & 0xFF) > (rgb >> 16 & 0xFF) ? 1 : 0;
                black += rgb == HeatMap.UNCOVERED_ARGB ? 1 : 0;
                grey += rgb == HeatMap.UNDEFINED_ARGB ? 1 : 0;
            }
        }
        assertTrue(panel > 10_000, "a panel behind the legend: " + panel);
        assertTrue(black >= 25 && grey >= 25, "swatches for not drawn and not comparable: " + black + ", " + grey);
    }
}
