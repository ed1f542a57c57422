package dev.trisect.cli;

import dev.trisect.TestObjs;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Messages as docs/reading-limits.md gives them, in a process of their own: a file name the locale
 * cannot map, and running out of memory, where only what helps is suggested.
 */
class CliMessagesTest {
    @TempDir
    Path dir;

    private String run(Map<String, String> env, List<String> jvm, int status, String... args) throws Exception {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.addAll(jvm);
        cmd.addAll(List.of("-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"),
                "dev.trisect.Trisect"));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile());
        pb.environment().putAll(env);
        Process p = pb.start();
        p.getOutputStream().close();
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the process ends");
        if (status == 0) {
            assertEquals(0, p.exitValue(), err);
        } else {
            assertTrue(p.exitValue() != 0, err);
        }
        assertEquals(1, err.lines().filter(l -> !l.startsWith("OpenJDK") && !l.startsWith("trisect: note:")).count(),
                "one line: " + err);
        return err;
    }

    @Test
    void aFileNameTheLocaleCannotMapIsAnInvalidFileName() throws Exception {
        String err = run(Map.of("LANG", "C", "LC_ALL", "C"), List.of(), 2, "render", "--obj", "m\u00e4t.obj", "--out",
                "x.png");
        assertTrue(err.contains("invalid file name") && err.contains("UTF-8") && err.contains("--obj"), err);
        assertFalse(err.contains("Exception") || err.contains("interface"), err);
    }

    /**
     * A name whose bytes are not valid UTF-8 under a UTF-8 locale reaches Java with U+FFFD in their place:
     * the output was written under that other name (exit 0), and an existing input was "no such file"
     * (found by the command-line fault probe). The shell passes the raw bytes, as a user's would.
     */
    @Test
    void aFileNameThatIsNotValidUtf8IsRefusedNotRenamed() throws Exception {
        java.nio.file.Files.writeString(dir.resolve("ok.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        String javaBin = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        for (String[] option : new String[][] {{"--out", "caf\\351.png"}, {"--obj", "m\\344t.obj"}}) {
            String args = option[0].equals("--out") ? "--obj ok.obj --out \"$(printf '" + option[1] + "')\""
                    : "--obj \"$(printf '" + option[1] + "')\" --out x.png";
            ProcessBuilder pb = new ProcessBuilder("/bin/sh", "-c", "exec \"$0\" -Djava.awt.headless=true -cp \"$1\" "
                    + "dev.trisect.Trisect render --size 8x8 " + args, javaBin, System.getProperty("java.class.path"))
                    .directory(dir.toFile());
            pb.environment().putAll(Map.of("LANG", "C.UTF-8", "LC_ALL", "C.UTF-8"));
            if (option[0].equals("--obj")) {
                // The file exists under its raw name: it is the name that cannot reach it.
                new ProcessBuilder("/bin/sh", "-c", "cp ok.obj \"$(printf '" + option[1] + "')\"")
                        .directory(dir.toFile()).start().waitFor();
            }
            Process p = pb.start();
            p.getOutputStream().close();
            String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8).strip();
            assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the process ends");
            assertEquals(2, p.exitValue(), err);
            assertTrue(err.startsWith("trisect render: Invalid value for option '" + option[0] + "': invalid file name")
                    && err.contains("is not valid UTF-8") && !err.contains("\n"), err);
        }
        try (var files = java.nio.file.Files.list(dir)) {
            assertFalse(files.anyMatch(f -> f.getFileName().toString().endsWith(".png")), "no output written");
        }
    }

    @Test
    void runningOutOfMemoryWithAModelSuggestsOnlyWhatHelps() throws Exception {
        Path obj = dir.resolve("grid.obj");
        TestObjs.grid(obj, 300);
        String err = run(Map.of(), List.of("-Xmx40m"), 1, "render", "--obj", obj.toString(), "--size", "64x64",
                "--out", "g.png");
        assertTrue(err.contains("memory") && err.contains("-Xmx"), err);
        assertFalse(err.contains("--max-frame-pieces"), "lowering the frame budget cannot help: " + err);
        assertFalse(err.contains("--size"), "a 64x64 frame is not what fills the heap: " + err);
    }
}
