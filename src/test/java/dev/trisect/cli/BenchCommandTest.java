package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.jr.ob.JSON;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureReader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code bench}: the fields of its JSON and the structure and values of {@code --sweep} (never timing). */
class BenchCommandTest {
    @TempDir
    Path dir;

    private static List<Map<String, Object>> jsonLines(String out) throws IOException {
        List<Map<String, Object>> rows = new ArrayList<>();
        for (String line : out.strip().split("\n")) {
            rows.add(JSON.std.mapFrom(line));
        }
        return rows;
    }

    private static double num(Map<String, Object> row, String key) {
        assertTrue(row.containsKey(key), key + " in " + row);
        Object v = row.get(key);
        return v == null ? Double.NaN : ((Number) v).doubleValue();
    }

    @Test
    void jsonHasEveryFieldPerPath() throws IOException {
        CliRun r = CliRun.of("bench", "--scene", "floor", "--size", "64x48", "--frames", "3", "--warmup", "1",
                "--threads", "2", "--json");
        assertEquals(0, r.status(), r.err());
        List<Map<String, Object>> rows = jsonLines(r.out());
        assertEquals(List.of("perspective", "affine", "tessellated", "spans"),
                rows.stream().map(m -> m.get("path")).toList());
        for (Map<String, Object> row : rows) {
            for (String key : List.of("size", "frames", "median_ms", "mean_ms", "p95_ms", "fps", "pieces", "threads",
                    "min_ms", "pixels", "pixels_written")) {
                assertTrue(row.containsKey(key), key + " in " + row);
            }
            assertEquals("64x48", row.get("size"));
            assertEquals(3, num(row, "frames"));
            assertEquals(2, num(row, "threads"));
            assertEquals(64 * 48, num(row, "pixels"));
            assertTrue(num(row, "min_ms") <= num(row, "median_ms") && num(row, "median_ms") <= num(row, "p95_ms"),
                    row.toString());
            assertTrue(num(row, "pixels_written") > 0 && num(row, "pixels_written") <= 64 * 48, row.toString());
        }
        assertTrue(num(rows.get(2), "pieces") > num(rows.get(0), "pieces"), "tessellation adds pieces");
        assertFalse(r.err().contains("bench:"), "no progress line when not in a terminal: " + r.err());
    }

    @Test
    void sweepMeasuresEveryThresholdAgainstTheReferences() throws IOException {
        Path plot = dir.resolve("sweep.png");
        CliRun r = CliRun.of("bench", "--scene", "demo", "--size", "160x90", "--frames", "1", "--warmup", "0",
                "--sweep", "--edges", "64,16,32", "--errors", "2,0.5", "--json", "--plot", plot.toString());
        assertEquals(0, r.status(), r.err());
        List<Map<String, Object>> rows = jsonLines(r.out());
        assertEquals(2 + 3 + 2 + 2 + 1, rows.size(), r.out());
        assertEquals("perspective", rows.get(0).get("path"));
        assertNull(rows.get(0).get("policy"));
        assertEquals(0, num(rows.get(0), "max_displacement"), "the reference is displaced by nothing");
        assertEquals("affine", rows.get(1).get("path"));
        List<Double> edges = new ArrayList<>();
        for (Map<String, Object> row : rows.subList(2, 5)) {
            assertEquals("tessellated", row.get("path"));
            assertEquals("edge", row.get("policy"));
            edges.add(num(row, "threshold"));
        }
        assertEquals(List.of(16.0, 32.0, 64.0), edges, "thresholds ascending");
        // Finer thresholds cut more pieces, and displace texels less than affine does.
        assertTrue(num(rows.get(2), "pieces") >= num(rows.get(3), "pieces")
                && num(rows.get(3), "pieces") >= num(rows.get(4), "pieces"), r.out());
        assertTrue(num(rows.get(2), "pieces") > num(rows.get(1), "pieces"), r.out());
        assertTrue(num(rows.get(2), "max_displacement") < num(rows.get(1), "max_displacement"), r.out());
        for (Map<String, Object> row : rows.subList(5, 7)) {
            assertEquals("error", row.get("policy"));
            double bound = num(row, "threshold");
            assertTrue(num(row, "max_displacement") <= bound, "the error bound holds: " + row);
            assertTrue(num(row, "p99_displacement") <= num(row, "max_displacement"), row.toString());
        }
        List<Double> spans = new ArrayList<>();
        for (Map<String, Object> row : rows.subList(7, 9)) {
            assertEquals("spans", row.get("path"));
            assertNull(row.get("policy"));
            spans.add(num(row, "threshold"));
            assertTrue(num(row, "max_displacement") <= num(row, "threshold") + 0.002, "the span bound holds: " + row);
            assertEquals(num(rows.get(0), "pieces"), num(row, "pieces"), "no pieces but the triangles");
        }
        assertEquals(List.of(0.5, 2.0), spans, "max errors ascending");
        Map<String, Object> summary = rows.get(9);
        assertTrue(summary.containsKey("break_even_max_edge") && summary.containsKey("break_even_max_error")
                && summary.containsKey("break_even_spans_max_error"), summary.toString());
        Texture chart = TextureReader.read(plot);
        assertEquals(1440, chart.width());
        assertEquals(480, chart.height());
    }

