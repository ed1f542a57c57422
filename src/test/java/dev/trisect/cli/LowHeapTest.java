package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 6's two runaway commands, each in its own JVM with a 96 MB heap: the frame piece budget
 * must end them normally, with the budget reported in the statistics. (Correctness only: the
 * timeout guards against a hang, not a speed.)
 */
class LowHeapTest {
    @TempDir
    Path dir;

    private String render(String... args) throws Exception {
        Process p = ProcessRobustnessTest.java(dir, List.of("-Xmx96m", "-Djava.awt.headless=true"),
                "dev.trisect.Trisect", args);
        p.getOutputStream().close();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the process ends");
        assertEquals(0, p.exitValue(), err);
        return out.strip();
    }

    private static void assertBudgetReached(String json) {
        assertTrue(json.contains("\"budget_reached\":true"), json);
        long budget = number(json, "piece_budget");
        assertTrue(number(json, "pieces") + number(json, "pieces_off_screen") <= budget, json);
        assertTrue(number(json, "pieces_fallback") > 0, json);
    }

    private static long number(String json, String key) {
        int i = json.indexOf("\"" + key + "\":") + key.length() + 3;
        int j = i;
        while (j < json.length() && (Character.isDigit(json.charAt(j)) || json.charAt(j) == '-')) {
            j++;
        }
        return Long.parseLong(json.substring(i, j));
    }

    @Test
    @Timeout(value = 180, unit = TimeUnit.SECONDS)
    void maxEdgeOfANanopixelEndsWithinASmallHeap() throws Exception {
        String json = render("render", "--scene", "floor", "--size", "320x240", "--max-edge", "1e-9", "--stats",
                "--out", dir.resolve("a.png").toString());
        assertBudgetReached(json);
        assertTrue(Files.size(dir.resolve("a.png")) > 0);
    }

    @Test
    @Timeout(value = 180, unit = TimeUnit.SECONDS)
    void deepUncappedSplittingOfANearPlaneTriangleEndsWithinASmallHeap() throws Exception {
        // One large triangle on the ground, reaching behind the camera: the near plane cuts it.
        Path obj = dir.resolve("big.obj");
        Files.writeString(obj, "v -50 0 20\nv 50 0 20\nv 0 0 -200\nvt 0 0\nvt 100 0\nvt 50 220\nf 1/1 2/2 3/3\n");
        String json = render("render", "--obj", obj.toString(), "--size", "320x240", "--eye", "0,1.6,0",
                "--target", "0,1,-10", "--near", "0.01", "--cull", "none", "--max-edge", "0.01", "--max-depth", "30",
                "--max-pieces", "2147483647", "--stats", "--out", dir.resolve("b.png").toString());
        assertBudgetReached(json);
        assertTrue(number(json, "clipped") == 1, "the near plane cuts the triangle: " + json);
    }
}
