package dev.trisect.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Reading OBJ geometry and materials (errors and fuzzing: ObjReaderErrorsTest). */
class ObjReaderTest extends ObjFixture {
    // ---- geometry ----

    @Test
    void normalsWithoutADirectionGetOneNoteNamingTheFileAndTheFirstLine() throws IOException {
        Path obj = write("n.obj", TRIANGLE_VERTICES + "vn 0 0 1\nvn nan 0 1\nvn 0 0 0\nvn 1e39 0 0\nvn 1e-50 0 0\n"
                + "vn 1e-40 0 0\nf 1//1 2//2 3//3\nf 1//4 2//5 3//6\n");
        List<String> notes = new java.util.ArrayList<>();
        ObjModel model = ObjReader.read(obj, false, notes::add);
        assertEquals(List.of(obj + ":5: normal (vn) without a direction (NaN, infinite or zero length), as are 3 "
                + "more: lit corners that use them take the ambient light alone"), notes,
                "NaN, zero, overflowing to infinity, underflowing to zero; 1e-40 (subnormal) has a direction");
        assertArrayEquals(new float[] {0, 0, 1, Float.NaN, 0, 1, 0, 0, 0, Float.POSITIVE_INFINITY, 0, 0, 0, 0, 0,
            1e-40f, 0, 0}, model.mesh().normals(), "kept as written");
        double[] n = new double[3];
        model.mesh().cornerNormal(5, n, 0);
        assertArrayEquals(new double[] {1, 0, 0}, n, "the subnormal one is a direction, as the note says");
        model.mesh().cornerNormal(1, n, 0);
        assertArrayEquals(new double[] {0, 0, 0}, n, "the NaN one is none");

        notes.clear();
        ObjReader.read(write("one.obj", TRIANGLE_VERTICES + "vn 0 0 0\nf 1//1 2//1 3//1\n"), false, notes::add);
        assertEquals(List.of(dir.resolve("one.obj") + ":4: normal (vn) without a direction (NaN, infinite or zero "
                + "length): lit corners that use it take the ambient light alone"), notes);
        notes.clear();
        ObjReader.read(write("fine.obj", TRIANGLE_VERTICES + "vn 0 0 2\nf 1//1 2//1 3//1\n"), false, notes::add);
        assertEquals(List.of(), notes, "a normal of any length with a direction is fine");
    }

    @Test
    void usemtlOfAMaterialNoLibraryDefinesGetsOneNote() throws IOException {
        write("m.mtl", "newmtl wood\nKd 0.5 0.3 0.1\nnewmtl bare\n");
        Path obj = write("typo.obj", "mtllib m.mtl\n" + TRIANGLE_VERTICES + "usemtl wood\nf 1 2 3\nusemtl wod\n"
                + "f 1 2 3\nusemtl bare\nf 1 2 3\nusemtl stone\nf 1 2 3\nusemtl wod\nf 1 2 3\n");
        List<String> notes = new java.util.ArrayList<>();
        ObjReader.read(obj, true, notes::add);
        assertEquals(List.of(obj + ":7: usemtl wod: no mtllib of the file defines it, nor stone"), notes,
                "the first line of the first undefined name; a defined material without statements is fine");
        notes.clear();
        ObjReader.read(obj, false, notes::add);
        assertEquals(List.of(), notes, "libraries not read: nothing to say");
        notes.clear();
        ObjReader.read(write("none.obj", TRIANGLE_VERTICES + "usemtl wood\nf 1 2 3\n"), true, notes::add);
        assertEquals(List.of(dir.resolve("none.obj") + ":4: usemtl wood: no mtllib of the file defines it"), notes);
        notes.clear();
        ObjReader.read(write("plain.obj", TRIANGLE_VERTICES + "f 1 2 3\n"), true, notes::add);
        assertEquals(List.of(), notes, "no usemtl: the default material needs no library");
    }

