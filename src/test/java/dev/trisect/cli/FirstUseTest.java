package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.texture.TextureReader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** What a new user runs into first: messages, defaults that match the demo, outputs in new folders. */
class FirstUseTest {
    @TempDir
    Path dir;

    @Test
    void anUnknownCommandIsNamedWithoutAStraySpace() {
        CliRun r = CliRun.of("bogus");
        assertEquals(2, r.status());
        assertTrue(r.errLine().startsWith("trisect: Unmatched argument"), r.err());
        assertTrue(r.errLine().endsWith("(see trisect --help)"), r.err());
        CliRun sub = CliRun.of("render", "--bogus");
        assertTrue(sub.errLine().startsWith("trisect render: "), sub.err());
    }

    @Test
    void theDemoSceneHasTheDemosSkyUnlessABackgroundIsGiven() throws IOException {
        Path sky = dir.resolve("sky.png");
        assertEquals(0, CliRun.of("render", "--scene", "demo", "--size", "64x36", "--out", sky.toString()).status());
        assertEquals(0xFF9DB8D3, TextureReader.read(sky).argb()[0], "top-left is sky, as in the desktop demo");
        Path red = dir.resolve("red.png");
        assertEquals(0, CliRun.of("render", "--scene", "demo", "--size", "64x36", "--background", "FF0000",
                "--out", red.toString()).status());
        assertEquals(0xFFFF0000, TextureReader.read(red).argb()[0]);
        Path floor = dir.resolve("floor.png");
        assertEquals(0, CliRun.of("render", "--scene", "floor", "--size", "64x36", "--out", floor.toString()).status());
        assertEquals(0xFF000000, TextureReader.read(floor).argb()[0], "the other scenes stay on black");
    }

    @Test
    void exportCreatesTheFolderItWritesInto() {
        Path obj = dir.resolve("new/deeper/x.obj");
        CliRun r = CliRun.of("export", "--scene", "floor", "--to", obj.toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(Files.isRegularFile(obj));
        assertTrue(Files.isRegularFile(dir.resolve("new/deeper/x.mtl")));
    }

    @Test
    void aFailedExportLeavesNoFolderBehind() throws IOException {
        Files.createDirectories(dir.resolve("kept"));
        Path obj = dir.resolve("kept/new/deeper/x.obj");
        CliRun r = CliRun.of("export", "--scene", "no-such-scene", "--to", obj.toString());
        assertTrue(r.status() != 0, r.err());
        assertFalse(Files.exists(dir.resolve("kept/new")), "the folders made for the export are gone again");
        assertTrue(Files.isDirectory(dir.resolve("kept")), "a folder that was there stays");
        // Named with . and .. the same folders are made, and removed.
        CliRun dotted = CliRun.of("export", "--scene", "no-such-scene", "--to",
                dir.resolve("kept/a/./b/../c/x.obj").toString());
        assertTrue(dotted.status() != 0, dotted.err());
        assertFalse(Files.exists(dir.resolve("kept/a")), "kept/a/c made and removed");
    }

    @Test
    void exportBlockedByAFileSaysSoInOneLine() throws IOException {
        Files.writeString(dir.resolve("file"), "x");
        CliRun r = CliRun.of("export", "--scene", "floor", "--to", dir.resolve("file/x.obj").toString());
        assertEquals(1, r.status());
        assertTrue(r.errLine().contains("cannot create the directory"), r.err());
    }
}