    @Test
    void sweepTableNamesEverySetting() {
        CliRun r = CliRun.of("bench", "--scene", "floor", "--size", "64x48", "--frames", "1", "--warmup", "0",
                "--sweep", "--edges", "32", "--errors", "1");
        assertEquals(0, r.status(), r.err());
        String out = r.out();
        for (String label : List.of("perspective", "affine", "edge 32.0", "error 1.0", "spans 1.0", "edge policy:",
                "error policy:", "spans:")) {
            assertTrue(out.contains(label), label + " in\n" + out);
        }
    }

    @Test
    void targetRunReportsEveryFrameWithinTheCeiling() throws IOException {
        Path plot = dir.resolve("budget.png");
        CliRun r = CliRun.of("bench", "--scene", "demo", "--size", "96x64", "--frames", "12", "--warmup", "0",
                "--max-edge", "40", "--target-ms", "0.001", "--orbit", "--json", "--plot", plot.toString());
        assertEquals(0, r.status(), r.err());
        List<Map<String, Object>> rows = jsonLines(r.out());
        assertEquals(12 + 1, rows.size(), r.out());
        for (int i = 0; i < 12; i++) {
            assertEquals(i, num(rows.get(i), "frame"));
            assertTrue(num(rows.get(i), "threshold") <= 40, "never looser than the ceiling: " + rows.get(i));
            assertTrue(num(rows.get(i), "pieces") > 0 && num(rows.get(i), "ms") > 0, rows.get(i).toString());
        }
        Map<String, Object> summary = rows.get(12);
        assertEquals("edge", summary.get("policy"));
        assertEquals(40, num(summary, "ceiling"));
        // A target no frame can meet keeps the threshold at the ceiling.
        assertEquals(40, num(summary, "final_threshold"));
        assertEquals(960, TextureReader.read(plot).width());
    }

    @Test
    void sweepOptionsNeedSweep() throws IOException {
        CliRun r = CliRun.of("bench", "--scene", "floor", "--plot", dir.resolve("p.png").toString());
        assertEquals(2, r.status());
        assertTrue(r.errLine().contains("--sweep"), r.err());
        assertFalse(Files.exists(dir.resolve("p.png")));
    }

    @Test
    void modeIsRefusedRatherThanIgnored() {
        // Found by the command-line trial: bench --mode affine measured all four paths, exit 0.
        CliRun r = CliRun.of("bench", "--scene", "floor", "--size", "16x16", "--frames", "1", "--warmup", "0",
                "--mode", "affine");
        assertEquals(2, r.status(), r.out());
        assertTrue(r.errLine().contains("--modes affine"), r.err());
        assertEquals("", r.out());
        // Likewise --modes where the sweep and the budget run choose their own paths.
        for (String run : new String[] {"--sweep", "--target-ms=5"}) {
            CliRun m = CliRun.of("bench", "--scene", "floor", "--size", "16x16", "--frames", "1", "--warmup", "0",
                    run, "--modes", "affine");
            assertEquals(2, m.status(), m.out());
            assertTrue(m.errLine().contains("--modes does not go with " + run.replace("=5", "")), m.err());
        }
    }

    @Test
    void glrefTimeStandsUnderTheMeanColumn() throws IOException {
        // Found by the command-line trial: glref's mean stood under "min ms" and its fps under "p95 ms".
        Path glref = dir.resolve("fake-glref.sh");
        Files.writeString(glref, "#!/bin/sh\necho 'triangles 2 frames 1 ms_per_frame 4.000'\n");
        glref.toFile().setExecutable(true);
        CliRun r = CliRun.of("bench", "--scene", "floor", "--size", "16x16", "--frames", "1", "--warmup", "0",
                "--modes", "affine", "--glref", glref.toString());
        assertEquals(0, r.status(), r.err());
        List<String> lines = r.out().lines().toList();
        String header = lines.get(1);
        String row = lines.stream().filter(l -> l.startsWith("glref")).findFirst().orElseThrow();
        assertEquals(header.indexOf("mean ms") + "mean ms".length(), row.indexOf("4.000") + "4.000".length(),
                header + "\n" + row);
        assertEquals(header.indexOf("fps") + "fps".length(), row.indexOf("250.0") + "250.0".length(),
                header + "\n" + row);
    }

    /**
     * bench and its sweep print each row when it is measured (the header first), so that Ctrl-C keeps what
     * was measured (see ProcessRobustnessTest). Shown here by a standard output that is gone: the run stops
     * at its first line, where it measured every setting first, a million frames each, before printing.
     */
    @Test
    @org.junit.jupiter.api.Timeout(value = 60, unit = java.util.concurrent.TimeUnit.SECONDS)
    void rowsArePrintedAsTheyAreMeasuredSoAClosedOutputStopsTheRunAtOnce() {
        for (String[] mode : new String[][] {{"--modes", "perspective,affine"}, {"--sweep", "--errors", "1"}}) {
            List<String> args = new ArrayList<>(List.of("bench", "--scene", "floor", "--size", "8x8", "--frames",
                    "1000000", "--warmup", "0", "--threads", "1"));
            args.addAll(List.of(mode));
            CliRun r = CliRun.withFailingStdout("Broken pipe", args.toArray(String[]::new));
            assertEquals(1, r.status(), r.err());
            assertEquals("trisect: cannot write to standard output: Broken pipe", r.errLine());
        }
    }
}
