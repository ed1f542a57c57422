package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureReader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** {@code render --obj} with {@code l} elements and {@code --line-width}. */
class LinesCommandTest {
    @TempDir
    Path dir;

    private Path obj() throws IOException {
        Files.writeString(dir.resolve("l.mtl"), "newmtl ink\nKd 0 1 0\n");
        return Files.writeString(dir.resolve("l.obj"),
                "mtllib l.mtl\nv -1 0 0\nv 1 0 0\nv 0 1 0\nusemtl ink\nl 1 2 3\n");
    }

    private int green(Path png) {
        Texture t = TextureReader.read(png);
        int n = 0;
        for (int c : t.argb()) {
            n += c == 0xFF00FF00 ? 1 : 0;
        }
        return n;
    }

    @Test
    void theObjLinesAreDrawnInTheirKdAndWiderWithLineWidth() throws IOException {
        Path obj = obj();
        Path thin = dir.resolve("thin.png");
        Path wide = dir.resolve("wide.png");
        String[] camera = {"--eye", "0,0.5,3", "--target", "0,0.5,0", "--size", "160x120"};
        CliRun r = CliRun.of(concat(new String[] {"render", "--obj", obj.toString(), "--out", thin.toString()}, camera));
        assertEquals(0, r.status(), r.err());
        CliRun r3 = CliRun.of(concat(new String[] {"render", "--obj", obj.toString(), "--line-width", "3",
            "--out", wide.toString()}, camera));
        assertEquals(0, r3.status(), r3.err());
        int one = green(thin);
        int three = green(wide);
        assertTrue(one > 100, "drawn: " + one);
        assertTrue(three > 2.5 * one && three < 3.5 * one, one + " pixels at width 1, " + three + " at width 3");
    }

    @Test
    void exportWritesTheLinesSoThatReadingThemBackGivesTheSameSegmentsAndColours() throws IOException {
        Files.writeString(dir.resolve("c.mtl"), "newmtl a\nKd 0.2 0.4 0.6\nnewmtl b\nKd 1 0.5 0\n");
        Path obj = Files.writeString(dir.resolve("c.obj"), "mtllib c.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                + "vt 0 0\nf 1/1 2/1 3/1\nusemtl a\nl 1 2 3 4\nl 4 1\nusemtl b\nl 2 4\nl 4 3\n");
        Path out = dir.resolve("out/x.obj");
        CliRun r = CliRun.of("export", "--obj", obj.toString(), "--to", out.toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("6 line segments"), r.out());
        dev.trisect.mesh.ObjModel before = dev.trisect.mesh.ObjReader.read(obj, true);
        dev.trisect.mesh.ObjModel after = dev.trisect.mesh.ObjReader.read(out, true);
        dev.trisect.mesh.Lines a = before.lines();
        dev.trisect.mesh.Lines b = after.lines();
        assertEquals(a.segmentCount(), b.segmentCount());
        org.junit.jupiter.api.Assertions.assertArrayEquals(a.colours(), b.colours());
        for (int s = 0; s < a.segmentCount(); s++) {
            for (int end = 0; end < 2; end++) {
                for (int k = 0; k < 3; k++) {
                    assertEquals(a.points()[3 * a.segments()[2 * s + end] + k], b.points()[3 * b.segments()[2 * s + end] + k]);
                }
            }
        }
        assertEquals(before.mesh().triangleCount(), after.mesh().triangleCount());
    }

    @Test
    void benchTimesTheFrameWithScatteredLines() {
        CliRun r = CliRun.of("bench", "--scene", "floor", "--size", "64x48", "--modes", "perspective", "--frames", "1",
                "--warmup", "0", "--lines", "200");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("200 line segments 1 px wide"), r.out());
        assertTrue(r.out().lines().anyMatch(l -> l.startsWith("perspective") && l.matches(".* lines -?[0-9.]+ ms")),
                r.out());
        CliRun bad = CliRun.of("bench", "--scene", "floor", "--lines", "-1");
        assertEquals(2, bad.status(), bad.err());
        assertTrue(bad.err().contains("--lines must be between 0 and 1000000, got -1"), bad.err());
    }

    @Test
    void benchTimesScatteredLabelsAgainstTheFrameWithoutThem() {
        CliRun r = CliRun.of("bench", "--scene", "floor", "--size", "96x64", "--modes", "perspective", "--frames", "2",
                "--warmup", "0", "--labels", "30");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().lines().anyMatch(l -> l.startsWith("perspective") && l.matches(".* labels -?[0-9.]+ ms")),
                r.out());
        CliRun both = CliRun.of("bench", "--scene", "floor", "--labels", "3", "--lines", "3");
        assertEquals(2, both.status(), both.err());
        assertTrue(both.err().contains("--labels times the labels alone"), both.err());
    }

    @Test
    void benchGivesGlrefsLineCostAsItsTimeWithThemLessItsTimeWithout() throws IOException {
        // A stand-in for glref: 9 ms a frame when the OBJ it is given has l elements, 4 ms otherwise.
        Path glref = dir.resolve("fake-glref.sh");
        Files.writeString(glref, "#!/bin/sh\nif grep -q '^l ' \"$1\"; then echo 'ms_per_frame 9.000'; "
                + "else echo 'ms_per_frame 4.000'; fi\n");
        glref.toFile().setExecutable(true);
        CliRun r = CliRun.of("bench", "--scene", "floor", "--size", "64x48", "--modes", "affine", "--frames", "1",
                "--warmup", "0", "--lines", "50", "--glref", glref.toString());
        assertEquals(0, r.status(), r.err());
        String row = r.out().lines().filter(l -> l.startsWith("glref")).findFirst().orElseThrow();
        assertTrue(row.contains(" 9.000 ") && row.endsWith("lines 5.000 ms"), row);
    }

    @ParameterizedTest
    @ValueSource(strings = {"0", "256", "-1"})
    void aLineWidthOutOfRangeIsAUsageError(String width) throws IOException {
        CliRun r = CliRun.of("render", "--obj", obj().toString(), "--line-width", width, "--out",
                dir.resolve("x.png").toString());
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains("--line-width must be a whole number of pixels from 1 to 255, got " + width),
                r.err());
        assertTrue(!Files.exists(dir.resolve("x.png")));
    }

    private static String[] concat(String[] a, String[] b) {
        String[] out = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }
}
