package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.mesh.ObjModel;
import dev.trisect.mesh.ObjReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.OptionalInt;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** MTL Kd: a material with a colour and no texture is that colour, not the UV grid. */
class MtlColourTest {
    @TempDir
    Path dir;

    @Test
    void kdWithoutMapKdIsTheMaterialsColour() throws Exception {
        Files.writeString(dir.resolve("m.mtl"), "newmtl red\nKd 1 0 0\nnewmtl grey\nKd 0.5\nnewmtl bare\n");
        Files.writeString(dir.resolve("m.obj"), "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                + "usemtl red\nf 1 2 3\nusemtl grey\nf 1 3 2\nusemtl bare\nf 2 1 3\n");
        ObjModel model = ObjReader.read(dir.resolve("m.obj"), true);
        assertEquals(Arrays.asList(0xFF0000, 0x808080, null), model.materialColours());
        List<String> notes = new ArrayList<>();
        SceneObject o = SceneObject.load(model, "m.obj", notes::add, false);
        assertEquals(OptionalInt.of(0xFF0000), o.materials().get(0).rgb());
        assertEquals(OptionalInt.of(0x808080), o.materials().get(1).rgb());
        assertTrue(o.materials().get(2).rgb().isEmpty(), "no Kd, no map_Kd: the UV grid");
        assertEquals(1, notes.size());
        assertTrue(notes.get(0).contains("bare") && !notes.get(0).contains("red"), notes.get(0));
    }
}