    @Test
    void readsPositionsAndTextureCoordinates() throws IOException {
        Mesh mesh = read("v 1 2 3\nv -4.5 5e1 0.25 1.0\nv 7 8 9 0.5 0.5 0.5\n"
                + "vt 0.25 0.75\nvt 0.5\nvt 1 2 3\nf 1/1 2/2 3/3\n").mesh();
        assertArrayEquals(new float[] {1, 2, 3, -4.5f, 50, 0.25f, 7, 8, 9}, mesh.positions());
        assertArrayEquals(new float[] {0.25f, 0.75f, 0.5f, 0, 1, 2}, mesh.uvs());
        assertArrayEquals(new int[] {0, 1, 2}, mesh.cornerPositions());
        assertArrayEquals(new int[] {0, 1, 2}, mesh.cornerUvs());
    }

    @Test
    void fanTriangulatesPolygonsAndNumbersTrianglesInFileOrder() throws IOException {
        Mesh mesh = read("v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\n"
                + "f 1 2 3\nf 1 2 3 4 5\nf 5 4 3 2\n").mesh();
        assertEquals(1 + 3 + 2, mesh.triangleCount());
        assertArrayEquals(new int[] {
            0, 1, 2,
            0, 1, 2, 0, 2, 3, 0, 3, 4,
            4, 3, 2, 4, 2, 1}, mesh.cornerPositions());
    }

    @Test
    void negativeIndicesCountBackFromTheLineTheyAreOn() throws IOException {
        Mesh mesh = read("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\n"
                + "f -3/-2 -2/-1 -1/-1\n"
                + "v 5 5 5\nvt 0 1\n"
                + "f -1/-1 -2/-2 -4/-3\n").mesh();
        assertArrayEquals(new int[] {0, 1, 2, 3, 2, 0}, mesh.cornerPositions());
        assertArrayEquals(new int[] {0, 1, 1, 2, 1, 0}, mesh.cornerUvs());
    }

    @Test
    void positiveIndicesMayReferToElementsDefinedLater() throws IOException {
        Mesh mesh = read("f 1/1 2/2 3/3\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n").mesh();
        assertArrayEquals(new int[] {0, 1, 2}, mesh.cornerPositions());
        assertArrayEquals(new int[] {0, 1, 2}, mesh.cornerUvs());
    }

