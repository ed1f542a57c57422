package dev.trisect.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.base.InputException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** OBJ and MTL defects of issue 10: byte-order marks, line endings, comments, map_Kd options and names. */
class ObjReaderRobustnessTest {
    private static final byte[] BOM = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};

    @TempDir
    Path dir;

    private Path write(String name, byte[] prefix, String text) throws IOException {
        Path file = dir.resolve(name);
        byte[] body = text.getBytes(StandardCharsets.UTF_8);
        byte[] all = Arrays.copyOf(prefix, prefix.length + body.length);
        System.arraycopy(body, 0, all, prefix.length, body.length);
        Files.write(file, all);
        return file;
    }

    private Path write(String name, String text) throws IOException {
        return write(name, new byte[0], text);
    }

    private String error(Path obj) {
        InputException e = assertThrows(InputException.class, () -> ObjReader.read(obj, true));
        String prefix = dir + dir.getFileSystem().getSeparator();
        assertTrue(e.getMessage().startsWith(prefix), e.getMessage());
        return e.getMessage().substring(prefix.length());
    }

    @Test
    void aByteOrderMarkIsSkippedInObjAndMtl() throws IOException {
        Path obj = write("m.obj", BOM, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assertEquals(3, ObjReader.read(obj, false).mesh().positions().length / 3, "the first vertex is kept");
        write("m.mtl", BOM, "newmtl a\nmap_Kd a.png\n");
        Path withLib = write("n.obj", BOM, "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
        assertEquals(List.of(dir.resolve("a.png").toAbsolutePath()), ObjReader.read(withLib, true).materialTextures());
    }

    @Test
    void crOnlyLineEndingsSeparateLines() throws IOException {
        Path obj = write("m.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\rv 1 q 0\r");
        assertEquals("m.obj:5: malformed number 'q' in vertex", error(obj));
        Path mixed = write("x.obj", "v 0 0 0\r\nv 1 0 0\rv 0 1 0\n\rf 1 2 3\r\r\nf 1 2 9\r");
        assertEquals("x.obj:7: vertex index 9 is out of range (3 vertices)", error(mixed));
    }

    /**
     * The OBJ specification says comments are not processed, so a backslash at the end of a comment
     * is comment text and continues nothing; the next line is read as a statement of its own.
     */
    @Test
    void aCommentEndingInABackslashDoesNotSwallowTheNextLine() throws IOException {
        Path obj = write("m.obj", "# a folder C:\\models\\\nv 0 0 0\nv 1 0 0 # note \\\nv 0 1 0\nf 1 2 3\n");
        assertEquals(9, ObjReader.read(obj, false).mesh().positions().length);
        // A statement still continues.
        Path cont = write("c.obj", "v 0 0 \\\n 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assertEquals(9, ObjReader.read(cont, false).mesh().positions().length);
    }

    @Test
    void mapKdFileNamesMayContainSpaces() throws IOException {
        write("m.mtl", "newmtl a\nmap_Kd my tex.png\nnewmtl b\nmap_Kd -s 2 2 1 dir/two  spaces.png\n");
        Path obj = write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\n");
        assertEquals(List.of(dir.resolve("my tex.png").toAbsolutePath(), dir.resolve("dir/two  spaces.png")
                .toAbsolutePath()), ObjReader.read(obj, true).materialTextures());
    }

    @Test
    void mapKdScaleAndOffsetApplyToTheMaterialsTexelCoordinates() throws IOException {
        write("m.mtl", "newmtl a\nmap_Kd -s 2 3 1 -o 0.5 0.25 t.png\nnewmtl b\nmap_Kd -o 1 t.png\n"
                + "newmtl c\nmap_Kd t.png\n");
        Path obj = write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                + "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 2/2 3/3\nusemtl c\nf 1/1 2/2 3/3\n");
        Mesh mesh = ObjReader.read(obj, true).mesh();
        float[][] expected = {
            {0.5f, 0.25f, 2.5f, 0.25f, 0.5f, 3.25f}, // u * 2 + 0.5, v * 3 + 0.25
            {1f, 0f, 2f, 0f, 1f, 1f},                  // u + 1
            {0f, 0f, 1f, 0f, 0f, 1f}};                 // as written
        for (int t = 0; t < 3; t++) {
            float[] uv = new float[6];
            for (int k = 0; k < 3; k++) {
                int i = mesh.cornerUvs()[3 * t + k];
                uv[2 * k] = mesh.uvs()[2 * i];
                uv[2 * k + 1] = mesh.uvs()[2 * i + 1];
            }
            assertArrayEquals(expected[t], uv, "triangle " + t);
        }
    }

    @Test
    void otherMapKdOptionsAreRefusedWithFileAndLine() throws IOException {
        write("m.mtl", "newmtl a\n\nmap_Kd -clamp on t.png\n");
        Path obj = write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
        assertEquals("m.mtl:3: map_Kd option '-clamp' is not supported (only -s and -o are)", error(obj));
        write("m.mtl", "newmtl a\nmap_Kd -s x t.png\n");
        assertEquals("m.mtl:2: map_Kd -s needs 1 to 3 numbers", error(obj));
        write("m.mtl", "newmtl a\nmap_Kd -s 1 1\n");
        assertEquals("m.mtl:2: map_Kd without a file name", error(obj));
    }
}
