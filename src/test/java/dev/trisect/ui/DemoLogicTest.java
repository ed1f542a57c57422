package dev.trisect.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import javax.swing.JLabel;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The demo window's logic without a window: its status bar and where screenshots go. */
class DemoLogicTest {
    @TempDir
    Path dir;

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
    void aWarningIsWithdrawnOnceTheFramesStopEarningIt() {
        JLabel label = new JLabel();
        StatusLine line = new StatusLine(label);
        line.rest("hint");
        line.warn("\u26a0 Over budget: median 23.4 ms against 16.7 ms even at your threshold (32.00 px)");
        assertTrue(label.getText().startsWith("\u26a0 Over budget"), label.getText());
        line.warn(null);
        assertEquals("hint", label.getText(), "a warning goes as soon as the frame on screen has none (issue 18)");
        line.pass("Copied", 1000);
        line.warn(null);
        assertEquals("Copied", label.getText(), "a passing message is not a warning to withdraw");
    }

    @Test
    void aPassingMessageShowsItsTimeWhileAWarningStandsThenTheWarningComesBack() {
        // The trial's steps: the cap is reached, then Ctrl+S; the frames repeat the warning 4 times a second.
        JLabel label = new JLabel();
        StatusLine line = new StatusLine(label);
        line.rest("hint");
        String cap = "\u26a0 Cap reached on 3 triangles: 41 pieces filled per pixel";
        line.warn(cap);
        assertEquals(cap, label.getText());
        line.pass("Saved screenshot to /home/u/Pictures/trisect-20261126-164000.png", 1000);
        for (int k = 0; k < StatusLine.PASSING_NANOS / 250_000_000L; k++) {
            line.tick(1000 + k * 250_000_000L);
            line.warn(k % 2 == 0 ? cap : cap + " (again)");
            assertEquals("Saved screenshot to /home/u/Pictures/trisect-20261126-164000.png", label.getText(),
                    "the warning, changed or not, waits until the message's time is up");
        }
        line.tick(1000 + StatusLine.PASSING_NANOS);
        assertEquals(cap + " (again)", label.getText(), "then the warning comes back at once, not the hint");
        line.pass("Copied", 20_000_000_000L);
        line.warn(null);
        line.tick(20_000_000_000L + StatusLine.PASSING_NANOS);
        assertEquals("hint", label.getText(), "a warning that ended meanwhile does not come back");
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
    void theStatusBarNamesThePathAndTheFilter() {
        dev.trisect.render.RenderSettings r = dev.trisect.render.RenderSettings.defaults()
                .withMode(dev.trisect.render.RenderMode.SPANS).withFilter(dev.trisect.texture.TextureFilter.BILINEAR);
        assertEquals("spans, max error 0.5 px, bilinear", PaceText.howDrawn(r, null, 0));
        assertEquals("perspective, bilinear", PaceText.howDrawn(r.withMode(dev.trisect.render.RenderMode.PERSPECTIVE),
                null, 0));
    }

    @Test
    void aScreenshotThatCannotBeSavedSaysSoAsEveryProblemDoes(@TempDir Path dir)
            throws Exception {
        Path notAFolder = Files.writeString(dir.resolve("file"), "");
        java.util.List<String> said = new java.util.concurrent.CopyOnWriteArrayList<>();
        var worker = Screenshots.save(new java.awt.image.BufferedImage(4, 4, java.awt.image.BufferedImage.TYPE_INT_RGB),
                notAFolder, said::add);
        // Bounded: the save fails at once; its message comes on the event thread after.
        for (int i = 0; i < 200 && said.size() < 2; i++) {
            Thread.sleep(10);
        }
        assertEquals(2, said.size(), said.toString());
        // It said "Could not save the screenshot: ..." where everything else says "trisect: ...".
        assertTrue(said.get(1).startsWith("trisect: cannot save the screenshot: "), said.get(1));
        assertTrue(worker.isDone());
    }

    @Test
    void aNarrowStatusBarKeepsTheRateAndTheSize() {
        String pace = "tessellated, edge 32 px, trilinear  idle, last frame 45.5 ms  400x253";
        assertEquals(pace, PaceText.fit(pace, String::length, pace.length()), "whole where it fits");
        assertEquals("idle, last frame 45.5 ms  400x253", PaceText.fit(pace, String::length, 40),
                "without how frames are drawn where it does not");
    }

    @Test
    void aStillViewsStatusBarSaysIdleWithTheLastFramesTimeNotZeroFps() {
        dev.trisect.render.RenderSettings r = dev.trisect.render.RenderSettings.defaults();
        dev.trisect.view.FrameInfo one = new dev.trisect.view.FrameInfo(1, 640, 360, null, r, null, 23.45, 0, null);
        // One frame, then none: the rate was never worked out, and "0 fps" said the view was stuck.
        assertEquals("tessellated, edge 32 px, nearest  idle, last frame 23.5 ms  640x360",
                PaceText.pace(r, one, 2_000_000_000L, 0, false));
        assertEquals("tessellated, edge 32 px, nearest  23.5 ms a frame  640x360",
                PaceText.pace(r, one, 10_000_000L, 0, false), "frames coming, but not for a second yet");
        // Slow frames (1.5 s each on a loaded machine) are being drawn, not idle.
        dev.trisect.view.FrameInfo slow = new dev.trisect.view.FrameInfo(7, 640, 360, null, r, null, 1500, 0.7, null);
        assertEquals("tessellated, edge 32 px, nearest  0.7 fps  640x360", PaceText.pace(r, slow, 1_200_000_000L, 0,
                false));
        // Slower still: a rate, not "0 fps".
        dev.trisect.view.FrameInfo slower = new dev.trisect.view.FrameInfo(7, 640, 360, null, r, null, 690, 0.4, null);
        assertEquals("tessellated, edge 32 px, nearest  0.4 fps  640x360", PaceText.pace(r, slower, 600_000_000L, 0,
                false));
        dev.trisect.view.FrameInfo flowing = new dev.trisect.view.FrameInfo(90, 640, 360, null, r, null, 10, 59.6, null);
        assertEquals("tessellated, edge 32 px, nearest  60 fps  640x360", PaceText.pace(r, flowing, 10_000_000L, 0,
                false));
        assertEquals("tessellated, edge 32 px, nearest  FROZEN at frame 90  640x360", PaceText.pace(r, flowing,
                5_000_000_000L, 0, true));
    }

    @Test
    void theStatusBarNamesTheSplitPolicyBesidePathAndFilter() {
        dev.trisect.render.RenderSettings r = dev.trisect.render.RenderSettings.defaults();
        assertEquals("tessellated, edge 32 px, nearest", PaceText.howDrawn(r, null, 0));
        dev.trisect.render.RenderSettings error = r.withTessellation(r.tessellation()
                .withPolicy(dev.trisect.render.SplitPolicy.ERROR).withMaxError(0.5));
        assertEquals("tessellated, error 0.5 px, nearest", PaceText.howDrawn(error, null, 0));
        // Under Auto, the threshold the newest frame was drawn with, and that Auto chose it.
        dev.trisect.render.RenderSettings drawn = r.withTessellation(r.tessellation().withMaxEdge(14.635));
        assertEquals("tessellated, edge 14.635 px (auto), nearest", PaceText.howDrawn(r, drawn, 40));
        // P's message, with the key of the path that uses the policy when another shows.
        assertEquals("Split policy: Error (split while an edge's affine error bound is over 0.5 px)",
                PaceText.policyChanged(error));
        assertTrue(PaceText.policyChanged(r.withMode(dev.trisect.render.RenderMode.SPANS))
                .endsWith("; the tessellated path (3) uses it"));
    }
    @Test
    void menuTooltipsWrap() {
        String tip = DemoMenus.wrapped("Show what the pixel under the mouse is made of (click to pin it): triangle, piece, "
                + "split level, depth, texel coordinates in both paths, exact displacement & more");
        for (String line : tip.replaceAll("</?html>", "").split("<br>")) {
            assertTrue(line.length() <= 64 + 4, line);
        }
        assertTrue(tip.contains("&amp; more") && tip.startsWith("<html>Show what"), tip);
    }
    @Test
    void mvnExecJavaEndsWhenTheWindowsClose() throws Exception {
        // exec:java interrupts daemon threads and waits up to 15 s for each to die unless told not to;
        // an idle SwingWorker thread ignores the interrupt (16.6 s measured; scripts/exec-linger.sh).
        String pom = Files.readString(Path.of("pom.xml"));
        int plugin = pom.indexOf("<artifactId>exec-maven-plugin</artifactId>");
        assertTrue(plugin > 0);
        String config = pom.substring(plugin, pom.indexOf("</configuration>", plugin));
        assertTrue(config.contains("<cleanupDaemonThreads>false</cleanupDaemonThreads>"), config);
    }
    @Test
    void recentFilesAreRememberedNewestFirstAcrossRunsWithTheirFolder() throws Exception {
        Path store = dir.resolve("cfg/demo.properties");
        RecentFiles r = new RecentFiles(store);
        assertEquals(java.util.List.of(), r.files());
        Path models = Files.createDirectory(dir.resolve("models"));
        for (int i = 0; i < RecentFiles.MAX + 2; i++) {
            r.opened(models.resolve("m" + i + ".obj"));
        }
        r.opened(models.resolve("m3.obj"));
        RecentFiles again = new RecentFiles(store);
        assertEquals(RecentFiles.MAX, again.files().size(), "at most " + RecentFiles.MAX);
        assertEquals(models.resolve("m3.obj"), again.files().get(0), "the newest first, once");
        assertEquals(models.resolve("m9.obj"), again.files().get(1));
        assertEquals(models, again.folder(), "Open OBJ opens where it was last");
        again.forget(models.resolve("m3.obj"));
        assertEquals(models.resolve("m9.obj"), new RecentFiles(store).files().get(0));
        again.clear();
        assertEquals(java.util.List.of(), new RecentFiles(store).files());
        Files.writeString(store, "open-folder=\\u00zz broken");
        assertEquals(Path.of("").toAbsolutePath(), new RecentFiles(store).folder(), "a broken file only forgets");
    }

    @Test
    void aLoadWithNotesSaysSoInTheStatusBar() {
        assertEquals("Loaded m.obj (2 triangles)", FileMenu.loaded(Path.of("m.obj"), 2, java.util.List.of()));
        assertEquals("Loaded m.obj (1 triangle)", FileMenu.loaded(Path.of("m.obj"), 1, java.util.List.of()));
        // A placeholder texture's warning stays in the bar after the load message has gone.
        assertEquals(null, FileMenu.standingNote(java.util.List.of()));
        String note = FileMenu.standingNote(java.util.List.of("m.mtl:2: map_Kd: gone", "x"));
        assertEquals("\u26a0 m.mtl:2: map_Kd: gone (and 1 more)", note);
        JLabel bar = new JLabel();
        StatusLine line = new StatusLine(bar);
        line.rest(note);
        line.pass("Loaded m.obj (2 triangles)", 1000);
        line.tick(1000 + StatusLine.PASSING_NANOS);
        assertEquals(note, bar.getText());
        assertEquals("Loaded m.obj (2 triangles). \u26a0 m.mtl:2: map_Kd: gone (and 1 more)",
                FileMenu.loaded(Path.of("m.obj"), 2, java.util.List.of("m.mtl:2: map_Kd: gone", "x")));
    }

    @Test
    void aModelPartWithoutAFinitePlaceGetsNoLabelAndTheOthersDo() throws Exception {
        // The OBJ reader keeps NaN coordinates (the renderer skips their triangles): the part's box is NaN,
        // and a label there would be refused, so X must leave it unlabelled rather than fail.
        Path obj = Files.writeString(dir.resolve("nan.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\n"
                + "usemtl good\nf 1 2 3\nusemtl bad\nf 1 2 4\n");
        dev.trisect.scene.Scene scene = new dev.trisect.scene.Scene();
        scene.add(dev.trisect.scene.SceneObject.load(obj));
        assertEquals(java.util.Set.of("good"), DemoShapes.landmarks(scene).keySet());
        assertTrue(DemoShapes.extrasFor(scene, dev.trisect.scene.Camera.looking(new dev.trisect.math.Vec3(0, 0, 3),
                dev.trisect.math.Vec3.ZERO)).size() >= 3, "axes, pane and labels");
    }
}