    @Test
    void mixesCornerFormatsAndGivesCornersWithoutVtNoUv() throws IOException {
        Mesh mesh = read(TRIANGLE_VERTICES + "v 1 1 0\nvt 0 0\nvt 1 1\nvn 0 0 1\n"
                + "f 1 2/1 3/2/1 4//1\n").mesh();
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, mesh.cornerPositions());
        assertArrayEquals(new int[] {-1, 0, 1, -1, 1, -1}, mesh.cornerUvs());
    }

    @Test
    void readsNormalsAndTheNormalIndexOfEachCorner() throws IOException {
        Mesh mesh = read(TRIANGLE_VERTICES + "v 1 1 0\nvt 0 0\nvn 0 0 1\nvn 0.5 -2 1e1\n"
                + "f 1/1/2 2//1 3/1/1 4//-2\nf 3 2 1\n").mesh();
        assertEquals(2, mesh.normalCount());
        assertArrayEquals(new float[] {0, 0, 1, 0.5f, -2, 10}, mesh.normals());
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3, 2, 1, 0}, mesh.cornerPositions());
        assertArrayEquals(new int[] {1, 0, 0, 1, 0, 0, -1, -1, -1}, mesh.cornerNormals());
        assertArrayEquals(new int[] {0, -1, 0, 0, 0, -1, -1, -1, -1}, mesh.cornerUvs());
    }

    /**
     * A corner with a normal has it made unit length; one without has its triangle's face normal, the
     * side from which the corners run counter-clockwise (the second face is wound clockwise seen from
     * +z, so it faces -z), corner by corner within one face.
     */
    @Test
    void cornersWithoutANormalTakeTheirTrianglesFaceNormal() throws IOException {
        Mesh mesh = read("v 0 0 0\nv 2 0 0\nv 0 3 0\nvn 0 3 4\n"
                + "f 1//1 2 3\nf 1 3 2\nv 5 5 5\nf 1 1 4\n").mesh();
        double[] n = new double[9 * 3];
        for (int c = 0; c < 9; c++) {
            mesh.cornerNormal(c, n, 3 * c);
        }
        assertArrayEquals(new double[] {
            0, 0.6, 0.8, 0, 0, 1, 0, 0, 1,
            0, 0, -1, 0, 0, -1, 0, 0, -1,
            0, 0, 0, 0, 0, 0, 0, 0, 0}, n, 1e-15);
    }

    @ParameterizedTest
    @CsvSource({
        "1, 1",
        "-2.5, -2.5",
        "1e3, 1000",
        ".5, 0.5",
        "5., 5",
        "0x1p-2, 0.25",
        "1f, 1",
        // Rounded once, to float, as OpenGL's float inputs are; via double it would be 1.0000002.
        "1.00000017881393431, 1.0000001",
        "16777217, 16777216",
        "1e-50, 0",
        "nan, NaN",
        "NaN, NaN",
        "-NAN, NaN",
        "inf, Infinity",
        "+Inf, Infinity",
        "-inf, -Infinity",
        "infinity, Infinity",
        "-INFINITY, -Infinity",
        "Infinity, Infinity",
    })
    void parsesNumbersLikeFloatParseFloatAndCSpecialValues(String text, float expected) throws IOException {
        Mesh mesh = read("v " + text + " 0 0\nv 1 0 0\nv 0 1 0\nvt 0 " + text + "\nf 1/1 2/1 3/1\n").mesh();
        assertEquals(Float.floatToIntBits(expected), Float.floatToIntBits(mesh.positions()[0]), text);
        assertEquals(Float.floatToIntBits(expected), Float.floatToIntBits(mesh.uvs()[1]), text);
    }

    @Test
    void skipsWhatCarriesNoGeometryAndHandlesLineFormats() throws IOException {
        String text = "# comment\r\n"
                + "\r\n"
                + "o thing\r\n"
                + "g group\n"
                + "s 1\n"
                + "   v 0 0 0   \r\n"
                + "\tv 1 \\\r\n"
                + "  0 0\n"
                + "v 0 1 0 # trailing comment\n"
                + "vp 0.5\n"
                + "l 1 2\n"
                + "p 1\n"
                + "curv 0 1 1 2\n"
                + "frobnicate whatever\n"
                + "f 1 2 \\\n"
                + "3\n";
        Mesh mesh = read(text).mesh();
        assertArrayEquals(new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, mesh.positions());
        assertArrayEquals(new int[] {0, 1, 2}, mesh.cornerPositions());
    }

    @Test
    void theLastLineNeedsNoNewlineEvenWhenContinued() throws IOException {
        assertEquals(1, read(TRIANGLE_VERTICES + "f 1 2 3").mesh().triangleCount());
        assertEquals(1, read(TRIANGLE_VERTICES + "f 1 2 3 \\").mesh().triangleCount());
        assertEquals(1, read(TRIANGLE_VERTICES + "f 1 2 3 \\\n").mesh().triangleCount());
    }

    @Test
    void namesAreUtf8AndOtherBytesAnywhereElseAreHarmless() throws IOException {
        Path file = dir.resolve("utf8.obj");
        byte[] head = (TRIANGLE_VERTICES + "usemtl caf\u00e9 \u00ff\n").getBytes(StandardCharsets.UTF_8);
        // A comment with bytes that are not UTF-8 is skipped as before.
        byte[] tail = {'#', (byte) 0x80, (byte) 0xC3, '\n', 'f', ' ', '1', ' ', '2', ' ', '3', '\n'};
        byte[] all = Arrays.copyOf(head, head.length + tail.length);
        System.arraycopy(tail, 0, all, head.length, tail.length);
        Files.write(file, all);
        assertEquals(List.of("caf\u00e9 \u00ff"), ObjReader.read(file, false).mesh().materialNames());
    }

    @Test
    void aNameThatIsNotUtf8IsRefusedWithItsBytes() throws IOException {
        Path file = dir.resolve("latin.obj");
        byte[] head = (TRIANGLE_VERTICES + "usemtl caf").getBytes(StandardCharsets.US_ASCII);
        byte[] tail = {(byte) 0xE9, ' ', (byte) 0xFF, '\n', 'f', ' ', '1', ' ', '2', ' ', '3', '\n'};
        byte[] all = Arrays.copyOf(head, head.length + tail.length);
        System.arraycopy(tail, 0, all, head.length, tail.length);
        Files.write(file, all);
        assertEquals("latin.obj:4: 'caf\\xE9 \\xFF' is not valid UTF-8", error(file, false));
    }

    @Test
    void libraryAndTextureNamesOutsideAsciiAreFound() throws IOException {
        // File names are bytes on Linux; Java maps them to strings through the locale's encoding.
        org.junit.jupiter.api.Assumptions.assumeTrue("UTF-8".equals(System.getProperty("sun.jnu.encoding")),
                "the JVM runs under a locale that is not UTF-8 (LANG=C.UTF-8 runs this test)");
        Files.writeString(dir.resolve("m\u00e4t.mtl"), "newmtl st\u00f6ne\nmap_Kd t\u00ebx.png\n", StandardCharsets.UTF_8);
        Path obj = dir.resolve("sc\u00e8ne.obj");
        Files.writeString(obj, TRIANGLE_VERTICES + "mtllib m\u00e4t.mtl\nusemtl st\u00f6ne\nf 1 2 3\n",
                StandardCharsets.UTF_8);
        ObjModel model = ObjReader.read(obj, true);
        assertEquals(List.of("st\u00f6ne"), model.mesh().materialNames());
        assertEquals(List.of(dir.resolve("t\u00ebx.png").toAbsolutePath()), model.materialTextures());
    }

    @Test
    @org.junit.jupiter.api.Timeout(120) // a guard against hanging, not a speed check
    void readsLargeFilesWithAMaterialForEveryFace() throws IOException {
        int n = 200_000;
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < n; i++) {
            sb.append("v ").append(i).append(" 0 0\nvt 0.5 0.5\n");
        }
        // A new material for every face: each gets its own index, in order of first use.
        for (int i = 0; i + 3 <= n; i += 3) {
            sb.append("usemtl m").append(i).append("\nf ").append(i + 1).append("/1 ").append(i + 2)
                    .append("/2 -1/-1\n");
        }
        Path file = write("big.obj", sb.toString());
        ObjModel model = ObjReader.read(file, false);
        assertEquals(n / 3, model.mesh().triangleCount());
        assertEquals(n / 3, model.mesh().materialCount());
        assertEquals(n, model.mesh().positionCount());
        assertEquals("m3", model.mesh().materialNames().get(1));
        assertEquals(1, model.mesh().triangleMaterials()[1]);
        assertEquals(n / 3 - 1, model.mesh().triangleMaterials()[n / 3 - 1]);
    }

    // ---- materials ----

    @Test
    void trianglesBeforeAnyUsemtlGetTheDefaultMaterialAsMeshBuilderGivesIt() throws IOException {
        MeshBuilder b = new MeshBuilder();
        b.position(0, 0, 0);
        b.position(1, 0, 0);
        b.position(0, 1, 0);
        b.triangle(0, 1, 2, -1, -1, -1);
        b.material("red");
        b.triangle(0, 1, 2, -1, -1, -1);
        Mesh expected = b.build();

        Mesh mesh = read(TRIANGLE_VERTICES + "f 1 2 3\nusemtl red\nf 1 2 3\n").mesh();
        assertEquals(expected.materialNames(), mesh.materialNames());
        assertArrayEquals(expected.triangleMaterials(), mesh.triangleMaterials());
        assertEquals(List.of("default", "red"), mesh.materialNames());
    }

    @Test
    void usemtlAssignsMaterialsInOrderOfFirstUse() throws IOException {
        Mesh mesh = read(TRIANGLE_VERTICES + "usemtl a\nf 1 2 3\nusemtl my  material\nf 1 2 3 1\n"
                + "usemtl a\nf 1 2 3\n").mesh();
        assertEquals(List.of("a", "my  material"), mesh.materialNames());
        assertArrayEquals(new int[] {0, 1, 1, 0}, mesh.triangleMaterials());
    }

    @Test
    void resolvesMaterialTexturesAgainstTheirLibraries() throws IOException {
        Path stone = dir.resolve("elsewhere/stone.png");
        write("mats/lib.mtl", "# made by hand\nnewmtl wood\nKd 1 1 1\nmap_Kd -s 2 2 1 -o 0 0 0 ../tex/./wood.png\n"
                + "newmtl plain\nKd 1 0 0\nnewmtl my material\nmap_Kd spaced.png\n");
        write("models/other.mtl", "newmtl stone\r\nmap_Kd " + stone + "\r\n");
        Path obj = write("models/scene.obj", TRIANGLE_VERTICES + "mtllib ../mats/lib.mtl other.mtl\n"
                + "f 1 2 3\nusemtl wood\nf 1 2 3\nusemtl stone\nf 1 2 3\nusemtl unknown\nf 1 2 3\n"
                + "usemtl plain\nf 1 2 3\nusemtl my material\nf 1 2 3\n");
        ObjModel model = ObjReader.read(obj, true);
        assertEquals(List.of("default", "wood", "stone", "unknown", "plain", "my material"),
                model.mesh().materialNames());
        assertEquals(Arrays.asList(null, dir.resolve("tex/wood.png").toAbsolutePath(), stone, null, null,
                dir.resolve("mats/spaced.png").toAbsolutePath()), model.materialTextures());
    }

    @Test
    void aMaterialDefinedAgainReplacesTheEarlierDefinition() throws IOException {
        write("one.mtl", "newmtl a\nmap_Kd a1.png\nnewmtl b\nmap_Kd b1.png\n");
        write("two.mtl", "newmtl a\nmap_Kd a2.png\nnewmtl b\n");
        Path obj = write("scene.obj", TRIANGLE_VERTICES + "mtllib one.mtl\nmtllib two.mtl one.mtl\n"
                + "usemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\n");
        assertEquals(Arrays.asList(dir.resolve("a2.png"), null), ObjReader.read(obj, true).materialTextures());
    }

    @Test
    void withoutMaterialsMtllibIsIgnoredButUsemtlStillNamesMaterials() throws IOException {
        write("real.mtl", "newmtl a\nmap_Kd a.png\n");
        Path obj = write("scene.obj", TRIANGLE_VERTICES + "mtllib missing.mtl\nmtllib real.mtl\nmtllib\n"
                + "usemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\n");
        ObjModel model = ObjReader.read(obj, false);
        assertEquals(List.of("a", "b"), model.mesh().materialNames());
        assertEquals(Arrays.asList(null, null), model.materialTextures());
    }

    @Test
    void modelRejectsATextureListThatDoesNotMatchTheMaterials() throws IOException {
        Mesh mesh = read(TRIANGLE_VERTICES + "f 1 2 3\n").mesh();
        assertThrows(IllegalArgumentException.class, () -> new ObjModel(mesh, List.of()));
        assertNull(new ObjModel(mesh, Arrays.asList((Path) null)).materialTextures().get(0));
    }
}
