package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.jr.ob.JSON;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The options every scene command shares (light, fog, line width) are checked before the scene is read
 * and anything is printed, in every command; each message names what the value is.
 */
class LightOptionsTest {
    @TempDir
    Path dir;

    private static final String[] BENCH = {"bench", "--scene", "floor", "--size", "8x8", "--frames", "1", "--warmup",
        "0", "--modes", "perspective"};

    private static String[] with(String[] base, String... more) {
        String[] all = java.util.Arrays.copyOf(base, base.length + more.length);
        System.arraycopy(more, 0, all, base.length, more.length);
        return all;
    }

    @Test
    void benchRefusesBadLightBeforePrintingItsTable() {
        for (String[] bad : new String[][] {{"--light", "0,0,0"}, {"--shade", "smooth"}, {"--fog-colour", "1"},
            {"--point-colour", "1"}}) {
            CliRun r = CliRun.of(with(BENCH, bad));
            assertEquals(2, r.status(), String.join(" ", bad) + ": " + r.err());
            assertEquals("", r.out(), "nothing measured, nothing printed for " + String.join(" ", bad));
            r.errLine();
        }
    }

    @Test
    void everyCommandChecksTheLineWidth() {
        for (String[] run : new String[][] {
            {"compare", "--scene", "floor", "--size", "8x8", "--line-width", "0"},
            with(BENCH, "--line-width", "0")}) {
            CliRun r = CliRun.of(run);
            assertEquals(2, r.status(), String.join(" ", run) + ": " + r.err());
            assertTrue(r.errLine().contains("--line-width must be a whole number of pixels from 1 to 255"), r.err());
            assertEquals("", r.out());
        }
        // export writes lines as l elements, which have no width: the option would be silently lost.
        CliRun r = CliRun.of("export", "--scene", "floor", "--to", dir.resolve("f.obj").toString(), "--line-width", "2");
        assertEquals(2, r.status(), r.err());
        assertTrue(r.errLine().contains("--line-width does not apply to export"), r.err());
        r = CliRun.of("export", "--scene", "floor", "--to", dir.resolve("f.obj").toString(), "--light", "0,0,0");
        assertEquals(2, r.status(), r.err());
        assertTrue(!Files.exists(dir.resolve("f.obj")), "export wrote nothing");
    }

    @Test
    void benchRefusesAGlrefItCannotRunBeforeMeasuring() throws Exception {
        Path missing = dir.resolve("no-glref");
        CliRun r = CliRun.of(with(BENCH, "--glref", missing.toString()));
        assertEquals(1, r.status(), r.err());
        assertEquals("", r.out(), "no row measured before the refusal");
        assertEquals("trisect: " + missing + ": cannot run (--glref): no such file", r.errLine());
        Path plain = Files.writeString(dir.resolve("plain"), "not a program");
        r = CliRun.of(with(BENCH, "--glref", plain.toString()));
        assertEquals(1, r.status(), r.err());
        assertTrue(r.errLine().endsWith("not an executable file"), r.err());
        r = CliRun.of(with(BENCH, "--glref", "no-such-glref-program"));
        assertEquals(1, r.status(), r.err());
        assertTrue(r.errLine().endsWith("no such program on the PATH"), r.err());
    }

    @Test
    void messagesNameWhatTheValueIs() {
        String out = dir.resolve("a.png").toString();
        CliRun r = CliRun.of("render", "--scene", "floor", "--size", "8x8", "--out", out, "--light", "1,2");
        assertEquals(2, r.status());
        assertTrue(r.errLine().contains("'1,2' is not a direction: use three finite numbers dx,dy,dz"), r.err());
        r = CliRun.of("render", "--scene", "floor", "--size", "8x8", "--out", out, "--point", "0,1,0",
                "--attenuation", "1,0");
        assertEquals(2, r.status());
        assertTrue(r.errLine().contains("'1,0' is not an attenuation: use three finite numbers kc,kl,kq"), r.err());
        r = CliRun.of("render", "--scene", "floor", "--size", "8x8", "--out", out, "--eye", "1,2");
        assertTrue(r.errLine().contains("'1,2' is not a point"), r.err());
        r = CliRun.of("render", "--scene", "floor", "--size", "8x8", "--out", out, "--light", "0,-0,0");
        assertEquals(2, r.status());
        assertTrue(r.errLine().endsWith("--light needs a non-zero direction, got 0.0,-0.0,0.0"), r.err());
        assertTrue(!Files.exists(Path.of(out)));
    }

    @Test
    void theSweepAndTheBudgetRunRefuseWhatTheyDoNotDraw() {
        // Both time the textured triangles alone: lines, labels, the alpha test, light and fog were silently dropped.
        for (String run : new String[] {"--sweep", "--target-ms=50"}) {
            for (String[] extra : new String[][] {{"--lines", "3"}, {"--labels", "2"}, {"--alpha-test"},
                {"--line-width", "2"}, {"--light", "1,1,1"}, {"--point", "0,1,0"}, {"--ambient", "0.5"},
                {"--shade", "none"}, {"--fog", "exp,0.1"}}) {
                String[] args = with(new String[] {"bench", "--scene", "floor", "--size", "8x8", "--frames", "1",
                    "--warmup", "0", run}, extra);
                CliRun r = CliRun.of(args);
                assertEquals(2, r.status(), String.join(" ", args) + ": " + r.err());
                assertEquals(extra[0] + " does not go with " + run.replace("=50", "") + ": it times the textured "
                        + "triangles alone, without lines, labels, alpha test, light or fog",
                        r.errLine().substring("trisect: ".length()));
                assertEquals("", r.out());
            }
        }
    }

