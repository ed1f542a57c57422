package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import java.util.zip.CRC32;
import java.util.zip.Deflater;
import java.util.zip.DeflaterOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** Defects that only show in a separate process: signals, a missing display, a small heap. */
class ProcessRobustnessTest {
    @TempDir
    Path dir;

    /** Starts the program (or another main class of the test class path) in a new JVM. */
    static Process java(Path workDir, List<String> jvm, String main, String... args) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.addAll(jvm);
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), main));
        cmd.addAll(List.of(args));
        return new ProcessBuilder(cmd).directory(workDir.toFile()).redirectErrorStream(false).start();
    }

    private static String drain(Process p) throws Exception {
        p.getOutputStream().close();
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the process ends");
        return err;
    }

    private List<String> listing() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    @Timeout(value = 120, unit = TimeUnit.SECONDS)
    void sigtermWhileWritingRemovesTheTemporaryFilesAndChangesNoOutput() throws Exception {
        Path out = dir.resolve("big.ppm");
        Files.writeString(out, "OLD\n");
        Process p = java(dir, List.of(), "dev.trisect.io.HoldOutputs", out.toString(), dir.resolve("ready").toString());
        for (int i = 0; i < 1200 && !Files.exists(dir.resolve("ready")) && p.isAlive(); i++) {
            Thread.sleep(50);
        }
        assertTrue(Files.exists(dir.resolve("ready")), "the helper got to writing");
        assertTrue(listing().stream().anyMatch(n -> n.endsWith(".tmp")), "temporary files exist: " + listing());
        // Another run writing into the same folder cleans stale temporaries, never one in use (it is locked).
        List<String> held = listing().stream().filter(n -> n.endsWith(".tmp")).toList();
        assertEquals(0, CliRun.of("render", "--scene", "floor", "--size", "8x6", "--out",
                dir.resolve("other.png").toString()).status());
        assertTrue(listing().containsAll(held), "the running program's temporary file is kept: " + listing());
        Files.delete(dir.resolve("other.png"));
        p.destroy(); // SIGTERM
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals(List.of("big.ppm", "ready"), listing(), "no temporary file and no new output remain");
        assertEquals("OLD\n", Files.readString(out));
    }

    @Test
    @Timeout(value = 120, unit = TimeUnit.SECONDS)
    void aCommandStoppedBySigtermWhileWritingEndsWithOneLineNotAnInternalError() throws Exception {
        Path out = Files.writeString(dir.resolve("x.ppm"), "OLD");
        Process p = java(dir, List.of(), "dev.trisect.io.AbandonedBatch", out.toString());
        String stdout = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        String err = drain(p);
        assertEquals(0, p.exitValue(), err);
        String stopped = "stopped: no output was written or changed";
        assertEquals(List.of(stopped, stopped, stopped), stdout.strip().lines().toList());
        assertEquals("OLD", Files.readString(out));
        assertEquals(List.of("x.ppm"), listing(), "the hook deleted the temporary files");
    }

    @Test
    @Timeout(value = 120, unit = TimeUnit.SECONDS)
    void demoWithoutAnXServerIsOneLine() throws Exception {
        String display = ":97";
        assumeTrue(!Files.exists(Path.of("/tmp/.X11-unix/X97")), "display :97 is free");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=false", "-cp", System.getProperty("java.class.path"), "dev.trisect.Trisect", "demo"));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile());
        pb.environment().put("DISPLAY", display);
        Process p = pb.start();
        String err = drain(p);
        assertEquals(1, p.exitValue(), err);
        assertEquals(1, err.strip().lines().count(), "one line:\n" + err);
        assertTrue(err.contains(display) && err.contains("render"), err);
        assertFalse(err.contains("\tat ") || err.contains("Exception"), err);
    }

    @Test
    @Timeout(value = 300, unit = TimeUnit.SECONDS)
    void aLargeValidPngUnderASmallHeapIsReportedAsMemory() throws Exception {
        Path png = dir.resolve("big.png");
        // 8192 x 8192 RGBA texels take 256 MiB decoded: far more than the 64 MiB heap.
        writeBlankRgbaPng(png, 8192, 8192);
        Path obj = dir.resolve("m.obj");
        Files.writeString(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n");
        Process p = java(dir, List.of("-Xmx64m"), "dev.trisect.Trisect", "render", "--size", "8x8", "--obj",
                obj.toString(), "--texture", png.toString(), "--out", dir.resolve("o.png").toString());
        String err = drain(p);
        assertEquals(1, p.exitValue(), err);
        assertEquals(1, err.strip().lines().count(), "one line:\n" + err);
        assertTrue(err.contains("big.png") && err.contains("memory") && err.contains("-Xmx"), err);
        assertFalse(err.contains("corrupt"), err);
    }

    /** A valid, all-transparent 8-bit RGBA PNG, streamed so the test needs no large image in memory. */
    static void writeBlankRgbaPng(Path file, int width, int height) throws IOException {
        try (OutputStream out = Files.newOutputStream(file)) {
            out.write(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'});
            ByteArrayOutputStream ihdr = new ByteArrayOutputStream();
            DataOutputStream h = new DataOutputStream(ihdr);
            h.writeInt(width);
            h.writeInt(height);
            h.write(new byte[] {8, 6, 0, 0, 0});
            chunk(out, "IHDR", ihdr.toByteArray());
            ByteArrayOutputStream idat = new ByteArrayOutputStream();
            try (DeflaterOutputStream z = new DeflaterOutputStream(idat, new Deflater(Deflater.BEST_SPEED))) {
                byte[] row = new byte[1 + 4 * width];
                for (int y = 0; y < height; y++) {
                    z.write(row);
                }
            }
            chunk(out, "IDAT", idat.toByteArray());
            chunk(out, "IEND", new byte[0]);
        }
    }

    private static void chunk(OutputStream out, String type, byte[] data) throws IOException {
        DataOutputStream d = new DataOutputStream(out);
        d.writeInt(data.length);
        byte[] t = type.getBytes(StandardCharsets.US_ASCII);
        d.write(t);
        d.write(data);
        CRC32 crc = new CRC32();
        crc.update(t);
        crc.update(data);
        d.writeInt((int) crc.getValue());
        d.flush();
    }

    /**
     * Ctrl-C during bench kept nothing: the table was printed whole at the end (found by the command-line
     * trial). Now each row is printed when its path is measured, and the signal adds a line saying the
     * table is short, with the exit status of an interrupted program (130). The stand-in glref holds the
     * run after the first path until the test has interrupted it.
     */
    @Test
    @Timeout(value = 120, unit = TimeUnit.SECONDS)
    void benchStoppedByCtrlCKeepsTheRowsMeasuredAndSaysItWasInterrupted() throws Exception {
        Path status = Path.of("/proc/self/status");
        assumeTrue(Files.exists(status) && Files.isExecutable(Path.of("/bin/kill")), "needs Linux and /bin/kill");
        // A program started with SIGINT ignored (a background job of a shell without job control) passes
        // that on to its children, whose JVM then leaves it ignored: nothing to test there.
        String ignored = Files.readAllLines(status).stream().filter(l -> l.startsWith("SigIgn:")).findFirst()
                .orElse("SigIgn: 0").substring(7).trim();
        assumeTrue((Long.parseLong(ignored, 16) & 2) == 0, "SIGINT is ignored in this process");
        Path glref = dir.resolve("held-glref.sh");
        // Held until released, 60 s at most, so that a bench printing only at its end still ends.
        // It says when it starts: the test interrupts only then, while the run waits for it.
        Path started = dir.resolve("started");
        Files.writeString(glref, "#!/bin/sh\necho $$ > " + started + "\nfor i in $(seq 600); do [ -e " + dir.resolve("release")
                + " ] && break; sleep 0.1; done\necho 'ms_per_frame 1.0'\n");
        glref.toFile().setExecutable(true);
        // The run's own temporary folder, to see that the scene exported for glref does not outlive it.
        Path tmp = Files.createDirectory(dir.resolve("tmp"));
        Process p = java(dir, List.of("-Djava.awt.headless=true", "-Djava.io.tmpdir=" + tmp), "dev.trisect.Trisect",
                "bench", "--scene", "floor",
                "--size", "16x16", "--frames", "2", "--warmup", "0", "--threads", "1", "--modes", "affine",
                "--glref", glref.toString());
        var stdout = new java.io.BufferedReader(new java.io.InputStreamReader(p.getInputStream(),
                StandardCharsets.UTF_8));
        List<String> lines = new ArrayList<>();
        // The method's timeout guards against a hang: rows held back until glref ends would never come.
        for (String line; lines.size() < 3 && (line = stdout.readLine()) != null; ) {
            lines.add(line);
        }
        assertTrue(p.isAlive(),
                "the header and the affine row arrive while glref is held: " + lines);
        assertEquals(3, lines.size(), lines.toString());
        assertTrue(lines.get(2).startsWith("affine "), lines.toString());
        try {
            // The affine row is printed before glref is run; interrupted in between, the run could also
            // have been stopped while it prepared glref's files, which says so in a line of its own.
            while (!Files.exists(started) && p.isAlive()) {
                Thread.sleep(10);
            }
            assertTrue(Files.exists(started), "the held glref started");
            assertEquals(0, new ProcessBuilder("/bin/kill", "-INT", Long.toString(p.pid())).start().waitFor());
            String err = drain(p);
            assertEquals(130, p.exitValue(), err);
            assertEquals("trisect: interrupted after measuring 1 of 2 paths: their rows are printed, the others are "
                    + "missing", err.strip());
            assertEquals(null, stdout.readLine(), "nothing more on standard output");
            // Before, the exported scene stayed in the temporary folder and glref ran on (found by the fault probe).
            try (Stream<Path> left = Files.list(tmp)) {
                assertEquals(List.of(), left.toList(), "the temporary files of the glref run are deleted");
            }
            long glrefPid = Long.parseLong(Files.readString(started).strip());
            for (int i = 0; i < 100 && ProcessHandle.of(glrefPid).map(ProcessHandle::isAlive).orElse(false); i++) {
                Thread.sleep(50);
            }
            assertFalse(ProcessHandle.of(glrefPid).map(ProcessHandle::isAlive).orElse(false), "glref was stopped");
        } finally {
            Files.writeString(dir.resolve("release"), "");
            p.destroyForcibly();
        }
    }
}
