package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * pick() on a frame drawn without its triangle ids draws it again with them (12 bytes a pixel): where that does
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
        // 3000x3000 draws in 69 MiB (8 bytes a pixel); the redraw needs 103 MiB, more than the heap.
        String err = run("-Xmx96m", 3000, 0);
        assertTrue(err.contains("3000x3000") && err.contains("103.0 MiB") && err.contains("recordIds")
                && err.contains("-Xmx"), err);
    }

    @Test
    void aRedrawThatFitsAnswers() throws Exception {
        run("-Xmx96m", 256, 2);
    }
}
