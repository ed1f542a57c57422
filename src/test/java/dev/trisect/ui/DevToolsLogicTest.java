package dev.trisect.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import dev.trisect.metrics.Comparison;
import dev.trisect.texture.TextureFilter;
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

/** The developer tools' logic without a window: view rules, status bar, screenshot folder, copied command. */
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
    void aPassingStatusMessageClearsAndTheHintComesBack() {
        JLabel label = new JLabel();
        StatusLine line = new StatusLine(label);
        line.rest("hint");
        line.pass("Copied", 1000);
        line.tick(1000 + StatusLine.PASSING_NANOS - 1);
        assertEquals("Copied", label.getText());
        assertEquals("Copied", label.getToolTipText(), "the whole message in the tooltip, should the bar cut it");
        line.tick(1000 + StatusLine.PASSING_NANOS);
        assertEquals("hint", label.getText());
        line.tick(Long.MAX_VALUE);
        assertEquals("hint", label.getText(), "the resting hint stays");
    }

    @Test
    void screenshotsGoToPicturesOrHomeNeverTheWorkingDirectory() throws Exception {
        assertEquals(dir, Screenshots.folder(dir));
        Files.createDirectory(dir.resolve("Pictures"));
        assertEquals(dir.resolve("Pictures"), Screenshots.folder(dir));
        assertNotEquals(Path.of("").toAbsolutePath(), Screenshots.folder());
        LocalDateTime t = LocalDateTime.of(2026, 1, 2, 3, 4, 5);
        Path first = Screenshots.newFile(dir, t);
        assertEquals("trisect-20260102-030405.png", first.getFileName().toString());
        Files.writeString(first, "");
        assertEquals("trisect-20260102-030405-2.png", Screenshots.newFile(dir, t).getFileName().toString());
    }

    @Test
    void theToolsWindowIsAsTallAsItsContentWhereTheScreenAllows() {
        Rectangle screen = new Rectangle(0, 0, 1920, 1080);
        assertEquals(new Dimension(420, 1000), DevToolsDialog.fit(new Dimension(420, 1000), 15, screen, 0));
        Dimension tall = DevToolsDialog.fit(new Dimension(420, 1400), 15, screen, 40);
        assertEquals(1040, tall.height, "down to the screen's bottom edge");
        assertEquals(435, tall.width, "room for the scroll bar");
        assertEquals(DevToolsDialog.MIN_WIDTH, DevToolsDialog.fit(new Dimension(100, 100), 15, screen, 0).width);
        assertTrue(DevToolsDialog.WHEEL_PIXELS >= 16, "a wheel notch scrolls rows, not pixels");
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
        DemoState.Measurement m = new DemoState.Measurement(new Comparison(1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, true, 0, 0, 0),
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
