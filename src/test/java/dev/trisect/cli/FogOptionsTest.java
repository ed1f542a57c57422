package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The fog options: their messages, and what export tells glref. */
class FogOptionsTest {
    @TempDir
    Path dir;

    private static byte[] readBytes(Path p) {
        try {
            return java.nio.file.Files.readAllBytes(p);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    @Test
    void badFogGetsOneLineAndUsageStatus() {
        CliRun r = CliRun.of("render", "--scene", "floor", "--size", "8x8", "--out", dir.resolve("a.png").toString(),
                "--fog", "lin,2");
        assertEquals(2, r.status());
        assertTrue(r.errLine().contains("'lin,2' is not a fog"), r.err());
        r = CliRun.of("render", "--scene", "floor", "--size", "8x8", "--out", dir.resolve("a.png").toString(),
                "--fog", "linear,5,5");
        assertEquals(2, r.status());
        assertTrue(r.errLine().contains("end > start"), r.err());
        r = CliRun.of("render", "--scene", "floor", "--size", "8x8", "--out", dir.resolve("a.png").toString(),
                "--fog-colour", "1,1,1");
        assertEquals(2, r.status());
        assertTrue(r.errLine().contains("--fog-colour applies to --fog"), r.err());
        r = CliRun.of("render", "--scene", "floor", "--size", "8x8", "--out", dir.resolve("a.png").toString(),
                "--fog", "exp,0.1", "--fog-colour", "1,-1,1");
        assertEquals(2, r.status());
        assertTrue(r.errLine().contains("is not a colour"), r.err());
    }

    @Test
    void renderFogsAndExportTellsGlrefTheSameFog() {
        CliRun plain = CliRun.of("render", "--scene", "floor", "--size", "32x18", "--out",
                dir.resolve("a.ppm").toString());
        CliRun fogged = CliRun.of("render", "--scene", "floor", "--size", "32x18", "--out",
                dir.resolve("b.ppm").toString(), "--fog", "exp2,0.1", "--fog-colour", "0.5");
        assertEquals(0, plain.status(), plain.err());
        assertEquals(0, fogged.status(), fogged.err());
        assertTrue(!java.util.Arrays.equals(readBytes(dir.resolve("a.ppm")), readBytes(dir.resolve("b.ppm"))),
                "the fog changed nothing");
        CliRun export = CliRun.of("export", "--scene", "floor", "--to", dir.resolve("f.obj").toString(), "--fog",
                "linear,2,30", "--fog-colour", "0.6,0.7,0.8");
        assertEquals(0, export.status(), export.err());
        assertTrue(export.out().contains("glref: GLREF_FOG=linear,2.0,30.0 GLREF_FOG_COLOUR=0.6,0.7,0.8"), export.out());
    }
}
