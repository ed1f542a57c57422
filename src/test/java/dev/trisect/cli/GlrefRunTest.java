package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.base.InputException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * bench's --glref program misbehaving: each way gets one line naming the program and what it did, exit
 * status 1, never an internal error or a hang (found by the command-line fault probe: a silent failure
 * said "failed: " and nothing more, a garbled time was an internal error with status 3, a time of 0 gave
 * "Infinity" fps, and a program that hung held bench forever, its 10-minute limit never reached).
 */
class GlrefRunTest {
    @TempDir
    Path dir;

    private Path script(String name, String body) throws IOException {
        Path p = dir.resolve(name);
        Files.writeString(p, "#!/bin/sh\n" + body + "\n");
        assertTrue(p.toFile().setExecutable(true));
        return p;
    }

    private CliRun bench(Path glref) {
        return CliRun.of("bench", "--scene", "floor", "--size", "16x16", "--frames", "1", "--warmup", "0",
                "--modes", "affine", "--glref", glref.toString());
    }

    @Test
    void aSilentFailureSaysItsExitStatus() throws IOException {
        Path glref = script("silent.sh", "exit 3");
        CliRun r = bench(glref);
        assertEquals(1, r.status(), r.err());
        assertEquals("trisect: " + glref + ": failed with exit status 3 and printed nothing", r.errLine());
        assertTrue(r.out().lines().anyMatch(l -> l.startsWith("affine ")), "the measured row stays: " + r.out());
    }

    @Test
    void aFailureQuotesTheLastLineOfItsOutputShortened() throws IOException {
        Path glref = script("noisy.sh", "i=0; while [ $i -lt 2000 ]; do echo \"line $i\"; i=$((i+1)); done\n"
                + "printf 'cannot open display: %0300d\\n' 0\nexit 1");
        CliRun r = bench(glref);
        assertEquals(1, r.status(), r.err());
        String line = r.errLine();
        assertTrue(line.startsWith("trisect: " + glref + ": failed with exit status 1: cannot open display: 000"),
                line);
        assertTrue(line.endsWith("...") && line.length() < 300, line);
    }

    @Test
    void aTimeThatIsNotAPositiveNumberIsRefusedInOneLine() throws IOException {
        for (String ms : List.of("1.2.3", ".", "0", "0.000", "-4", "NaN", "Infinity", "1e400")) {
            Path glref = script("bad-time.sh", "echo 'triangles 2 frames 1 ms_per_frame " + ms + "'");
            CliRun r = bench(glref);
            assertEquals(1, r.status(), ms + ": " + r.err());
            assertEquals("trisect: " + glref + ": printed ms_per_frame '" + ms + "', not a positive number of "
                    + "milliseconds", r.errLine());
        }
        Path glref = script("no-time.sh", "echo 'triangles 2 frames 1'");
        CliRun r = bench(glref);
        assertEquals(1, r.status(), r.err());
        assertEquals("trisect: " + glref + ": printed no ms_per_frame: triangles 2 frames 1", r.errLine());
    }

    @Test
    @Timeout(value = 60, unit = TimeUnit.SECONDS)
    void aProgramThatHangsIsStoppedAtTheLimitWithItsChildren() throws Exception {
        Path pid = dir.resolve("pid");
        Path glref = script("hang.sh", "echo working\nsleep 300 &\necho $! > " + pid + "\nwait");
        Path folder;
        try (GlrefRun run = new GlrefRun(glref, 1500)) {
            folder = run.dir();
            InputException e = assertThrows(InputException.class, () -> run.meanMs(d -> List.of(), Map.of()));
            assertEquals(glref + ": did not finish in 2 seconds; stopped it: working", e.getMessage());
        }
        long sleeper = Long.parseLong(Files.readString(pid).strip());
        for (int i = 0; i < 100 && ProcessHandle.of(sleeper).map(ProcessHandle::isAlive).orElse(false); i++) {
            Thread.sleep(50);
        }
        assertFalse(ProcessHandle.of(sleeper).map(ProcessHandle::isAlive).orElse(false), "its child was stopped too");
        assertFalse(Files.exists(folder), "the temporary folder is deleted");
    }

    @Test
    void theTemporaryFolderGoesWhateverTheOutcome() throws IOException {
        Path glref = script("ok.sh", "echo 'ms_per_frame 2.5'");
        Path folder;
        try (GlrefRun run = new GlrefRun(glref)) {
            folder = run.dir();
            assertEquals(2.5, run.meanMs(d -> List.of(Files.writeString(d.resolve("scene.obj"), "v 0 0 0\n")
                    .toString()), Map.of("GLREF_FILTER", "nearest")));
        } catch (InterruptedException e) {
            throw new AssertionError(e);
        }
        assertFalse(Files.exists(folder), folder.toString());
    }

    /**
     * Only the end of glref's output is read: a program that printed 100 MB before its time ran a bench
     * with a 48 MB heap out of memory.
     */
    @Test
    @Timeout(value = 120, unit = TimeUnit.SECONDS)
    void aProgramThatPrintsAGreatDealIsReadFromItsEnd() throws Exception {
        Path glref = script("chatty.sh", "head -c 100000000 /dev/zero | tr '\\0' x\necho\necho 'ms_per_frame 2.5'");
        Process p = ProcessRobustnessTest.java(dir, List.of("-Xmx48m", "-Djava.awt.headless=true"),
                "dev.trisect.Trisect", "bench", "--scene", "floor", "--size", "16x16", "--frames", "1", "--warmup", "0",
                "--threads", "1", "--modes", "affine", "--glref", glref.toString());
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        String err = new String(p.getErrorStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        assertTrue(p.waitFor(100, TimeUnit.SECONDS));
        assertEquals(0, p.exitValue(), err);
        assertTrue(out.lines().anyMatch(l -> l.startsWith("glref") && l.contains(" 2.500 ")), out);
    }

    /** A model of lines alone (no material, so no texture) was an internal error, status 3, with --glref. */
    @Test
    void aModelOfLinesAloneIsTimedToo() throws IOException {
        Path obj = Files.writeString(dir.resolve("lines.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3 1\n");
        // Times only when given a texture file that exists, as glref needs one.
        Path glref = script("lines.sh", "[ -f \"$2\" ] && echo 'ms_per_frame 2.0'");
        CliRun r = CliRun.of("bench", "--obj", obj.toString(), "--size", "16x16", "--frames", "1", "--warmup", "0",
                "--modes", "affine", "--glref", glref.toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().lines().anyMatch(l -> l.startsWith("glref") && l.contains(" 2.000 ")), r.out());
    }
}
