package dev.trisect.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import dev.trisect.base.InputException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/** What ObjReader refuses, and how: one line naming file and line, never a hang or another exception. */
class ObjReaderErrorsTest extends ObjFixture {

    @Test
    void aMissingLibraryNamesTheObjFileAndItsMtllibLine() throws IOException {
        write("present.mtl", "newmtl a\n");
        Path obj = write("scene.obj", TRIANGLE_VERTICES + "mtllib present.mtl missing.mtl\nf 1 2 3\n");
        assertEquals("scene.obj:4: cannot read material library 'missing.mtl': no such file", error(obj, true));
    }

    @Test
    void aLibraryThatIsADirectoryIsAnError() throws IOException {
        Files.createDirectories(dir.resolve("mats"));
        Path obj = write("scene.obj", "mtllib mats\n" + TRIANGLE_VERTICES + "f 1 2 3\n");
        assertEquals("scene.obj:1: cannot read material library 'mats': is a directory", error(obj, true));
    }

    @org.junit.jupiter.api.Test
    @org.junit.jupiter.api.Timeout(10)
    void pipesAndDevicesAreRefusedWithoutBlocking() throws Exception {
        Path fifo = dir.resolve("pipe.obj");
        Process mk = new ProcessBuilder("mkfifo", fifo.toString()).start();
        org.junit.jupiter.api.Assumptions.assumeTrue(mk.waitFor() == 0, "mkfifo is not available here");
        InputException e = org.junit.jupiter.api.Assertions.assertThrows(InputException.class,
                () -> ObjReader.read(fifo, true));
        assertEquals(fifo + ": cannot read: is not a regular file", e.getMessage());
        Path obj = write("scene.obj", "mtllib pipe.obj\n" + TRIANGLE_VERTICES + "f 1 2 3\n");
        assertEquals("scene.obj:1: cannot read material library 'pipe.obj': is not a regular file", error(obj, true));
        Path zero = Path.of("/dev/zero");
        if (Files.exists(zero)) {
            InputException z = org.junit.jupiter.api.Assertions.assertThrows(InputException.class,
                    () -> ObjReader.read(zero, false));
            assertEquals("/dev/zero: cannot read: is not a regular file", z.getMessage());
        }
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "newmtl a\\nKd 1 1 1\\nmap_Kd\\n | lib.mtl:3: map_Kd without a file name",
        "# lib\\nmap_Kd tex.png\\nnewmtl a\\n | lib.mtl:2: map_Kd before any newmtl",
        "newmtl a\\nnewmtl   \\n | lib.mtl:2: newmtl without a material name",
    })
    void malformedLibrariesNameTheLibraryAndLine(String mtl, String expected) throws IOException {
        write("lib.mtl", mtl.replace("\\n", "\n"));
        Path obj = write("scene.obj", TRIANGLE_VERTICES + "mtllib lib.mtl\nf 1 2 3\n");
        assertEquals(expected, error(obj, true));
    }

    @Test
    void mtllibWithoutANameIsAnErrorWhenMaterialsAreRead() throws IOException {
        Path obj = write("scene.obj", TRIANGLE_VERTICES + "mtllib   # nothing\nf 1 2 3\n");
        assertEquals("scene.obj:4: mtllib without a file name", error(obj, true));
    }

    // ---- errors ----

    static Stream<Arguments> malformedFiles() {
        String eight = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n";
        return Stream.of(
            Arguments.of(eight + "f 1 2 3\n# fine so far\n\nf 1 2 9\nf 9 10 11\n",
                "scene.obj:12: vertex index 9 is out of range (8 vertices)"),
            Arguments.of("v 1 2 3\nv 0 0 0\nv 1 2 abc\nf 1 2 3\n",
                "scene.obj:3: malformed number 'abc' in vertex"),
            // Forward references are fine; the first face beyond the final count is reported.
            Arguments.of("f 1 2 3\nf 3 4 5 6\nf 7 8 9\n" + "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n",
                "scene.obj:2: vertex index 5 is out of range (4 vertices)"),
            Arguments.of(TRIANGLE_VERTICES + "vt 0 0\nf 1/1 2/1 3/1\nf 1/2 2/1 3/1\nf 1 2 4\n",
                "scene.obj:6: texture coordinate index 2 is out of range (1 texture coordinate)"),
            Arguments.of(TRIANGLE_VERTICES + "vn 0 0 1\nf 1//1 2//1 3//2\nvn 0 0 1\nf 1//3 2//1 3//1\n",
                "scene.obj:7: normal index 3 is out of range (2 normals)"),
            Arguments.of(TRIANGLE_VERTICES + "f 1 2 0\n",
                "scene.obj:4: vertex index 0 is not valid (OBJ indices start at 1)"),
            Arguments.of(TRIANGLE_VERTICES + "vt 0 0\nf 1/1 2/0 3/1\n",
                "scene.obj:5: texture coordinate index 0 is not valid (OBJ indices start at 1)"),
            Arguments.of(TRIANGLE_VERTICES + "vn 0 0 1\nf 1//0 2//1 3//1\n",
                "scene.obj:5: normal index 0 is not valid (OBJ indices start at 1)"),
            Arguments.of(TRIANGLE_VERTICES + "f -1 -2 -4\n",
                "scene.obj:4: vertex index -4 reaches before the first vertex (3 vertices defined so far)"),
            Arguments.of(TRIANGLE_VERTICES + "f 1/-1 2/-1 3/-1\nvt 0 0\n",
                "scene.obj:4: texture coordinate index -1 reaches before the first texture coordinate"
                    + " (0 texture coordinates defined so far)"),
            Arguments.of("vn 0 0 1\n" + TRIANGLE_VERTICES + "f 1//-1 2//-2 3//-1\n",
                "scene.obj:5: normal index -2 reaches before the first normal (1 normal defined so far)"),
            Arguments.of(TRIANGLE_VERTICES + "f 1 2 99999999999\n",
                "scene.obj:4: vertex index 99999999999 is out of range (too large)"),
            Arguments.of(TRIANGLE_VERTICES + "f 1 2\n", "scene.obj:4: face has 2 corners; needs at least 3"),
            Arguments.of(TRIANGLE_VERTICES + "f 1\n", "scene.obj:4: face has 1 corner; needs at least 3"),
            Arguments.of(TRIANGLE_VERTICES + "f # nothing\n", "scene.obj:4: face has 0 corners; needs at least 3"),
            Arguments.of("v 1 2\n", "scene.obj:1: vertex has 2 coordinates; needs x y z"),
            Arguments.of("v 0 0 0\nv\n", "scene.obj:2: vertex has 0 coordinates; needs x y z"),
            Arguments.of("v 1 2 3 w\n", "scene.obj:1: malformed number 'w' in vertex"),
            Arguments.of("v 1,5 2 3\n", "scene.obj:1: malformed number '1,5' in vertex"),
            Arguments.of("vt\n", "scene.obj:1: texture coordinate without u"),
            Arguments.of("vt 0.5 zz\n", "scene.obj:1: malformed number 'zz' in texture coordinate"),
            Arguments.of("vt 0.5 0.5 nix\n", "scene.obj:1: malformed number 'nix' in texture coordinate"),
            Arguments.of(TRIANGLE_VERTICES + "vn 0 1\nf 1//1 2//1 3//1\n", "scene.obj:4: normal has 2 coordinates; needs x y z"),
            Arguments.of("vn\n", "scene.obj:1: normal has 0 coordinates; needs x y z"),
            Arguments.of("vn 0 1 up\n", "scene.obj:1: malformed number 'up' in normal"),
            Arguments.of("vn 0 1 0 x\n", "scene.obj:1: malformed number 'x' in normal"),
            Arguments.of(TRIANGLE_VERTICES + "vn 0 0 1\nf 1//1 2//1 3//1/\n", "scene.obj:5: malformed face corner '3//1/'"),
            Arguments.of(TRIANGLE_VERTICES + "vn 0 0 1\nf 1//1 2//1 3//x\n", "scene.obj:5: malformed face corner '3//x'"),
            Arguments.of("v 0 0 0\nusemtl\n", "scene.obj:2: usemtl without a material name"),
            // Errors name the line a continued statement starts on, and later lines keep their numbers.
            Arguments.of("v 0 0 0\nv 1 \\\n 0 0\nv 0 1 0\nf 1 2 \\\n 3 \\\n 0\n",
                "scene.obj:5: vertex index 0 is not valid (OBJ indices start at 1)"),
            Arguments.of("v 0 \\\r\n0 0\r\nv 1 2 q\r\n", "scene.obj:3: malformed number 'q' in vertex"),
            Arguments.of("v 0 0 \u0085x\n", "scene.obj:1: malformed number '\\x85x' in vertex"),
            Arguments.of("v 0 0 " + "9".repeat(30) + "x\n",
                "scene.obj:1: malformed number '" + "9".repeat(30) + "x" + "' in vertex"),
            Arguments.of("v 0 0 " + "7".repeat(50) + "x\n",
                "scene.obj:1: malformed number '" + "7".repeat(40) + "...' in vertex"),
            Arguments.of("", "scene.obj: no faces or lines"),
            Arguments.of("# nothing\n\n", "scene.obj: no faces or lines"),
            Arguments.of(TRIANGLE_VERTICES + "vt 0 0\n", "scene.obj: no faces or lines"));
    }

    @ParameterizedTest
    @MethodSource("malformedFiles")
    void malformedFilesGiveOneLineNamingFileAndLine(String text, String expected) throws IOException {
        assertEquals(expected, error(text));
    }

    @ParameterizedTest
    @ValueSource(strings = {"1/", "/1", "1/2/3/4", "a", "1//", "1.5", "1/2/", "--1", "1/+", "1/x/1", "//", "1e2"})
    void malformedCornersAreErrors(String corner) throws IOException {
        assertEquals("scene.obj:6: malformed face corner '" + corner + "'",
                error(TRIANGLE_VERTICES + "vt 0 0\nvn 0 0 1\nf 1 2 " + corner + "\n"));
    }

    @Test
    void namesTheFileAsGiven() throws IOException {
        write("sub/keep", "");
        write("scene.obj", "v 0 0 x\n");
        assertEquals("sub/../scene.obj:1: malformed number 'x' in vertex", error(dir.resolve("sub/../scene.obj"), false));
    }

    @Test
    void unreadablePathsAreReportedWithoutALine() throws IOException {
        assertEquals("nothing.obj: cannot read: no such file", error(dir.resolve("nothing.obj"), false));
        Files.createDirectories(dir.resolve("folder.obj"));
        assertEquals("folder.obj: cannot read: is a directory", error(dir.resolve("folder.obj"), false));
    }

    @Test
    void overlongLinesAreRefusedRatherThanExhaustingMemory() throws IOException {
        byte[] bytes = new byte[LineScanner.MAX_LINE + 10];
        Arrays.fill(bytes, (byte) '7');
        bytes[0] = 'v';
        bytes[1] = ' ';
        Path file = dir.resolve("long.obj");
        Files.write(file, bytes);
        assertEquals("long.obj:1: line is longer than " + LineScanner.MAX_LINE + " characters", error(file, false));
    }

    // ---- robustness ----

    private static final String[] WORDS = {
        "v", "vt", "vn", "f", "usemtl", "mtllib", "o", "g", "s", "#", "\\", "1", "2", "3", "-1", "-2", "0", "-0",
        "+1", "1/1", "1/1/1", "1//1", "-1/-1", "2/", "/", "//", "1.5", "nan", "-inf", "1e40", "0x1p3", "abc", "",
        "99999999999", "-99999999999", "lib.mtl", "none.mtl", "newmtl", "map_Kd", "\u00ff", "\u0000", "\t", "\r",
    };

    @Test
    @org.junit.jupiter.api.Timeout(120) // a guard against hanging: no input may make the reader loop
    void randomBytesGiveAModelOrAnInputExceptionAndNothingElse() throws IOException {
        write("lib.mtl", "newmtl a\nmap_Kd a.png\n");
        {
            Random random = new Random(12345);
            for (int round = 0; round < 1500; round++) {
                byte[] bytes = new byte[random.nextInt(600)];
                random.nextBytes(bytes);
                if (round % 2 == 0) {
                    // Mostly OBJ-like bytes, so that the parser gets past the first line.
                    byte[] alphabet = "vtnf/ -0123\n\\#".getBytes(StandardCharsets.US_ASCII);
                    for (int i = 0; i < bytes.length; i++) {
                        if (random.nextInt(8) != 0) {
                            bytes[i] = alphabet[random.nextInt(alphabet.length)];
                        }
                    }
                }
                Path file = dir.resolve("fuzz.obj");
                Files.write(file, bytes);
                readSafely(file, round % 3 == 0, "round " + round);
            }
        }
    }

    @Test
    @org.junit.jupiter.api.Timeout(120) // a guard against hanging: no input may make the reader loop
    void garbageLinesGiveAModelOrAnInputExceptionAndNothingElse() throws IOException {
        write("lib.mtl", "newmtl a\nmap_Kd a.png\n");
        write("bad.mtl", "newmtl a\nmap_Kd\n");
        int[] outcomes = new int[2];
        {
            Random random = new Random(777);
            for (int round = 0; round < 4000; round++) {
                StringBuilder sb = new StringBuilder("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\n"
                        + "vt 0 1\nvt 1 1\nvn 0 0 1\nvn 0 1 0\nvn 1 0 0\nvn 0 0 -1\n");
                int lines = 1 + random.nextInt(8);
                for (int l = 0; l < lines; l++) {
                    garbageStatement(random, sb);
                    sb.append(random.nextInt(5) == 0 ? "\r\n" : "\n");
                }
                boolean ok = readSafely(write("fuzz.obj", sb.toString()), random.nextBoolean(), "input:\n" + sb);
                outcomes[ok ? 1 : 0]++;
            }
        }
        // The generator must reach both outcomes often, or it tests little.
        assertTrue(outcomes[0] > 400 && outcomes[1] > 400, Arrays.toString(outcomes));
    }

    /** Appends a statement that is mostly plausible OBJ, with now and then a wrong word. */
    private static void garbageStatement(Random random, StringBuilder sb) {
        String[] keywords = {"v", "vt", "vn", "f", "f", "f", "usemtl", "mtllib", "g", "#"};
        String keyword = keywords[random.nextInt(keywords.length)];
        sb.append(keyword);
        // Mostly the right number of arguments, sometimes one too few.
        int least = keyword.equals("f") || keyword.equals("v") ? 3 : 1;
        int args = Math.max(0, least + random.nextInt(3) - (random.nextInt(10) == 0 ? 2 : 0));
        for (int a = 0; a < args; a++) {
            sb.append(random.nextInt(6) == 0 ? "\t" : " ");
            if (random.nextInt(25) == 0) {
                sb.append(WORDS[random.nextInt(WORDS.length)]);
            } else if (keyword.startsWith("v")) {
                String[] numbers = {"0", "1.5", "-2", "1e40", "nan", "-inf", "3"};
                sb.append(numbers[random.nextInt(numbers.length)]);
            } else if (keyword.equals("f")) {
                String[] forms = {"%s", "%s/%s", "%s/%s/%s", "%s//%3$s"};
                sb.append(String.format(forms[random.nextInt(forms.length)],
                        randomIndex(random), randomIndex(random), randomIndex(random)));
            } else {
                String[] names = {"a", "b", "lib.mtl", "lib.mtl", "lib.mtl", "bad.mtl", "none.mtl"};
                sb.append(names[random.nextInt(names.length)]);
            }
        }
    }

    private static String randomIndex(Random random) {
        String[] rare = {"0", "2147483647", "99999999999", "-99999999999"};
        int k = random.nextInt(150);
        return k < rare.length ? rare[k] : k < 50 ? "-" + (1 + random.nextInt(4)) : "" + (1 + random.nextInt(4));
    }

    /**
     * Reads {@code file} and checks that the outcome is a consistent model or a proper InputException.
     *
     * @return whether a model was read
     */
    private static boolean readSafely(Path file, boolean readMaterials, String what) {
        ObjModel model;
        try {
            model = ObjReader.read(file, readMaterials);
        } catch (InputException e) {
            String message = e.getMessage();
            assertTrue(message.startsWith(file.toString()) || message.startsWith(file.resolveSibling("").toString()),
                    message + " for " + what);
            assertTrue(message.indexOf('\n') < 0 && message.indexOf('\r') < 0, message + " for " + what);
            return false;
        } catch (RuntimeException | Error e) {
            throw new AssertionError("unexpected " + e + " for " + what, e);
        }
        Mesh mesh = model.mesh();
        assertTrue(mesh.triangleCount() > 0, what);
        assertEquals(mesh.materialCount(), model.materialTextures().size(), what);
        for (int p : mesh.cornerPositions()) {
            assertTrue(p >= 0 && p < mesh.positionCount(), what);
        }
        for (int t : mesh.cornerUvs()) {
            assertTrue(t >= -1 && t < mesh.uvCount(), what);
        }
        for (int m : mesh.triangleMaterials()) {
            assertTrue(m >= 0 && m < mesh.materialCount(), what);
        }
        return true;
    }
}
