package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * pick() on a frame drawn without UV output draws it again with one (32 bytes a pixel): where that does
 * not fit the heap, it refuses with a message saying what helps, never a bare OutOfMemoryError.
 */
class PickMemoryTest {
    private static String run(String heap, int side, int expectedStatus) throws Exception {
        Process p = new ProcessBuilder(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                heap, "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"),
                PickInSmallHeap.class.getName(), Integer.toString(side))).start();
        p.getOutputStream().close();
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS));
        assertEquals(expectedStatus, p.exitValue(), err);
        return err;
    }

    @Test
    void aRedrawLargerThanTheHeapIsRefusedWithWhatHelps() throws Exception {
        // 2048x2048 draws in 32 MiB (8 bytes a pixel); the redraw needs 128 MiB, more than the heap.
        String err = run("-Xmx96m", 2048, 0);
        assertTrue(err.contains("2048x2048") && err.contains("128.0 MiB") && err.contains("recordUv")
                && err.contains("-Xmx"), err);
    }

    @Test
    void aRedrawThatFitsAnswers() throws Exception {
        run("-Xmx96m", 256, 2);
    }
}
