package dev.trisect.content;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.base.InputException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A model whose map_Kd texture is missing (issue 18, defect 6): the demo shows it, renders refuse it. */
class SceneLoaderPlaceholderTest {
    @TempDir
    Path dir;

    private Path model() throws Exception {
        Files.writeString(dir.resolve("m.mtl"), "newmtl a\nmap_Kd gone.png\nnewmtl b\n");
        Path obj = dir.resolve("m.obj");
        Files.writeString(obj, "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                + "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 3/3 2/2\n");
        return obj;
    }

    @Test
    void aMissingTextureGetsAPlaceholderAndAWarningInsteadOfRejectingTheModel() throws Exception {
        List<String> notes = new ArrayList<>();
        SceneAsset s = SceneLoader.load(model(), null, notes::add, true);
        assertEquals(2, s.mesh().triangleCount(), "the whole model");
        assertEquals(java.util.Set.of(0xFFFF00FF, 0xFF000000), java.util.Arrays.stream(s.textures().get(0).argb())
                .boxed().collect(java.util.stream.Collectors.toSet()), "a magenta and black checkerboard");
        assertTrue(notes.stream().anyMatch(n -> n.startsWith(dir.resolve("m.mtl") + ":2: map_Kd: ")
                && n.contains("gone.png") && n.endsWith("drawn with a magenta checkerboard instead")), notes.toString());
    }

    @Test
    void rendersStillRefuseIt() throws Exception {
        Path obj = model();
        InputException e = assertThrows(InputException.class, () -> SceneLoader.load(obj, null, n -> { }));
        assertTrue(e.getMessage().contains("map_Kd"), e.getMessage());
    }
}
