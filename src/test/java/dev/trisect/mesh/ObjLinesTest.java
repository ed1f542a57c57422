package dev.trisect.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import dev.trisect.base.InputException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** OBJ {@code l} elements: read as segments, coloured by their material's {@code Kd}. */
class ObjLinesTest {
    @TempDir
    Path dir;

    private Path write(String name, String text) throws IOException {
        Path file = dir.resolve(name);
        Files.writeString(file, text, StandardCharsets.UTF_8);
        return file;
    }

    @Test
    void aPolylineIsItsSegmentsBetweenConsecutivePointsColouredByKd() throws IOException {
        write("m.mtl", "newmtl red\nKd 1 0 0\nnewmtl grey\nKd 0.5\nnewmtl plain\nmap_Kd none.png\n");
        Path obj = write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\n"
                + "l 1 2\nusemtl red\nl 1/1 2/1 3/1 -1\nusemtl grey\nf 1 2 3\nl 4 1\nusemtl plain\nl 2 3\n");
        ObjModel model = ObjReader.read(obj, true);
        Lines lines = model.lines();
        assertEquals(6, lines.segmentCount());
        assertArrayEquals(new int[] {0, 1, 0, 1, 1, 2, 2, 3, 3, 0, 1, 2}, lines.segments());
        // Before any usemtl, and of a material without Kd: white, as OpenGL's current colour starts.
        assertArrayEquals(new int[] {0xFFFFFF, 0xFF0000, 0xFF0000, 0xFF0000, 0x808080, 0xFFFFFF}, lines.colours());
        // The segments index the mesh's own positions.
        assertSame(model.mesh().positions(), lines.points());
        assertEquals(1, model.mesh().triangleCount());
    }

    @Test
    void aFileOfLinesAloneIsAModelWithoutTriangles() throws IOException {
        ObjModel model = ObjReader.read(write("l.obj", "v 0 0 0\nv 1 2 3\nl 1 2\n"), false);
        assertEquals(0, model.mesh().triangleCount());
        assertEquals(1, model.lines().segmentCount());
    }

    @Test
    void aFileWithoutLinesHasNone() throws IOException {
        ObjModel model = ObjReader.read(write("f.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), false);
        assertSame(Lines.EMPTY, model.lines());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "v 0 0 0\\nl 1|l.obj:2: line has 1 point; needs at least 2",
        "v 0 0 0\\nl 1 7\\nv 1 1 1\\nf 1 2 1|l.obj:2: vertex index 7 is out of range (2 vertices)",
        "v 0 0 0\\nl 1 0|l.obj:2: vertex index 0 is not valid (OBJ indices start at 1)",
        "v 0 0 0\\nv 1 1 1\\nl 1 x|l.obj:3: malformed line point 'x'",
        "v 0 0 0\\nv 1 1 1\\nl 1 2/1/1/|l.obj:3: malformed line point '2/1/1/'",
    })
    void badLinesNameTheFileAndLine(String text, String expected) throws IOException {
        Path obj = write("l.obj", text.replace("\\n", "\n"));
        InputException e = assertThrows(InputException.class, () -> ObjReader.read(obj, false));
        assertEquals(expected, e.getMessage().substring(dir.toString().length() + 1));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "Kd 1 0|m.mtl:2: Kd needs r g b (or one grey level), got 2 values",
        "Kd spectral f.spd|m.mtl:2: Kd spectral is not supported: give r g b (or one grey level)",
        "Kd xyz 1 1 1|m.mtl:2: Kd xyz is not supported: give r g b (or one grey level)",
        "Ka xyz 1|m.mtl:2: Ka xyz is not supported: give r g b (or one grey level)",
        "Kd 1 q 0|m.mtl:2: Kd: malformed number 'q' (only the r g b form is supported)",
        "Kd NaN 0 0|m.mtl:2: Kd: 'NaN' is not a finite number: a colour must be finite",
        "Kd nan|m.mtl:2: Kd: 'nan' is not a finite number: a colour must be finite",
        "Ka inf 0 0|m.mtl:2: Ka: 'inf' is not a finite number: a colour must be finite",
        "Ka 1 -Infinity 0|m.mtl:2: Ka: '-Infinity' is not a finite number: a colour must be finite",
        "Kd 1 1 1e39|m.mtl:2: Kd: '1e39' is not a finite number (beyond float's 3.4e38): a colour must be finite",
    })
    void badKdNamesTheMtlFileAndLine(String kd, String expected) throws IOException {
        write("m.mtl", "newmtl a\n" + kd + "\n");
        Path obj = write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nusemtl a\nl 1 2\n");
        InputException e = assertThrows(InputException.class, () -> ObjReader.read(obj, true));
        assertEquals(expected, e.getMessage().substring(dir.toString().length() + 1));
    }
}
