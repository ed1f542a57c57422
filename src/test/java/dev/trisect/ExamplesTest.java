package dev.trisect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.examples.HeadlessRender;
import dev.trisect.examples.PickPixels;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The headless examples of src/examples/java run and do what they say. */
class ExamplesTest {
    @Test
    void headlessRenderWritesTheCubeOnItsGround(@TempDir Path dir) throws Exception {
        Path png = dir.resolve("cube.png");
        HeadlessRender.main(new String[] {png.toString()});
        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(640, image.getWidth());
        assertEquals(400, image.getHeight());
        assertEquals(0, image.getRGB(5, 5) & 0xFFFFFF, "black above the horizon");
        int crate = image.getRGB(320, 200);
        int r = crate >> 16 & 0xFF;
        int g = crate >> 8 & 0xFF;
        int b = crate & 0xFF;
        assertTrue(r > g && g > b && r > 60, "the crate's wood at the centre: " + Integer.toHexString(crate));
        int ground = image.getRGB(20, 390);
        assertTrue((ground & 0xFFFFFF) != 0, "the ground at the bottom");
    }

    @Test
    void pickPixelsNamesTheObjectsUnderKnownPixels() {
        PrintStream out = System.out;
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(bytes, true, StandardCharsets.UTF_8));
            PickPixels.main(new String[0]);
        } finally {
            System.setOut(out);
        }
        String[] lines = bytes.toString(StandardCharsets.UTF_8).split("\\R");
        assertEquals(3, lines.length, String.join("\n", lines));
        assertTrue(lines[0].startsWith("128,100: crate triangle "), lines[0]);
        assertTrue(lines[1].startsWith("191,100: ball triangle "), lines[1]);
        assertEquals("160,30: background", lines[2]);
    }
}
