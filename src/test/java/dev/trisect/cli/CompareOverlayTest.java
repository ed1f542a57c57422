package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.texture.TextureReader;
import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code compare --borders} measures the rendered image, never the yellow overlay drawn over it. */
class CompareOverlayTest {
    @TempDir
    Path dir;

    @Test
    void bordersChangeTheOutImageButNotOneNumber() throws IOException {
        String[] args = {"compare", "--scene", "demo", "--size", "320x180", "--split", "error", "--max-error", "0.5"};
        CliRun plain = CliRun.of(args);
        Path out = dir.resolve("b.png");
        String[] withBorders = java.util.Arrays.copyOf(args, args.length + 3);
        withBorders[args.length] = "--borders";
        withBorders[args.length + 1] = "--out";
        withBorders[args.length + 2] = out.toString();
        CliRun borders = CliRun.of(withBorders);
        assertEquals(0, plain.status() + borders.status(), borders.err());
        assertEquals(plain.out(), borders.out(), "the overlay is not measured");
        int yellow = 0;
        for (int p : TextureReader.read(out).argb()) {
            yellow += p == 0xFFFFFF00 ? 1 : 0;
        }
        assertTrue(yellow > 1000, "the --out image still shows the borders: " + yellow);
    }

    @Test
    void heatmapsCarryTheirLegendAndTheScaleCanBeLogarithmic() throws IOException {
        Path lin = dir.resolve("lin.png");
        Path log = dir.resolve("log.png");
        assertEquals(0, CliRun.of("compare", "--scene", "floor", "--size", "320x180", "--mode", "affine",
                "--heatmap", lin.toString(), "--heatmap-max", "1000").status());
        assertEquals(0, CliRun.of("compare", "--scene", "floor", "--size", "320x180", "--mode", "affine",
                "--heatmap", log.toString(), "--heatmap-max", "1000", "--heatmap-scale", "log").status());
        int[] a = TextureReader.read(lin).argb();
        int[] b = TextureReader.read(log).argb();
        assertEquals(0xFFFFFFFF, a[8 * 320 + 8 + 149], "the legend's bar ends white");
        java.util.Set<Integer> linColours = new java.util.HashSet<>();
        java.util.Set<Integer> logColours = new java.util.HashSet<>();
        for (int i = 60 * 320; i < a.length; i++) {
            linColours.add(a[i]);
            logColours.add(b[i]);
        }
        assertTrue(logColours.size() > linColours.size() + 20, "log spreads the floor's errors over more colours: "
                + logColours.size() + " vs " + linColours.size());
        CliRun bad = CliRun.of("compare", "--scene", "floor", "--heatmap-scale", "cubic", "--heatmap", lin.toString());
        assertEquals(2, bad.status());
        assertTrue(bad.errLine().contains("--heatmap-scale must be linear or log"), bad.err());
    }

    /** Without --heatmap-max the top is the frame's largest displacement: its worst pixel is white. */
    @Test
    void theHeatMapsTopIsTheLargestDisplacementByDefault() throws IOException {
        String[] frame = {"compare", "--scene", "floor", "--size", "320x180", "--split", "error", "--max-error", "0.5"};
        Path fitted = dir.resolve("fitted.png");
        CliRun run = CliRun.of(cat(frame, "--heatmap", fitted.toString()));
        assertEquals(0, run.status(), run.err());
        java.util.regex.Matcher max = java.util.regex.Pattern.compile("\"max_displacement\":([0-9.eE-]+)")
                .matcher(run.out());
        assertTrue(max.find(), run.out());
        Path atMax = dir.resolve("at-max.png");
        Path atTwo = dir.resolve("at-two.png");
        assertEquals(0, CliRun.of(cat(frame, "--heatmap", atMax.toString(), "--heatmap-max", max.group(1))).status());
        assertEquals(0, CliRun.of(cat(frame, "--heatmap", atTwo.toString(), "--heatmap-max", "2")).status());
        int[] byDefault = TextureReader.read(fitted).argb();
        assertTrue(java.util.Arrays.equals(TextureReader.read(atMax).argb(), byDefault),
                "the default top is the printed max_displacement, " + max.group(1));
        // The old default, 2 px, left this 0.5 px-bounded frame in the ramp's dark third.
        assertFalse(java.util.Arrays.equals(TextureReader.read(atTwo).argb(), byDefault));
    }

    private static String[] cat(String[] a, String... b) {
        String[] out = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }

    @Test
    void namedValuesIgnoreCaseAndHeatMapOptionsNeedTheHeatMap() throws IOException {
        Path heat = dir.resolve("heat.png");
        CliRun upper = CliRun.of("compare", "--scene", "floor", "--size", "32x24", "--heatmap", heat.toString(),
                "--heatmap-scale", "LOG");
        assertEquals(0, upper.status(), upper.err());
        CliRun colour = CliRun.of("render", "--scene", "floor", "--size", "32x24", "--borders", "--border-colour",
                "Depth", "--out", dir.resolve("b.png").toString());
        assertEquals(0, colour.status(), colour.err());
        for (String option : new String[] {"--heatmap-scale", "--heatmap-max"}) {
            CliRun alone = CliRun.of("compare", "--scene", "floor", "--size", "32x24", option,
                    option.endsWith("scale") ? "log" : "3");
            assertEquals(2, alone.status(), alone.err());
            assertEquals("trisect: " + option + " needs --heatmap", alone.errLine());
        }
    }

    @Test
    void renderColoursBordersByDepthOrBoundAndRefusesOtherColourings() throws IOException {
        Path depth = dir.resolve("depth.png");
        CliRun r = CliRun.of("render", "--scene", "floor", "--size", "320x180", "--split", "error", "--borders",
                "--border-colour", "depth", "--out", depth.toString());
        assertEquals(0, r.status(), r.err());
        java.util.Set<Integer> colours = new java.util.HashSet<>();
        int cyan = 0;
        for (int p : TextureReader.read(depth).argb()) {
            cyan += p == 0xFF00FFFF ? 1 : 0;
            colours.add(p);
        }
        assertTrue(cyan > 0, "unsplit pieces' outlines are cyan");
        CliRun bad = CliRun.of("render", "--scene", "floor", "--borders", "--border-colour", "pink", "--out",
                dir.resolve("x.png").toString());
        assertEquals(2, bad.status());
        assertTrue(bad.errLine().contains("--border-colour must be yellow, depth or bound"), bad.err());
    }

    @Test
    void outlineOptionsWithoutBordersAreRefusedNotIgnored() {
        for (String[] option : new String[][] {{"--border-colour", "depth"}, {"--border-fade"}}) {
            java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of("render", "--scene", "floor",
                    "--size", "64x36", "--out", dir.resolve("o.png").toString()));
            args.addAll(java.util.List.of(option));
            CliRun r = CliRun.of(args.toArray(new String[0]));
            assertEquals(2, r.status(), r.err());
            assertTrue(r.errLine().contains(option[0] + " needs --borders"), r.err());
            assertFalse(java.nio.file.Files.exists(dir.resolve("o.png")), "nothing written");
        }
    }
}
