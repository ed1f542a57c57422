package dev.trisect.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.content.SceneAsset;
import dev.trisect.content.SceneLoader;
import dev.trisect.mesh.ObjReader;
import dev.trisect.texture.Texture;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ObjWriterTest {
    @TempDir
    Path dir;

    @Test
    void materialsWhoseCleanedNamesClashGetTexturesOfTheirOwn() throws IOException {
        MeshBuilder b = new MeshBuilder();
        int t = b.uv(0, 0);
        for (String name : new String[] {"a.b", "a_b", "A_B"}) {
            b.material(name);
            b.triangle(b.position(0, 0, 0), b.position(1, 0, 0), b.position(0, 1, 0), t, t, t);
        }
        Mesh mesh = b.build();
        List<Texture> textures = List.of(Texture.solid("r", 0xFFFF0000), Texture.solid("g", 0xFF00FF00),
                Texture.solid("b", 0xFF0000FF));
        List<Path> maps = ObjWriter.write(dir.resolve("e.obj"), mesh, textures);
        assertEquals(List.of("e-a_b.ppm", "e-a_b-2.ppm", "e-A_B-3.ppm"),
                maps.stream().map(p -> p.getFileName().toString()).toList());
        assertEquals("newmtl a.b\nmap_Kd e-a_b.ppm\nnewmtl a_b\nmap_Kd e-a_b-2.ppm\nnewmtl A_B\nmap_Kd e-A_B-3.ppm\n",
                Files.readString(dir.resolve("e.mtl")));
    }

    /**
     * Materials that share one texture share its file, written once: a model whose 200 materials named
     * one 4096x4096 map was exported as 200 copies of it (10 GB; found by the fault probe). Reading the
     * export back gives each material its texels.
     */
    @Test
    void materialsSharingATextureShareItsFile() throws IOException {
        MeshBuilder b = new MeshBuilder();
        int t = b.uv(0.5, 0.5);
        for (String name : new String[] {"a", "b", "c", "d"}) {
            b.material(name);
            b.triangle(b.position(0, 0, 0), b.position(1, 0, 0), b.position(0, 1, 0), t, t, t);
        }
        Texture shared = new Texture("shared", 2, 1, new int[] {0xFF102030, 0xFF405060});
        // c's texture has the same texels as the shared one but is another texture: a file of its own.
        Texture twin = new Texture("twin", 2, 1, new int[] {0xFF102030, 0xFF405060});
        List<Texture> textures = List.of(shared, shared, twin, shared);
        Path obj = dir.resolve("s.obj");
        List<Path> maps = ObjWriter.write(obj, b.build(), textures);
        assertEquals(List.of("s-a.ppm", "s-a.ppm", "s-c.ppm", "s-a.ppm"),
                maps.stream().map(p -> p.getFileName().toString()).toList());
        assertEquals(maps, ObjWriter.files(obj, b.build(), textures).subList(2, 6));
        try (var files = Files.list(dir)) {
            assertEquals(List.of("s-a.ppm", "s-c.ppm", "s.mtl", "s.obj"),
                    files.map(p -> p.getFileName().toString()).sorted().toList());
        }
        assertEquals("newmtl a\nmap_Kd s-a.ppm\nnewmtl b\nmap_Kd s-a.ppm\nnewmtl c\nmap_Kd s-c.ppm\nnewmtl d\n"
                + "map_Kd s-a.ppm\n", Files.readString(dir.resolve("s.mtl")));
        SceneAsset back = SceneLoader.load(obj, null, note -> { });
        for (int m = 0; m < textures.size(); m++) {
            assertArrayEquals(textures.get(m).argb(), back.textures().get(m).argb());
        }
    }

    /**
     * A texture with alpha (a cut-out and a translucent one) is written as a PAM with its alpha, an
     * opaque one as a PPM, and loading the OBJ back gives every texel as it was, alpha included: an
     * exported scene's transparency survives (a PPM would have made both opaque).
     */
    @Test
    void texturesWithAlphaAreWrittenAsPamAndReadBackAsTheyWere() throws IOException {
        MeshBuilder b = new MeshBuilder();
        int t = b.uv(0.5, 0.5);
        for (String name : new String[] {"cut", "glass", "wall"}) {
            b.material(name);
            b.triangle(b.position(0, 0, 0), b.position(1, 0, 0), b.position(0, 1, 0), t, t, t);
        }
        List<Texture> textures = List.of(new Texture("cut", 2, 1, new int[] {0xFF102030, 0x00405060}),
                new Texture("glass", 2, 1, new int[] {0x80FF0000, 0xFF00FF00}),
                new Texture("wall", 2, 1, new int[] {0xFF010203, 0xFFFFFFFF}));
        Path obj = dir.resolve("a.obj");
        List<Path> maps = ObjWriter.write(obj, b.build(), textures);
        assertEquals(List.of("a-cut.pam", "a-glass.pam", "a-wall.ppm"),
                maps.stream().map(p -> p.getFileName().toString()).toList());
        assertEquals(maps, ObjWriter.files(obj, b.build(), textures).subList(2, 5));
        SceneAsset back = SceneLoader.load(obj, null, note -> { });
        for (int m = 0; m < textures.size(); m++) {
            assertArrayEquals(textures.get(m).argb(), back.textures().get(m).argb(), textures.get(m).name());
            assertEquals(textures.get(m).alpha(), back.textures().get(m).alpha(), textures.get(m).name());
        }
    }

    /**
     * Normals are written as {@code vn} and each corner names what it has ({@code v}, {@code v/vt},
     * {@code v//vn}, {@code v/vt/vn}), so reading the file back gives the same mesh, array for array.
     */
    @Test
    void normalsAreWrittenAndReadBackAsTheyWere() throws IOException {
        MeshBuilder b = new MeshBuilder();
        b.position(0, 0, 0);
        b.position(1, 0, 0);
        b.position(0, 1, 0);
        b.uv(0.25, 0.5);
        b.normal(0, 0, 1);
        b.normal(0.1f, -2, 3e-7);
        b.triangle(0, 1, 2, -1, 0, -1, -1, -1, 1);
        b.triangle(2, 1, 0, 0, 0, 0, 0, 1, 0);
        Mesh mesh = b.build();
        Path obj = dir.resolve("n.obj");
        ObjWriter.write(obj, mesh, List.of(Texture.solid("w", 0xFFFFFFFF)));
        List<String> lines = Files.readAllLines(obj);
        assertEquals(List.of("vn 0.0 0.0 1.0", "vn 0.1 -2.0 3.0E-7", "f 1 2/1 3//2", "f 3/1/1 2/1/2 1/1/1"),
                lines.stream().filter(l -> l.startsWith("vn") || l.startsWith("f")).toList());
        Mesh back = ObjReader.read(obj, false).mesh();
        assertArrayEquals(mesh.positions(), back.positions());
        assertArrayEquals(mesh.uvs(), back.uvs());
        assertArrayEquals(mesh.normals(), back.normals());
        assertArrayEquals(mesh.cornerPositions(), back.cornerPositions());
        assertArrayEquals(mesh.cornerUvs(), back.cornerUvs());
        assertArrayEquals(mesh.cornerNormals(), back.cornerNormals());
    }

    @Test
    void aMeshWithoutNormalsIsWrittenWithoutVn() throws IOException {
        MeshBuilder b = new MeshBuilder();
        b.triangle(b.position(0, 0, 0), b.position(1, 0, 0), b.position(0, 1, 0), -1, -1, -1);
        Path obj = dir.resolve("plain.obj");
        ObjWriter.write(obj, b.build(), List.of(Texture.solid("w", 0xFFFFFFFF)));
        assertEquals("# written by Trisect\nmtllib plain.mtl\nv 0.0 0.0 0.0\nv 1.0 0.0 0.0\nv 0.0 1.0 0.0\n"
                + "usemtl default\nf 1 2 3\n", Files.readString(obj));
    }
}
