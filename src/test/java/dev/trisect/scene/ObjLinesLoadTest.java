package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trisect.math.Vec3;
import dev.trisect.render.RenderSettings;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An OBJ file's {@code l} elements come with the object {@link SceneObject#load} makes, coloured by their
 * material's {@code Kd} as the command line draws them: a file of faces and lines keeps its lines, and a
 * file of lines alone is an object of lines (it was an object that drew nothing).
 */
class ObjLinesLoadTest {
    @TempDir
    Path dir;

    @Test
    void theFilesLinesAreTheObjectsLines() throws Exception {
        Files.writeString(dir.resolve("m.mtl"), "newmtl green\nKd 0 1 0\n");
        Files.writeString(dir.resolve("faces.obj"), "mtllib m.mtl\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\nv -1 1.5 0\nv 1 1.5 0\n"
                + "usemtl green\nf 1 2 3\nl 4 5\n");
        Files.writeString(dir.resolve("lines.obj"), "mtllib m.mtl\nv -1 0 0\nv 1 0 0\nusemtl green\nl 1 2\n");
        SceneObject faces = SceneObject.load(dir.resolve("faces.obj"));
        assertEquals(1, faces.mesh().triangleCount());
        assertEquals(1, faces.lines().segmentCount(), "the l element");
        assertEquals(0x00FF00, faces.lines().colours()[0] & 0xFFFFFF, "coloured by Kd");

        SceneObject lines = SceneObject.load(dir.resolve("lines.obj"));
        assertEquals(0, lines.mesh().triangleCount());
        Scene scene = new Scene();
        scene.add(lines);
        BufferedImage image = SceneRenderer.renderImage(scene, Camera.looking(new Vec3(0, 0, 3), Vec3.ZERO),
                RenderSettings.defaults(), 64, 64);
        int green = 0;
        for (int x = 0; x < 64; x++) {
            for (int y = 0; y < 64; y++) {
                green += (image.getRGB(x, y) & 0xFFFFFF) == 0x00FF00 ? 1 : 0;
            }
        }
        assertEquals(true, green > 20, "the line is drawn: " + green + " green pixels");
    }
}
