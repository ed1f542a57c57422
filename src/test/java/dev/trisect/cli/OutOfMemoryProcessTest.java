package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 14, items 1 and 2, in real processes: a heap too small for the work ends every command with
 * the one-line out-of-memory message and exit 1, never a hang or a raw JVM {@code OutOfMemoryError}
 * line, and the message suggests only options the command has; a standard output on /dev/full exits 1
 * with the reason. Each case is one JVM of about a second. The collector is pinned (G1, the JVM's choice on
 * machines of 2 processors and 2 GB or more) and two render threads are asked for, so the frame fails inside the worker
 * pool on any machine.
 */
class OutOfMemoryProcessTest {
    @TempDir
    Path dir;

    /**
     * The two messages of a command that renders: the frame itself does not fit (found when it is
     * allocated), or the work in it does not; which one depends on the collector's layout of the heap.
     */
    private static final String RENDERING = "1\\|trisect: (out of memory \\(use a smaller --size, or "
            + "give Java more with -Xmx\\)|not enough memory for a \\d+x\\d+ frame \\(use a smaller --size, or give "
            + "Java more with -Xmx\\)|out of memory: the scene needs more than the heap holds \\(give Java more "
            + "with -Xmx, e\\.g\\. java -Xmx4g -jar trisect\\.jar\\))";
    private static final String OTHER = "trisect: out of memory (give Java more with -Xmx, e.g. java -Xmx4g -jar "
            + "trisect.jar)";

    /** A standard output that is closed: the program is started by a shell with {@code >&-}. */
    private static final File CLOSED = new File("closed");

    /** Runs the program with {@code heap}; returns "status|stderr". */
    private String run(String heap, File stdout, String... args) throws Exception {
        List<String> jvm = List.of("-Xmx" + heap, "-XX:+UseG1GC", "-Djava.awt.headless=true");
        List<String> cmd = new ArrayList<>();
        if (stdout == CLOSED) {
            cmd.addAll(List.of("/bin/sh", "-c", "exec \"$@\" >&-", "sh"));
        }
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.addAll(jvm);
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "dev.trisect.Trisect"));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile());
        pb.redirectOutput(stdout == null || stdout == CLOSED ? ProcessBuilder.Redirect.DISCARD
                : ProcessBuilder.Redirect.to(stdout));
        Process p = pb.start();
        p.getOutputStream().close();
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            return "hang|" + err;
        }
        return p.exitValue() + "|" + err.strip();
    }

    private static void assertRendering(String result) {
        assertTrue(result.matches(RENDERING), result);
    }

    @Test
    @Timeout(value = 300, unit = TimeUnit.SECONDS)
    void everyCommandEndsOutOfMemoryWithOneLineAndExit1() throws Exception {
        // The 4000x4000 frame (128 MB) fits in 150 MB; its render does not, in the render threads.
        assertRendering(run("150m", null, "render", "--scene", "floor", "--size", "4000x4000",
                "--threads", "2", "--out", "x.png"));
        assertRendering(run("100m", null, "render", "--scene", "sphere1m", "--threads", "2",
                "--out", "s.png"));
        assertRendering(run("150m", null, "compare", "--scene", "floor", "--size", "3000x3000",
                "--threads", "2"));
        assertRendering(run("150m", null, "bench", "--scene", "floor", "--size", "3000x3000",
                "--threads", "2", "--frames", "1", "--warmup", "0", "--sweep", "--edges", "64", "--errors", "4"));
        // Export renders nothing: its message names no render option.
        assertEquals("1|" + OTHER, run("60m", null, "export", "--scene", "sphere1m", "--to", "e/x.obj"));
        try (var left = Files.list(dir)) {
            assertEquals(List.of(), left.filter(f -> !Files.isDirectory(f)).toList(), "no output, no temporary");
        }
    }

    @Test
    @Timeout(value = 120, unit = TimeUnit.SECONDS)
    void aFullOrClosedStandardOutputExits1WithTheReasonAndChangesNoFile() throws Exception {
        File full = new File("/dev/full");
        org.junit.jupiter.api.Assumptions.assumeTrue(full.exists(), "/dev/full exists");
        Path old = Files.writeString(dir.resolve("x.png"), "OLD");
        assertEquals("1|trisect: cannot write to standard output: No space left on device", run("256m", full,
                "render", "--scene", "floor", "--size", "32x24", "--stats", "--out", old.toString()));
        assertEquals("OLD", Files.readString(old));
        assertEquals("1|trisect: cannot write to standard output: Bad file descriptor", run("256m", CLOSED,
                "compare", "--scene", "floor", "--size", "32x24", "--out", old.toString()));
        assertEquals("OLD", Files.readString(old));
    }
}
