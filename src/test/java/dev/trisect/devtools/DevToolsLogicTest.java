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

    @Test
    void theFrameTimeChartsScaleIsTheWorstFrameRoundedUp() {
        assertEquals(20, TimingSection.Graph.scaleMs(new double[][] {{3, 4}}));
        assertEquals(40, TimingSection.Graph.scaleMs(new double[][] {{30, 4}}));
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
    void theToolsWindowIsAsTallAsItsContentWhereTheScreenAllows() {
        Rectangle screen = new Rectangle(0, 0, 1920, 1080);
        assertEquals(new Dimension(420, 1000), DevToolsDialog.fit(new Dimension(420, 1000), 15, screen, 0));
        Dimension tall = DevToolsDialog.fit(new Dimension(420, 1400), 15, screen, 40);
        assertEquals(1040, tall.height, "down to the screen's bottom edge");
        assertEquals(435, tall.width, "room for the scroll bar");
        assertEquals(DevToolsPanel.MIN_WIDTH, DevToolsDialog.fit(new Dimension(100, 100), 15, screen, 0).width);
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
