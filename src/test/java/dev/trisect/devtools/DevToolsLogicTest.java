package dev.trisect.devtools;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import dev.trisect.metrics.Comparison;
import dev.trisect.texture.TextureFilter;
import dev.trisect.view.internal.ViewKind;
import dev.trisect.view.internal.ViewSettings;
import dev.trisect.view.internal.ViewState;
import dev.trisect.scene.Camera;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import java.awt.Dimension;
import java.awt.Rectangle;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JLabel;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The developer tools' logic without a window: view rules, window size, sliders, copied command. */
class DevToolsLogicTest {
    @TempDir
    Path dir;

    @Test
    void theComparisonViewsTurnComparingOnAndStoppingItLeavesThem() {
        ViewSettings s = ViewSettings.defaults().withCompare(false);
        assertTrue(s.withView(ViewKind.DIFFERENCE).compare(), "the heat map needs the comparison");
        assertTrue(s.withView(ViewKind.SPLIT).compare());
        ViewSettings diff = ViewSettings.defaults().withView(ViewKind.DIFFERENCE);
        ViewSettings off = diff.withCompare(false);
        assertFalse(off.compare());
        assertEquals(ViewKind.IMAGE, off.view(), "unticking the measurement stops the heat map too");
        assertEquals(ViewKind.SPLIT, ViewSettings.defaults().withView(ViewKind.SPLIT).withCompare(true).view());
    }

    @Test
    void maxErrorSliderMapsLogarithmicallyAndRoundTrips() {
        assertEquals(0.05, SplitPolicySection.sliderToError(0), 1e-12);
        assertEquals(8, SplitPolicySection.sliderToError(1000), 1e-9);
        for (double px : new double[] {0.05, 0.1, 0.5, 1, 2, 8}) {
            assertEquals(px, SplitPolicySection.sliderToError(SplitPolicySection.errorToSlider(px)), px * 0.006);
        }
    }

    /** 299 frames of 30 ms (stages 5 + 25) and one of 2,190 ms, the spike, at {@code spikeAt}. */
    private static double[][] framesWithASpike(int spikeAt) {
        double[][] rows = new double[300][];
        for (int i = 0; i < rows.length; i++) {
            rows[i] = new double[] {5, 0, 0, 25, 0, 0, 0, 0};
        }
        rows[spikeAt] = new double[] {5, 0, 0, 2185, 0, 0, 0, 0};
        return rows;
    }

    @Test
    void oneSlowFrameDoesNotRescaleTheFrameTimeChart() {
        double[][] rows = framesWithASpike(150);
        assertEquals(50, FrameChart.topMs(rows), "1.2 x the 90th percentile, 36 ms, rounded up; not 2,190 ms");
        assertEquals(20, FrameChart.topMs(new double[][] {{3, 4}}), "never below 20 ms: the 16.7 ms line shows");
        assertEquals(20, FrameChart.topMs(new double[0][]));
        // Drawn: the ordinary frames fill most of the plot, not 2 px of it as under a 2,190 ms scale.
        FrameChart chart = new FrameChart(i -> { });
        chart.setSize(300, 170);
        chart.show(rows, -1);
        java.awt.image.BufferedImage img = new java.awt.image.BufferedImage(300, 170,
                java.awt.image.BufferedImage.TYPE_INT_RGB);
        java.awt.Graphics2D g = img.createGraphics();
        chart.paint(g);
        g.dispose();
        int raster = FrameChart.COLOURS[3].getRGB() & 0xFFFFFF;
        int tall = 0;
        for (int y = 0; y < 170; y++) {
            tall += (img.getRGB(150, y) & 0xFFFFFF) == raster ? 1 : 0;
        }
        assertTrue(tall > 40, "a 30 ms frame's raster stage is " + tall + " px tall");
    }

    @Test
    void theChartsLabelsReadOverTheBarsAndItsHeadingSaysPaused() {
        // Every frame 18 ms of raster: the bars run through the 10 ms label and the 16.7 ms one, which were
        // drawn straight over them and could not be read.
        double[][] rows = new double[300][];
        for (int i = 0; i < rows.length; i++) {
            rows[i] = new double[] {0, 0, 0, 18, 0, 0, 0, 0};
        }
        FrameChart chart = new FrameChart(i -> { });
        chart.setSize(330, 170);
        chart.show(rows, -1);
        java.awt.image.BufferedImage img = new java.awt.image.BufferedImage(330, 170,
                java.awt.image.BufferedImage.TYPE_INT_RGB);
        java.awt.Graphics2D g = img.createGraphics();
        chart.paint(g);
        g.dispose();
        int raster = FrameChart.COLOURS[3].getRGB() & 0xFFFFFF;
        double top = FrameChart.topMs(rows);
        int base = 170 - 30;
        int y10 = base - (int) Math.round(10 / top * (170 - 30 - 14));
        int throughLabel = 0;
        for (int y = y10 + 2; y <= y10 + 6; y++) {
            for (int x = 3; x < 24; x++) {
                throughLabel += (img.getRGB(x, y) & 0xFFFFFF) == raster ? 1 : 0;
            }
        }
        assertEquals(0, throughLabel, "bar pixels inside the 10 ms label");
        assertEquals("PAUSED \u2014 scale 0\u201350 ms", FrameChart.heading(true, 0, 0, 50));
        assertEquals("scale 0\u201350 ms", FrameChart.heading(false, 0, 0, 50));
    }

