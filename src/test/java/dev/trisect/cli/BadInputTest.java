package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Every kind of bad input ends in one clear line and the right exit status, never a stack trace. */
class BadInputTest {
    @TempDir
    Path dir;

    private CliRun render(String... extra) {
        List<String> args = new ArrayList<>(List.of("render", "--size", "32x24", "--threads", "1",
                "--out", dir.resolve("o.png").toString()));
        args.addAll(List.of(extra));
        return CliRun.of(args.toArray(String[]::new));
    }

    private static void usage(CliRun r, String gist) {
        assertEquals(2, r.status(), r.err());
        String line = r.errLine();
        assertTrue(line.contains(gist), "message '" + line + "' should say '" + gist + "'");
    }

    private static void unreadable(CliRun r, String gist) {
        assertEquals(1, r.status(), r.err());
        String line = r.errLine();
        assertTrue(line.contains(gist), "message '" + line + "' should say '" + gist + "'");
    }

    @ParameterizedTest(name = "{0} {1}")
    @CsvSource(delimiter = '|', value = {
        "--size|0x5|not a frame size",
        "--size|-5x10|not a frame size",
        "--size|NaNx10|not a frame size",
        "--size|abc|not a frame size",
        "--size|20000x10|not a frame size",
        "--max-edge|0|not a positive number",
        "--max-edge|-3|not a positive number",
        "--max-edge|NaN|not a positive number",
        "--max-edge|Infinity|not a positive number",
        "--max-error|0|not a positive number",
        "--max-error|nope|not a positive number",
        "--max-depth|-1|--max-depth must be between 0 and 30",
        "--max-depth|31|--max-depth must be between 0 and 30",
        "--max-pieces|0|--max-pieces must be at least 1",
        "--split-point|middle|is not a split point: use midpoint, screen or geometric",
        "--max-frame-pieces|0|is not a piece count",
        "--max-frame-pieces|lots|is not a piece count",
        "--eye|1,2|not a point",
        "--eye|1,NaN,2|not a point",
        "--target|a,b,c|not a point",
        "--fov|0|field of view",
        "--fov|180|field of view",
        "--fov|NaN|--fov must be a number",
        "--near|0|--near must be a positive number",
        "--near|NaN|--near must be a positive number",
        "--far|-1|--far must be a positive number",
        "--mode|fast|not a mode",
        "--split|area|not a split policy",
        "--cull|front|not a cull mode",
        "--background|red|not a colour",
        "--scene|nosuch|unknown scene 'nosuch'",
        "--bogus|1|Unknown option"
    })
    void badValuesAreUsageErrors(String option, String value, String gist) {
        usage(render(option, value), gist);
    }

    @Test
    void nearNotBeforeFarIsAUsageError() {
        usage(render("--near", "5", "--far", "5"), "--near (5.0) must be less than --far (5.0)");
        usage(render("--near", "2000"), "must be less than --far (1000.0)");
    }

    /**
     * --far 1.7e308 skipped every triangle (2 * far overflowed in the projection); now it draws what
     * --far 1e307 draws, and a far whose projection overflows with the given near is refused, naming the limit.
     */
    @Test
    void anyFiniteFarDrawsWithTheDefaultNearAndAnOverflowingOneIsRefused() throws IOException {
        CliRun huge = CliRun.of("render", "--size", "32x24", "--far", "1.7e308", "--stats", "--out",
                dir.resolve("huge.png").toString());
        assertEquals(0, huge.status(), huge.err());
        assertTrue(huge.out().contains("\"skipped_invalid\":0,"), huge.out());
        assertEquals(0, render("--far", "1e307").status());
        assertEquals(java.util.Arrays.toString(dev.trisect.texture.TextureReader.read(dir.resolve("o.png")).argb()),
                java.util.Arrays.toString(dev.trisect.texture.TextureReader.read(dir.resolve("huge.png")).argb()));
        usage(render("--near", "1", "--far", "1e308"), "--far 1.0E308 is too large for --near 1.0: the projection "
                + "needs 2 x near x far to be a finite double, so --far may be at most 8.988465674311579E307");
        assertEquals(0, render("--near", "1", "--far", "8.988465674311579E307").status());
    }

    @Test
    void threadCountIsChecked() {
        usage(CliRun.of("render", "--size", "8x8", "--threads", "0", "--out", dir.resolve("o.png").toString()),
                "--threads must be between 1 and 256");
    }

    @Test
    void eyeEqualToTargetIsAUsageError() {
        usage(render("--eye", "1,2,3", "--target", "1,2,3"), "--eye and --target are the same point");
    }

    @Test
    void upAlongTheViewIsAUsageError() {
        usage(render("--eye", "0,5,0", "--target", "0,0,0"), "parallel to the view direction");
    }

    @Test
    void outputFormatsAreChecked() {
        usage(CliRun.of("render", "--out", dir.resolve("o.jpg").toString()), "unsupported output format");
        usage(render("--uv-out", dir.resolve("uv.png").toString()), "use .pfm");
        usage(CliRun.of("render", "--size", "8x8"), "--out FILE.png|FILE.ppm is required");
        unreadable(CliRun.of("render", "--size", "8x8", "--out", dir.resolve("no/such/dir/o.png").toString()),
                "cannot write");
    }

