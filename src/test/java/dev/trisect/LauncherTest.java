package dev.trisect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.base.InputException;
import dev.trisect.io.Faults;
import dev.trisect.ui.ReportFile;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The entry point as a user starts it, in a separate JVM without a display. */
class LauncherTest {
    private record Run(int status, String out, String err) {
    }

    private static Run launch(String... args) throws IOException, InterruptedException {
        return launchWith(System.getProperty("java.class.path"), args);
    }

    private static Run launchWith(String classPath, String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "-cp", classPath, Trisect.class.getName()));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd);
        pb.environment().remove("DISPLAY");
        Process p = pb.start();
        // Hang guard only.
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the launcher ended");
        return new Run(p.exitValue(), new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8),
                new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8));
    }

    @Test
    void theLibraryAloneSaysOneLineNamingTheMissingLibraries() throws Exception {
        // The class path of the installed artifact's consumer: the library and its required dependencies,
        // without the optional application libraries (picocli, FlatLaf, XChart).
        List<String> kept = new ArrayList<>();
        for (String entry : System.getProperty("java.class.path").split(java.io.File.pathSeparator)) {
            String name = Path.of(entry).getFileName().toString();
            if (!name.startsWith("picocli") && !name.startsWith("flatlaf") && !name.startsWith("xchart")) {
                kept.add(entry);
            }
        }
        for (String[] args : new String[][] {{"--version"}, {}, {"render", "--scene", "demo", "--out", "x.png"}}) {
            Run r = launchWith(String.join(java.io.File.pathSeparator, kept), args);
            assertEquals(1, r.status(), r.err());
            String err = r.err().strip();
            assertFalse(err.contains("\n") || err.contains("Exception") || err.contains("Error"), "one clean line: " + err);
            assertTrue(err.startsWith("trisect: picocli, FlatLaf, XChart not found: this is the library jar"), err);
        }
    }

    @Test
    void withoutADisplayTheDemoSaysOneLinePointingToRender() throws Exception {
        Run r = launch();
        assertEquals(1, r.status());
        String err = r.err().strip();
        assertFalse(err.contains("\n") || err.contains("Exception"), "one clean line: " + r.err());
        assertTrue(err.contains("no display") && err.contains("render"), err);
    }

    @Test
    void demoOptionsAreCheckedAndHelpWorksWithoutADisplay() throws Exception {
        Run help = launch("demo", "--help");
        assertEquals(0, help.status(), help.err());
        assertTrue(help.out().contains("--soak") && help.out().contains("--render-scale"), help.out());
        Run bad = launch("demo", "--render-scale", "5");
        assertEquals(2, bad.status(), bad.err());
        assertEquals("trisect: --render-scale must be between 0.25 and 1, got 5.0", bad.err().strip());
        // 0 is refused: the message read "between 0 and 1000", which 0 is (found by the demo trial).
        Run zero = launch("demo", "--target-ms", "0");
        assertEquals(2, zero.status(), zero.err());
        assertEquals("trisect: --target-ms must be more than 0 and at most 1000 milliseconds, got 0.0",
                zero.err().strip());
    }

    @Test
    void helpListsTheDemoAndTheDemosUsageNamesTheProgram() throws Exception {
        Run help = launch("--help");
        assertEquals(0, help.status(), help.err());
        assertTrue(help.out().lines().anyMatch(l -> l.strip().startsWith("demo ")), help.out());
        Run demo = launch("demo", "--help");
        assertTrue(demo.out().startsWith("Usage: trisect demo "), demo.out());
    }

    @Test
    void theDemoPrintsTheVersionAsEveryCommandDoes() throws Exception {
        // Found by the command-line trial: trisect demo --version printed nothing, exit 0.
        Run root = launch("--version");
        assertEquals(0, root.status(), root.err());
        assertTrue(root.out().startsWith("trisect "), root.out());
        Run demo = launch("demo", "--version");
        assertEquals(0, demo.status(), demo.err());
        assertEquals(root.out(), demo.out());
    }

    @Test
    void theDemoNamesABadSceneAndRefusesObjWithSceneBeforeLookingForADisplay() throws Exception {
        // Found by the command-line trial: demo --scene nope said only "no display"; --obj with --scene
        // opened the OBJ and dropped the scene.
        Run bad = launch("demo", "--scene", "nope");
        assertEquals(2, bad.status(), bad.err());
        assertTrue(bad.err().strip().startsWith("trisect: unknown scene 'nope'"), bad.err());
        Run both = launch("demo", "--obj", "m.obj", "--scene", "demo");
        assertEquals(2, both.status(), both.err());
        assertEquals("trisect: --obj and --scene both name what to open; give one of them", both.err().strip());
    }

    @Test
    void argumentsRunTheCommandLine() throws Exception {
        Run r = launch("render", "--list-scenes");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("floor"));
        Run bad = launch("render", "--size", "0x0");
        assertEquals(2, bad.status());
        assertTrue(bad.err().strip().startsWith("trisect render:"), bad.err());
    }

    @Test
    void theSoakReportIsCheckedBeforeTheSoakAndRefusedWithoutIt() throws Exception {
        Run alone = launch("demo", "--report", "r.json");
        assertEquals(2, alone.status(), alone.err());
        assertEquals("trisect: --report goes with --soak", alone.err().strip());
        Run folder = launch("demo", "--soak", "1", "--report", "r.json/");
        assertEquals(2, folder.status(), folder.err());
        assertEquals("trisect: --report 'r.json/' ends with a separator, so it names a directory: give the name of "
                + "the file to write", folder.err().strip());
        // Checked before anything else, the display included (this JVM has none).
        Path missing = Path.of("/nonexistent-trisect/r.json");
        Run bad = launch("demo", "--soak", "1", "--report", missing.toString());
        assertEquals(1, bad.status(), bad.err());
        assertEquals("trisect: " + missing + ": cannot write: no such directory " + missing.getParent(),
                bad.err().strip());
    }

    @Test
    void demoHelpOnAFullStandardOutputFails() throws Exception {
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.exists(Path.of("/dev/full")), "needs /dev/full");
        ProcessBuilder pb = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"), Trisect.class.getName(),
                "demo", "--help").redirectOutput(new java.io.File("/dev/full"));
        Process p = pb.start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the launcher ended");
        assertEquals(1, p.exitValue());
        assertEquals("trisect: cannot write to standard output",
                new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8).strip());
    }

    @Test
    void theSoakReportIsWrittenAllOrNothing(@TempDir Path dir) throws IOException {
        Path report = Files.writeString(dir.resolve("r.json"), "OLD");
        InputException directory = assertThrows(InputException.class, () -> Trisect.openReport(dir));
        assertEquals(dir + ": cannot write: it is a directory", directory.getMessage());
        try (ReportFile file = Trisect.openReport(report)) {
            Faults.fullDiskAt(1);
            InputException full = assertThrows(InputException.class, () -> file.write("{\"new\":1}\n"));
            assertEquals(report + ": cannot write: No space left on device", full.getMessage());
        } finally {
            Faults.clear();
        }
        assertEquals("OLD", Files.readString(report));
        try (ReportFile file = Trisect.openReport(report)) {
            file.write("{\"new\":1}\n");
        }
        assertEquals("{\"new\":1}\n", Files.readString(report));
        try (var files = Files.list(dir)) {
            assertEquals(List.of(report), files.toList(), "no temporary file is left");
        }
    }
}
