package dev.trisect.io;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
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
}