    /**
     * An output the user ended with a separator names a directory: refused, where Path's dropping the
     * separator wrote the file {@code o.png} with exit 0.
     */
    @ParameterizedTest(name = "{0} {1}")
    @CsvSource(delimiter = '|', value = {
        "render|--out|o.png",
        "render|--uv-out|uv.pfm",
        "compare|--heatmap|h.png",
        "compare|--out|o.png",
        "diff|--heatmap|h.png",
        "export|--to|e.obj",
        "bench|--plot|p.png"
    })
    void anOutputEndingWithASeparatorIsRefused(String command, String option, String name) throws IOException {
        List<String> args = new ArrayList<>(List.of(command, option, dir.resolve(name) + "/"));
        if (command.equals("render") && !option.equals("--out")) {
            args.addAll(List.of("--out", dir.resolve("o.png").toString()));
        }
        if (command.equals("diff")) {
            Path t = texture();
            Path uv = dir.resolve("uv.pfm");
            byte[] header = "PF\n2 2\n-1\n".getBytes(StandardCharsets.US_ASCII);
            Files.write(uv, java.util.Arrays.copyOf(header, header.length + 2 * 2 * 3 * 4));
            args.addAll(List.of("--image", t.toString(), "--uv", uv.toString(), "--reference", t.toString(),
                    "--reference-uv", uv.toString()));
        }
        if (command.equals("bench")) {
            args.addAll(List.of("--sweep", "--frames", "1", "--warmup", "0"));
        }
        args.addAll(command.equals("diff") || command.equals("export") ? List.of() : List.of("--size", "8x8"));
        CliRun r = CliRun.of(args.toArray(String[]::new));
        usage(r, "Invalid value for option '" + option + "': '" + dir.resolve(name) + "/' ends with a separator, so "
                + "it names a directory: give the name of the file to write");
        assertFalse(Files.exists(dir.resolve(name)), name + " must not be written");
    }

    @Test
    void missingObjFile() {
        unreadable(render("--obj", dir.resolve("missing.obj").toString()), "missing.obj");
    }

    private Path obj(String text) throws IOException {
        Path p = dir.resolve("m.obj");
        Files.writeString(p, text, StandardCharsets.ISO_8859_1);
        return p;
    }

    @ParameterizedTest(name = "{1}")
    @CsvSource(delimiter = '|', value = {
        "v 0 0 0\\nv 1 0 0\\nv 0 1 zz\\nf 1 2 3|m.obj:3:",
        "v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 9|m.obj:4:",
        "v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 0|m.obj:4:",
        "v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2|m.obj:4:",
        "v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1/5 2 3|m.obj:4:",
        "v 0 0 0\\n|no faces"
    })
    void malformedObjNamesFileAndLine(String text, String gist) throws IOException {
        Path p = obj(text.replace("\\n", "\n"));
        unreadable(render("--obj", p.toString(), "--texture", texture().toString()), gist);
    }