    @Test
    void theChartsGridSitsAtRoundMilliseconds() {
        for (double v : new double[] {0.3, 7, 20, 21, 36, 43, 85, 128, 170, 999, 2190}) {
            double top = FrameChart.roundUp(v);
            assertTrue(top >= v, v + " -> " + top);
            double step = FrameChart.gridStep(top);
            double mantissa = step / Math.pow(10, Math.floor(Math.log10(step)));
            assertTrue(Math.abs(mantissa - 1) < 1e-9 || Math.abs(mantissa - 2) < 1e-9 || Math.abs(mantissa - 5) < 1e-9,
                    "step " + step + " for top " + top);
            double lines = top / step;
            assertTrue(lines >= 4 - 1e-9 && lines <= 10 + 1e-9, lines + " grid lines for a top of " + top);
        }
        assertEquals(5, FrameChart.gridStep(20));
        assertEquals(10, FrameChart.gridStep(50));
        assertEquals("2.5", FrameChart.msText(2.5));
        assertEquals("40", FrameChart.msText(40));
    }

    @Test
    void controlsThePathDoesNotUseAreDisabledAndSayWhy() throws Exception {
        javax.swing.SwingUtilities.invokeAndWait(() -> {
            dev.trisect.view.internal.ViewController c = WindowlessController.boxes();
            DevToolsPanel panel = new DevToolsPanel(c);
            SplitPolicySection split = panel.section(SplitPolicySection.class);
            c.update(s -> s.withRender(s.render().withMode(dev.trisect.render.RenderMode.SPANS)));
            panel.syncFromSettings();
            assertFalse(split.control("Max edge").enabled(), "Max edge in the span path");
            assertTrue(split.control("Max edge").tooltip().contains("span path (4) splits nothing"),
                    split.control("Max edge").tooltip());
            assertTrue(split.control("Max error").enabled(), "the span path's knot spacing");
            assertFalse(panel.section(BudgetSection.class).autoSwitch().isEnabled(), "Auto has nothing to choose");
            c.update(s -> s.withRender(s.render().withMode(dev.trisect.render.RenderMode.TESSELLATED)));
            panel.syncFromSettings();
            assertTrue(split.control("Max edge").enabled() && split.control("Max depth").enabled());
            assertFalse(split.control("Max error").enabled(), "the Edge policy does not use Max error");
            assertTrue(split.control("Max error").tooltip().contains("choose Error"), split.control("Max error").tooltip());
            assertTrue(panel.section(BudgetSection.class).autoSwitch().isEnabled());
        });
    }


    @Test
    void everyTooltipOfTheToolsWrapsIntoShortLines() throws Exception {
        javax.swing.SwingUtilities.invokeAndWait(() -> {
            dev.trisect.view.internal.ViewController c = WindowlessController.boxes();
            List<String> tips = new ArrayList<>();
            collectTips(new DevToolsPanel(c), tips);
            assertTrue(tips.size() > 30, tips.size() + " tooltips");
            for (String tip : tips) {
                for (String line : tip.replaceAll("</?html>", "").split("<br>")) {
                    assertTrue(line.length() <= ToolsForm.TIP_LINE + 8, "a tooltip line of " + line.length()
                            + " characters: " + line);
                }
            }
        });
        assertEquals("<html>a b<br>ccc<br>&lt;d&gt;</html>", ToolsForm.wrap("a b ccc <d>", 4));
    }

    private static void collectTips(java.awt.Component c, List<String> out) {
        if (c instanceof javax.swing.JComponent j && j.getToolTipText() != null && !j.getToolTipText().isEmpty()) {
            out.add(j.getToolTipText());
        }
        if (c instanceof java.awt.Container p) {
            for (java.awt.Component child : p.getComponents()) {
                collectTips(child, out);
            }
        }
    }

    @Test
    void theCameraReadoutIsRoundedToTheMillimetre() {
        assertEquals("0.500, 1.800, -6.123", CameraSection.rounded(new Vec3(0.49999999999, 1.8000000001, -6.12345678)));
        assertEquals("0.000, 0.000, 0.000", CameraSection.rounded(new Vec3(-1e-9, 0, 1e-12)));
    }

