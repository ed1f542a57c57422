package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** The defects of issue 10, each reproduced through the command line. */
class RobustnessTest {
    @TempDir
    Path dir;

    private static void status(int expected, CliRun r, String gist) {
        assertEquals(expected, r.status(), r.err());
        String line = r.errLine();
        assertTrue(line.contains(gist), "message '" + line + "' should say '" + gist + "'");
    }

    private List<String> listing(Path d) throws IOException {
        try (Stream<Path> files = Files.list(d)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void aFailedSecondOutputLeavesTheFirstUntouched() throws IOException {
        Path c = dir.resolve("c.png");
        Files.writeString(c, "OLD\n");
        CliRun r = CliRun.of("render", "--scene", "floor", "--size", "64x48", "--threads", "1", "--out", c.toString(),
                "--uv-out", dir.resolve("nodir/u.pfm").toString());
        status(1, r, "u.pfm");
        assertEquals("OLD\n", Files.readString(c), "the existing output is untouched");
        assertEquals(List.of("c.png"), listing(dir), "no temporary file is left");
    }

    @Test
    void compareWritesBothOutputsOrNeither() throws IOException {
        Path heat = dir.resolve("h.png");
        Files.writeString(heat, "OLD\n");
        CliRun r = CliRun.of("compare", "--scene", "floor", "--size", "32x24", "--threads", "1", "--heatmap",
                heat.toString(), "--out", dir.resolve("nodir/o.png").toString());
        status(1, r, "o.png");
        assertEquals("OLD\n", Files.readString(heat));
        assertEquals(List.of("h.png"), listing(dir));
    }

    @Test
    void aFailedExportLeavesNoPartialOutput() throws IOException {
        Path good = Files.createDirectory(dir.resolve("good"));
        CliRun ok = CliRun.of("export", "--scene", "demo", "--to", good.resolve("s.obj").toString());
        assertEquals(0, ok.status(), ok.err());
        List<String> written = listing(good);
        assertTrue(written.containsAll(List.of("s.obj", "s.mtl", "s-bricks.ppm", "s-floor.ppm", "s-crate.ppm")),
                written.toString());
        // The last material's texture cannot be written: a directory stands in its place.
        Path bad = Files.createDirectory(dir.resolve("bad"));
        Files.createDirectory(bad.resolve("s-crate.ppm"));
        CliRun r = CliRun.of("export", "--scene", "demo", "--to", bad.resolve("s.obj").toString());
        status(1, r, "s-crate.ppm");
        assertEquals(List.of("s-crate.ppm"), listing(bad), "nothing else was written");
    }

    @Test
    // A separate thread: opening a FIFO blocks in native code, which an interrupt does not end.
    @Timeout(value = 60, unit = TimeUnit.SECONDS, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void diffRefusesAFifoInsteadOfHanging() throws Exception {
        Path fifo = dir.resolve("uv.pfm");
        Process mk = new ProcessBuilder("mkfifo", fifo.toString()).inheritIO().start();
        assertEquals(0, mk.waitFor());
        Path img = dir.resolve("a.png");
        Path uv = dir.resolve("a.pfm");
        assertEquals(0, CliRun.of("render", "--size", "8x8", "--threads", "1", "--out", img.toString(), "--uv-out",
                uv.toString()).status());
        status(1, CliRun.of("diff", "--image", img.toString(), "--uv", fifo.toString(), "--reference", img.toString(),
                "--reference-uv", uv.toString()), "uv.pfm: cannot read: is not a regular file");
        status(1, CliRun.of("diff", "--image", img.toString(), "--uv", uv.toString(), "--reference", img.toString(),
                "--reference-uv", fifo.toString()), "uv.pfm: cannot read: is not a regular file");
    }

    @Test
    void benchFramesAreBounded() {
        status(2, CliRun.of("bench", "--scene", "floor", "--size", "8x8", "--frames", "2147483647"), "--frames");
        status(2, CliRun.of("bench", "--scene", "floor", "--size", "8x8", "--warmup", "2147483647"), "--warmup");
    }

    @Test
    void aHugePfmHeaderIsReportedWithoutOverflow() throws IOException {
        Path img = dir.resolve("a.png");
        Path uv = dir.resolve("a.pfm");
        assertEquals(0, CliRun.of("render", "--size", "8x8", "--threads", "1", "--out", img.toString(), "--uv-out",
                uv.toString()).status());
        Path big = dir.resolve("big.pfm");
        Files.writeString(big, "PF\n2147483647 2147483647\n-1.0\n", StandardCharsets.US_ASCII);
        CliRun r = CliRun.of("diff", "--image", img.toString(), "--uv", big.toString(), "--reference", img.toString(),
                "--reference-uv", uv.toString());
        status(1, r, "big.pfm: the image is 2147483647x2147483647 pixels; at most 16384 on a side");
        assertTrue(!r.err().contains("needs -"), r.err());
    }

    @Test
    void threadsAreCheckedByDiffAndExport() {
        status(2, CliRun.of("diff", "--threads", "0", "--image", "a.png", "--uv", "a.pfm", "--reference", "a.png",
                "--reference-uv", "a.pfm"), "--threads must be between 1 and 256, got 0");
        status(2, CliRun.of("export", "--threads", "-5", "--scene", "floor", "--to",
                dir.resolve("x.obj").toString()), "--threads must be between 1 and 256, got -5");
    }

    @Test
    void farAndDegenerateCamerasAreNamedForWhatTheyAre() {
        Path out = dir.resolve("o.png");
        status(2, CliRun.of("render", "--size", "8x8", "--eye", "1e200,1,0", "--target", "0,0,0", "--out",
                out.toString()), "too far apart");
        status(2, CliRun.of("render", "--size", "8x8", "--eye", "0,0,0", "--target", "1e-320,0,0", "--out",
                out.toString()), "too close together");
        // The genuine case keeps its message.
        status(2, CliRun.of("render", "--size", "8x8", "--eye", "0,5,0", "--target", "0,0,0", "--out",
                out.toString()), "parallel to the view direction");
    }

    @Test
    void exportToAnMtlAndAHeatmapOverTheImageAreRefused() throws IOException {
        status(2, CliRun.of("export", "--scene", "floor", "--to", dir.resolve("x.mtl").toString()), "x.mtl");
        Path same = dir.resolve("same.png");
        status(2, CliRun.of("compare", "--scene", "floor", "--size", "8x8", "--heatmap", same.toString(), "--out",
                dir.resolve("sub/../same.png").toString()), "the same file");
        assertEquals(List.of(), listing(dir));
    }

    @Test
    void aMissingMapKdTextureNamesTheMtlFileAndLine() throws IOException {
        Files.writeString(dir.resolve("m.mtl"), "# materials\nnewmtl a\nmap_Kd gone.png\n");
        Path obj = dir.resolve("m.obj");
        Files.writeString(obj, "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
        status(1, CliRun.of("render", "--size", "8x8", "--obj", obj.toString(), "--out",
                dir.resolve("o.png").toString()), "m.mtl:3: map_Kd");
    }

    @Test
    void anOutputThatIsAnInputIsRefusedAndTheInputKept() throws IOException {
        // Found by the command-line trial: each of these replaced its input with the output, exit 0.
        Path tex = dir.resolve("t.ppm");
        byte[] texture = "P6\n2 1\n255\n\377\0\0\0\0\377".getBytes(StandardCharsets.ISO_8859_1);
        Files.write(tex, texture);
        Path obj = dir.resolve("m.obj");
        String model = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
        Files.writeString(obj, model);
        status(2, CliRun.of("render", "--size", "8x8", "--obj", obj.toString(), "--texture", tex.toString(),
                "--out", tex.toString()), "is also the --texture input");
        // Outputs are written through links, so a link to the texture is the texture.
        Path link = Files.createSymbolicLink(dir.resolve("link.ppm"), tex);
        status(2, CliRun.of("compare", "--size", "8x8", "--obj", obj.toString(), "--texture", tex.toString(),
                "--out", link.toString()), "is also the --texture input");
        status(2, CliRun.of("export", "--obj", obj.toString(), "--texture", tex.toString(), "--to",
                dir.resolve("sub/../m.obj").toString()), "is also the --obj input");
        assertArrayEquals(texture, Files.readAllBytes(tex));
        assertEquals(model, Files.readString(obj));

        Path png = dir.resolve("r.png");
        Path uv = dir.resolve("r.pfm");
        CliRun r = CliRun.of("render", "--size", "8x8", "--out", png.toString(), "--uv-out", uv.toString());
        assertEquals(0, r.status(), r.err());
        byte[] image = Files.readAllBytes(png);
        status(2, CliRun.of("diff", "--image", png.toString(), "--uv", uv.toString(), "--reference", png.toString(),
                "--reference-uv", uv.toString(), "--heatmap", png.toString()), "is also the --image input");
        assertArrayEquals(image, Files.readAllBytes(png));
        assertEquals(List.of("link.ppm", "m.obj", "r.pfm", "r.png", "t.ppm"), listing(dir), "nothing else is written");
    }

    @Test
    void anOutputOverATextureTheObjNamesIsRefused() throws IOException {
        // Found by the command-line trial: render --obj m.obj --out t.ppm replaced the map_Kd texture t.ppm.
        Path tex = dir.resolve("t.ppm");
        byte[] texture = "P6\n2 1\n255\n\377\0\0\0\0\377".getBytes(StandardCharsets.ISO_8859_1);
        Files.write(tex, texture);
        Files.writeString(dir.resolve("m.mtl"), "newmtl a\nmap_Kd t.ppm\n");
        Path obj = dir.resolve("m.obj");
        Files.writeString(obj, "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl a\n"
                + "f 1/1 2/2 3/3\n");
        status(2, CliRun.of("render", "--size", "8x8", "--obj", obj.toString(), "--out", tex.toString()),
                "is also an input of m.obj");
        status(2, CliRun.of("compare", "--size", "8x8", "--obj", obj.toString(), "--heatmap",
                dir.resolve("x/../t.ppm").toString().replace(".ppm", ".png"), "--out", tex.toString()),
                "is also an input of m.obj");
        assertArrayEquals(texture, Files.readAllBytes(tex));
        assertEquals(List.of("m.mtl", "m.obj", "t.ppm"), listing(dir), "nothing else is written");
        CliRun ok = CliRun.of("render", "--size", "8x8", "--obj", obj.toString(), "--out",
                dir.resolve("r.ppm").toString());
        assertEquals(0, ok.status(), ok.err());
    }

    /**
     * The MTL files an OBJ reads are inputs too (found by the command-line trial: they were not checked):
     * export --to e.obj writes e.mtl and e-MATERIAL.ppm beside it, and replaced the model's own e.mtl
     * (mtllib e.mtl) or its texture e-a.ppm with exit 0; a render over an MTL file was not refused either.
     * Each is refused now, before anything is written, and the model keeps its files.
     */
    @Test
    void anOutputOverAnMtlFileOrATextureTheExportWritesIsRefused() throws IOException {
        byte[] texture = "P6\n2 1\n255\n\377\0\0\0\0\377".getBytes(StandardCharsets.ISO_8859_1);
        Files.write(dir.resolve("t.ppm"), texture);
        String library = "newmtl a\nmap_Kd t.ppm\n";
        Files.writeString(dir.resolve("e.mtl"), library);
        Path obj = dir.resolve("m.obj");
        String model = "mtllib e.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl a\nf 1/1 2/2 3/3\n";
        Files.writeString(obj, model);
        status(2, CliRun.of("export", "--obj", obj.toString(), "--to", dir.resolve("e.obj").toString()),
                dir.resolve("e.mtl") + " is also an input of m.obj (a material library or texture it names)");
        // An MTL file may have any name, an image's too.
        Files.writeString(dir.resolve("lib.png"), library);
        Path other = dir.resolve("other.obj");
        Files.writeString(other, model.replace("e.mtl", "lib.png"));
        status(2, CliRun.of("render", "--size", "8x8", "--obj", other.toString(), "--out",
                dir.resolve("lib.png").toString()), "is also an input of other.obj");
        // The exported textures are named after the OBJ and the material: t.obj's is t-a.ppm.
        Files.write(dir.resolve("t-a.ppm"), texture);
        Files.writeString(dir.resolve("e.mtl"), "newmtl a\nmap_Kd t-a.ppm\n");
        status(2, CliRun.of("export", "--obj", obj.toString(), "--to", dir.resolve("t.obj").toString()),
                dir.resolve("t-a.ppm") + " is also an input of m.obj");
        status(2, CliRun.of("export", "--obj", obj.toString(), "--texture", dir.resolve("t-a.ppm").toString(),
                "--to", dir.resolve("t.obj").toString()), "t-a.ppm is also the --texture input");
        assertEquals("newmtl a\nmap_Kd t-a.ppm\n", Files.readString(dir.resolve("e.mtl")));
        assertEquals(library, Files.readString(dir.resolve("lib.png")));
        assertArrayEquals(texture, Files.readAllBytes(dir.resolve("t-a.ppm")));
        assertEquals(List.of("e.mtl", "lib.png", "m.obj", "other.obj", "t-a.ppm", "t.ppm"), listing(dir),
                "nothing else is written");
        CliRun ok = CliRun.of("export", "--obj", obj.toString(), "--to", dir.resolve("x.obj").toString());
        assertEquals(0, ok.status(), ok.err());
    }
}