    @Test
    void nanAndInfiniteCoordinatesSkipTheTriangleAndCountIt() throws IOException {
        Path p = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nv 0 inf 0\n"
                + "f 1 2 3\nf 1 2 4\nf 5 2 3\n");
        CliRun r = render("--obj", p.toString(), "--texture", texture().toString(), "--stats", "--cull", "none");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("\"skipped_invalid\":2"), r.out());
        assertTrue(r.out().contains("\"triangles_in\":3"), r.out());
    }

    private Path texture() throws IOException {
        Path t = dir.resolve("t.ppm");
        byte[] header = "P6\n2 2\n255\n".getBytes(StandardCharsets.US_ASCII);
        byte[] data = new byte[header.length + 12];
        System.arraycopy(header, 0, data, 0, header.length);
        for (int i = header.length; i < data.length; i++) {
            data[i] = (byte) (i * 37);
        }
        Files.write(t, data);
        return t;
    }

    @Test
    void missingUnreadableAndUnsupportedTextures() throws IOException {
        Path p = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        unreadable(render("--obj", p.toString(), "--texture", dir.resolve("none.png").toString()), "none.png");
        Path text = dir.resolve("notes.png");
        Files.writeString(text, "this is not an image");
        unreadable(render("--obj", p.toString(), "--texture", text.toString()), "notes.png");
        Path huge = dir.resolve("huge.ppm");
        Files.writeString(huge, "P6\n20000 4\n255\n", StandardCharsets.US_ASCII);
        unreadable(render("--obj", p.toString(), "--texture", huge.toString()), "huge.ppm");
        usage(render("--texture", texture().toString()), "--texture applies to --obj");
    }

    @Test
    void objAndSceneTogetherAreRefused() throws IOException {
        // Found by the command-line trial: --scene was silently dropped and the OBJ drawn, exit 0.
        Path p = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        usage(render("--obj", p.toString(), "--scene", "demo"), "--obj and --scene");
        assertFalse(Files.exists(dir.resolve("o.png")));
        usage(CliRun.of("export", "--scene", "floor", "--obj", p.toString(), "--to", dir.resolve("e.obj").toString()),
                "--obj and --scene");
        assertEquals(0, render("--obj", p.toString()).status(), "--obj alone still draws the OBJ");
    }

    @Test
    void exportRefusesTheFrameOptionsItWouldIgnore() {
        // Found by the command-line trial: export --size 100x900 --cull none --background 123456 wrote and
        // printed exactly what export without them did, exit 0.
        for (String[] option : new String[][] {{"--size", "100x900"}, {"--cull", "none"}, {"--background", "123456"}}) {
            usage(CliRun.of("export", "--scene", "floor", option[0], option[1], "--to", dir.resolve("e.obj").toString()),
                    option[0] + " does not apply to export");
        }
        assertFalse(Files.exists(dir.resolve("e.obj")));
        assertEquals(0, CliRun.of("export", "--scene", "floor", "--fov", "50", "--to", dir.resolve("e.obj").toString())
                .status(), "the camera's options still apply");
    }

    @Test
    void missingMapKdNamesTheTexture() throws IOException {
        Files.writeString(dir.resolve("m.mtl"), "newmtl a\nmap_Kd gone.png\n");
        Path p = obj("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
        unreadable(render("--obj", p.toString()), "gone.png");
    }

    @Test
    void verboseAddsTheStackTraceAndOnlyThen() {
        CliRun quiet = render("--obj", dir.resolve("missing.obj").toString());
        assertFalse(quiet.err().contains("\tat "));
        CliRun loud = render("--obj", dir.resolve("missing.obj").toString(), "--verbose");
        assertEquals(1, loud.status());
        assertTrue(loud.err().contains("\tat "), loud.err());
    }

    @Test
    void diffChecksItsFiles() throws IOException {
        Path img = dir.resolve("a.png");
        assertEquals(0, render("--uv-out", dir.resolve("a.pfm").toString()).status());
        Files.copy(dir.resolve("o.png"), img);
        CliRun r = CliRun.of("diff", "--image", img.toString(), "--uv", dir.resolve("a.pfm").toString(),
                "--reference", img.toString(), "--reference-uv", dir.resolve("missing.pfm").toString());
        unreadable(r, "missing.pfm");
        CliRun other = CliRun.of("render", "--size", "16x16", "--out", dir.resolve("b.png").toString(),
                "--uv-out", dir.resolve("b.pfm").toString());
        assertEquals(0, other.status(), other.err());
        unreadable(CliRun.of("diff", "--image", img.toString(), "--uv", dir.resolve("a.pfm").toString(),
                "--reference", dir.resolve("b.png").toString(), "--reference-uv", dir.resolve("b.pfm").toString()),
                "is 16x16 but");
    }

    @Test
    void aNewlineInsideAValueKeepsTheMessageOnOneLine() {
        String a = dir.resolve("a.png").toString();
        String[][] runs = {
            {"render", "--scene", "floor\nX", "--out", a},
            {"render", "--scene", "floor", "--borders", "--border-colour", "yel\nlow", "--out", a},
            {"compare", "--scene", "floor", "--heatmap", a, "--heatmap-scale", "li\nnear"},
            {"render", "--obj", dir.resolve("m\nx.obj").toString(), "--out", a},
            {"render", "--scene", "floor", "--out", dir.resolve("no\ndir/b.png").toString()},
        };
        for (String[] args : runs) {
            CliRun r = CliRun.of(args);
            assertTrue(r.status() == 1 || r.status() == 2, String.join(" ", args) + ": " + r.err());
            assertTrue(r.errLine().contains("\\x0A"), "the newline is shown escaped: " + r.err());
        }
    }

    @Test
    void aLoopOfSymbolicLinksIsCalledSoWhereverAFileIsRead() throws IOException {
        Path a = dir.resolve("a.png");
        Path b = dir.resolve("b.png");
        Files.createSymbolicLink(a, b);
        Files.createSymbolicLink(b, a);
        Path obj = dir.resolve("t.obj");
        Files.writeString(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n");
        unreadable(render("--obj", obj.toString(), "--texture", a.toString()), "too many levels of symbolic links");
        Files.writeString(dir.resolve("l.mtl"), "newmtl m\nmap_Kd a.png\n");
        Path withMtl = dir.resolve("m.obj");
        Files.writeString(withMtl, "mtllib l.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n");
        CliRun r = render("--obj", withMtl.toString());
        unreadable(r, "too many levels of symbolic links");
        assertTrue(r.errLine().contains("l.mtl:2: map_Kd"), r.err());
        unreadable(CliRun.of("diff", "--image", a.toString(), "--uv", dir.resolve("a.pfm").toString(),
                "--reference", b.toString(), "--reference-uv", dir.resolve("b.pfm").toString()),
                "too many levels of symbolic links");
    }

    @Test
    void aNewlineInAValueThatPicocliRefusesStaysInsideTheOneLineMessage() {
        usage(render("--mode", "fa\nst"), "fa\\x0Ast");
        usage(render("--bogus\nopt", "1"), "--bogus\\x0Aopt");
    }
}
