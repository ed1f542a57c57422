package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 14, item 2: a standard output that cannot be written (a full disk, as /dev/full) ends every
 * command with one line naming the reason and exit status 1, and leaves the command's files as they
 * were. {@code ProcessRobustnessTest} checks the same through a real /dev/full.
 */
class StandardOutputTest {
    @TempDir
    Path dir;

    private String p(String name) {
        return dir.resolve(name).toString();
    }

    @Test
    void everyCommandThatPrintsFailsOnAFullStandardOutputAndKeepsItsOldFiles() throws IOException {
        List<String> old = List.of("r.png", "r.pfm", "h.png", "c.png", "d.png", "s.png", "t.png", "e.obj");
        for (String name : old) {
            Files.writeString(dir.resolve(name), "OLD " + name);
        }
        // Inputs for diff, written first.
        assertEquals(0, CliRun.of("render", "--scene", "floor", "--size", "16x12", "--out", p("a.png"), "--uv-out",
                p("a.pfm")).status());
        List<String[]> commands = new ArrayList<>(List.of(
                new String[] {"render", "--scene", "floor", "--size", "16x12", "--stats", "--out", p("r.png"), "--uv-out",
                    p("r.pfm")},
                new String[] {"compare", "--scene", "floor", "--size", "16x12", "--heatmap", p("h.png"), "--out", p("c.png")},
                new String[] {"diff", "--image", p("a.png"), "--uv", p("a.pfm"), "--reference", p("a.png"),
                    "--reference-uv", p("a.pfm"), "--heatmap", p("d.png")},
                new String[] {"export", "--scene", "floor", "--to", p("e.obj")},
                new String[] {"bench", "--scene", "floor", "--size", "16x12", "--frames", "1", "--warmup", "0", "--json"},
                new String[] {"bench", "--scene", "floor", "--size", "16x12", "--frames", "1", "--warmup", "0", "--sweep",
                    "--edges", "64", "--errors", "4", "--plot", p("s.png")},
                new String[] {"bench", "--scene", "floor", "--size", "16x12", "--frames", "2", "--warmup", "0",
                    "--target-ms", "5", "--plot", p("t.png")},
                new String[] {"render", "--list-scenes"},
                new String[] {"export", "--list-scenes"},
                new String[] {"--help"},
                new String[] {"--version"},
                new String[] {"compare", "--help"}));
        for (String[] args : commands) {
            CliRun r = CliRun.withFullStdout(args);
            String what = String.join(" ", args);
            assertEquals(1, r.status(), what + ": " + r.err());
            assertEquals("trisect: cannot write to standard output: No space left on device", r.errLine(), what);
        }
        for (String name : old) {
            assertEquals("OLD " + name, Files.readString(dir.resolve(name)), name + " is unchanged");
        }
        try (var files = Files.list(dir)) {
            List<String> left = files.map(f -> f.getFileName().toString()).sorted().toList();
            assertEquals(List.of("a.pfm", "a.png", "c.png", "d.png", "e.obj", "h.png", "r.pfm", "r.png", "s.png",
                    "t.png"), left, "no new file and no temporary file is left");
        }
    }

    @Test
    void exportListsScenesWithoutATarget() {
        CliRun list = CliRun.of("export", "--list-scenes");
        assertEquals(0, list.status(), list.err());
        assertEquals(CliRun.of("render", "--list-scenes").out(), list.out());
        CliRun none = CliRun.of("export", "--scene", "floor");
        assertEquals(2, none.status());
        assertEquals("trisect: --to FILE.obj is required", none.errLine());
    }
}