    @Test
    void aPickedFramesStagesAddUpToItsTime() {
        String b = FrameChart.breakdown(new double[] {1, 2, 3, 4, 0, 0, 0, 0.5}, ", ");
        assertTrue(b.startsWith("10.5 ms, other 0.50, present 0.00"), b);
        assertTrue(b.endsWith("raster 4.00, tessellate 3.00, clip 2.00, transform 1.00"), b);
    }

    @Test
    void aTypedNumberMayEndInItsUnitAndAnythingElseIsNoNumber() {
        assertEquals(40.0, NumberField.parse("40", "ms"));
        assertEquals(0.25, NumberField.parse(" .25 px ", "px"));
        assertEquals(12.0, NumberField.parse("12px", "px"));
        assertEquals(1e3, NumberField.parse("1e3", "px"));
        for (String bad : new String[] {"", "x", "12 ms", "1,5", "--2", "0x10", "NaN", "Infinity", "1.2.3"}) {
            assertEquals(null, NumberField.parse(bad, "px"), bad);
        }
    }

    @Test
    void theToolsWindowDocksBesideTheViewsWindowOrOverTheViewAboveItsStatusBar() {
        Rectangle screen = new Rectangle(0, 0, 1920, 1080);
        Dimension wanted = new Dimension(420, 1000);
        // Room on the right: docked there, level with the window's top.
        Rectangle main = new Rectangle(100, 40, 1280, 767);
        Rectangle view = new Rectangle(100, 90, 1280, 690);
        assertEquals(new Rectangle(1380, 40, 420, 1000), DevToolsDock.place(main, view, wanted, screen));
        assertEquals(new Rectangle(1380, 40, 420, 1040), DevToolsDock.place(main, view, new Dimension(420, 1400),
                screen), "down to the screen's bottom edge, no further");
        // None on the right, some on the left.
        Rectangle moved = new Rectangle(600, 40, 1280, 767);
        assertEquals(new Rectangle(180, 40, 420, 1000), DevToolsDock.place(moved, view, wanted, screen));
        // The window fills the screen's width: over the view's right edge, never below the view (it once
        // ran to the screen's bottom over the status bar).
        Rectangle wide = new Rectangle(0, 0, 1920, 1080);
        Rectangle wideView = new Rectangle(0, 50, 1920, 1000);
        Rectangle over = DevToolsDock.place(wide, wideView, new Dimension(420, 1400), screen);
        assertEquals(new Rectangle(1500, 50, 420, 1000), over);
        assertTrue(over.y + over.height <= wideView.y + wideView.height, "the status bar below the view stays clear");
        assertTrue(DevToolsPanel.WHEEL_PIXELS >= 16, "a wheel notch scrolls rows, not pixels");
    }

    /** Splits a POSIX shell line into words (single quotes only, as {@link CliArgs#shellQuote} writes). */
    private static List<String> words(String line) {
        List<String> out = new ArrayList<>();
        StringBuilder w = new StringBuilder();
        boolean quoted = false;
        boolean any = false;
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (c == '\'') {
                quoted = !quoted;
                any = true;
            } else if (c == '\\' && !quoted) {
                w.append(line.charAt(++i));
            } else if (c == ' ' && !quoted) {
                if (any || w.length() > 0) {
                    out.add(w.toString());
                }
                w.setLength(0);
                any = false;
            } else {
                w.append(c);
            }
        }
        out.add(w.toString());
        return out;
    }

    @Test
    void theCopiedCommandRunsFromTheRepositoryRootWithEverySetting() {
        SceneAsset demo = DemoScenes.demo();
        SceneAsset obj = new SceneAsset("it's here", "", demo.mesh(), demo.textures(), demo.camera(),
                Path.of("my models/it's.obj"));
        ViewSettings v = ViewSettings.defaults().withRender(ViewSettings.defaults().render().withBorders(true)
                .withFilter(TextureFilter.BILINEAR));
        ViewState.Measurement m = new ViewState.Measurement(new Comparison(1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, true, 0, 0, 0),
                1, Camera.looking(new Vec3(1, 2, 3), new Vec3(0, 0, 0)), v, 320, 180, 0);
        String line = CliArgs.compareCommand(obj, m);
        assertTrue(line.startsWith("java -jar target/trisect.jar compare "), line);
        List<String> w = words(line);
        assertEquals(List.of("java", "-jar", "target/trisect.jar"), w.subList(0, 3));
        assertEquals(CliArgs.compare(obj, m), w.subList(3, w.size()), "every argument survives the shell");
        assertTrue(w.contains("my models/it's.obj"));
        assertTrue(w.contains("--borders") && w.contains("--filter") && w.contains("bilinear"), line);
    }
}