    @Test
    void scatteredLinesAndLabelsAreBoundedBeforeTheHeader() {
        for (String option : new String[] {"--lines", "--labels"}) {
            CliRun r = CliRun.of(with(BENCH, option, "2000000000"));
            assertEquals(2, r.status(), r.err());
            assertEquals("trisect: " + option + " must be between 0 and 1000000, got 2000000000", r.errLine());
            assertEquals("", r.out(), "refused before the header, not out of memory after it");
        }
    }

    @Test
    void aLightDirectionOfAnyFiniteNonZeroLengthLightsAsItsUnitVector() throws Exception {
        String[] frame = {"render", "--scene", "boxes", "--size", "32x18", "--shade", "flat", "--out"};
        for (String[] run : new String[][] {{"1,0,0", "unit.ppm"}, {"1e-300,0,0", "tiny.ppm"}, {"1e300,0,0", "huge.ppm"}}) {
            CliRun r = CliRun.of(with(frame, dir.resolve(run[1]).toString(), "--light", run[0]));
            assertEquals(0, r.status(), run[0] + ": " + r.err());
        }
        byte[] unit = Files.readAllBytes(dir.resolve("unit.ppm"));
        assertTrue(java.util.Arrays.equals(unit, Files.readAllBytes(dir.resolve("tiny.ppm"))), "1e-300,0,0");
        assertTrue(java.util.Arrays.equals(unit, Files.readAllBytes(dir.resolve("huge.ppm"))), "1e300,0,0");
        CliRun export = CliRun.of("export", "--scene", "floor", "--to", dir.resolve("f.obj").toString(), "--light",
                "1e300,0,0");
        assertEquals(0, export.status(), export.err());
        assertTrue(export.out().contains("GLREF_LIGHT=1.0,0.0,0.0 "), "glref, in floats, gets the unit vector: "
                + export.out());
    }

    /** bench --json's rows say what they timed: the light and fog in force, as compare's line does. */
    @Test
    void benchJsonRecordsTheLightAndFogItTimed() throws Exception {
        String[] base = {"bench", "--scene", "floor", "--size", "32x18", "--modes", "perspective", "--frames", "1",
            "--warmup", "0", "--json"};
        CliRun plain = CliRun.of(base);
        assertEquals(0, plain.status(), plain.err());
        Map<String, Object> none = JSON.std.mapFrom(plain.out().strip());
        for (String key : new String[] {"light", "point", "ambient", "shade", "fog"}) {
            assertFalse(none.containsKey(key), key + " without any light or fog option: " + plain.out());
        }
        CliRun lit = CliRun.of(with(base, "--light", "0.3,-1,-0.5", "--shade", "flat", "--fog", "exp,0.05"));
        assertEquals(0, lit.status(), lit.err());
        Map<String, Object> j = JSON.std.mapFrom(lit.out().strip());
        assertEquals(Map.of("direction", List.of(0.3, -1.0, -0.5), "colour", List.of(1.0, 1.0, 1.0)), j.get("light"),
                lit.out());
        assertEquals("flat", j.get("shade"));
        assertEquals(Map.of("mode", "exp", "density", 0.05, "colour", List.of(0.0, 0.0, 0.0)), j.get("fog"));
        assertEquals("perspective", j.get("path"), "the timing fields still lead");
    }

    @Test
    void compareRecordsTheLightAndFogItDrewWith() throws Exception {
        String[] base = {"compare", "--scene", "floor", "--size", "32x18", "--mode", "tessellated"};
        CliRun plain = CliRun.of(base);
        assertEquals(0, plain.status(), plain.err());
        Map<String, Object> none = JSON.std.mapFrom(plain.out().strip());
        for (String key : new String[] {"light", "point", "ambient", "shade", "fog"}) {
            assertFalse(none.containsKey(key), key + " without any light or fog option: " + plain.out());
        }
        CliRun lit = CliRun.of(with(base, "--light", "1,2,3", "--point", "0,2,0", "--attenuation", "1,0.2,0.05",
                "--shade", "flat", "--fog", "linear,-2,9", "--fog-colour", "0.5"));
        assertEquals(0, lit.status(), lit.err());
        Map<String, Object> j = JSON.std.mapFrom(lit.out().strip());
        assertEquals(Map.of("direction", List.of(1.0, 2.0, 3.0), "colour", List.of(1.0, 1.0, 1.0)), j.get("light"),
                lit.out());
        assertEquals(Map.of("position", List.of(0.0, 2.0, 0.0), "colour", List.of(1.0, 1.0, 1.0), "attenuation",
                List.of(1.0, 0.2, 0.05)), j.get("point"));
        assertEquals(List.of(0.2, 0.2, 0.2), j.get("ambient"), "the ambient in force: OpenGL's default");
        assertEquals("flat", j.get("shade"));
        assertEquals(Map.of("mode", "linear", "start", -2.0, "end", 9.0, "colour", List.of(0.5, 0.5, 0.5)),
                j.get("fog"));
        assertTrue(j.containsKey("max_displacement"), "the metrics still follow");
        Map<String, Object> fogOnly = JSON.std.mapFrom(CliRun.of(with(base, "--fog", "exp2,0.25")).out().strip());
        assertEquals(Map.of("mode", "exp2", "density", 0.25, "colour", List.of(0.0, 0.0, 0.0)), fogOnly.get("fog"));
        assertFalse(fogOnly.containsKey("shade"), "fog alone lights nothing");
        Map<String, Object> ambientOnly = JSON.std.mapFrom(CliRun.of(with(base, "--ambient", "0.5,0.4,0.3")).out()
                .strip());
        assertEquals(List.of(0.5, 0.4, 0.3), ambientOnly.get("ambient"));
        assertEquals("smooth", ambientOnly.get("shade"), "the default with a light");
    }
}
