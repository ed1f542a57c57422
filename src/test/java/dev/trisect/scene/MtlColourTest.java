package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.base.InputException;
import dev.trisect.io.ImageFiles;
import dev.trisect.mesh.ObjModel;
import dev.trisect.mesh.ObjReader;
import dev.trisect.render.Colour;
import dev.trisect.render.Shading;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.OptionalInt;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * MTL Kd: a material with a colour and no texture is that colour, not the UV grid; with a texture,
 * Kd is its diffuse colour under light and the texture shows unchanged. Ka is the ambient colour, the
 * factor of the ambient light reflected: lit by ambient light alone, a face shows Ka times that light.
 */
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

    @Test
    void kdWithMapKdIsTheDiffuseColourUnderLight() throws Exception {
        ImageFiles.write(dir.resolve("t.png"), 2, 2, new int[] {0xFF102030, 0xFF405060, 0xFF708090, 0xFFA0B0C0});
        Files.writeString(dir.resolve("m.mtl"), "newmtl lit\nKd 1 0.5 0\nmap_Kd t.png\nnewmtl plain\nmap_Kd t.png\n");
        Files.writeString(dir.resolve("m.obj"), "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                + "usemtl lit\nf 1 2 3\nusemtl plain\nf 1 3 2\n");
        SceneObject o = SceneObject.load(ObjReader.read(dir.resolve("m.obj"), true), "m.obj", note -> { }, false);
        Material lit = o.materials().get(0);
        Material plain = o.materials().get(1);
        assertEquals(Colour.of(0xFF8000), lit.diffuse());
        assertEquals(Colour.WHITE, plain.diffuse());
        assertSame(lit.texture(), plain.texture(), "one texture, read once");
        assertEquals(Shading.NONE, lit.shading(), "unlit unless asked: the texture shows as it is");
    }

    @Test
    void kaIsTheAmbientColourUnderLight() throws Exception {
        Files.writeString(dir.resolve("m.mtl"), "newmtl dim\nKd 1 1 1\nKa 0.5 0.25 0\nnewmtl grey\nKa 0.2\n"
                + "newmtl none\nKd 1 1 1\nnewmtl dim\nKa 1 0 1\nnewmtl again\nKa 0 1 0\n");
        Files.writeString(dir.resolve("m.obj"), "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                + "usemtl dim\nf 1 2 3\nusemtl grey\nf 1 3 2\nusemtl none\nf 2 1 3\nusemtl again\nf 3 2 1\n");
        ObjModel model = ObjReader.read(dir.resolve("m.obj"), true);
        assertEquals(Arrays.asList(0xFF00FF, 0x333333, null, 0x00FF00), model.materialAmbients(),
                "the last definition of a material wins; one number is a grey level");
        SceneObject o = SceneObject.load(model, "m.obj", note -> { }, false);
        assertEquals(Colour.of(0xFF00FF), o.materials().get(0).ambient());
        assertEquals(Colour.of(0x333333), o.materials().get(1).ambient());
        assertEquals(Colour.WHITE, o.materials().get(2).ambient(), "no Ka: the default, white");
        assertEquals(Colour.WHITE, o.materials().get(0).diffuse(), "Kd of the redefinition: none");
    }

    @Test
    void aMalformedKaNamesItsLine() throws Exception {
        Files.writeString(dir.resolve("m.mtl"), "newmtl a\nKa 1 x 0\n");
        Files.writeString(dir.resolve("m.obj"), "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
        InputException e = assertThrows(InputException.class, () -> ObjReader.read(dir.resolve("m.obj"), true));
        assertTrue(e.getMessage().contains("m.mtl:2") && e.getMessage().contains("Ka"), e.getMessage());
    }
}
