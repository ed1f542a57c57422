package dev.trisect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.examples.HeadlessRender;
import dev.trisect.examples.LitCrates;
import dev.trisect.examples.PickPixels;
import dev.trisect.examples.TransparentPane;
import dev.trisect.examples.WireframeAxes;
import dev.trisect.render.RenderSettings;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The headless examples of src/examples/java run and do what they say; the overview's quick start compiles. */
class ExamplesTest {
    @Test
    void headlessRenderWritesTheCubeOnItsGround(@TempDir Path dir) throws Exception {
        Path png = dir.resolve("cube.png");
        HeadlessRender.main(new String[] {png.toString()});
        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(640, image.getWidth());
        assertEquals(400, image.getHeight());
        assertEquals(RenderSettings.SKY, image.getRGB(5, 5) & 0xFFFFFF, "the sky above the horizon, as in a view");
        int crate = image.getRGB(320, 200);
        int r = crate >> 16 & 0xFF;
        int g = crate >> 8 & 0xFF;
        int b = crate & 0xFF;
        assertTrue(r > g && g > b && r > 60, "the crate's wood at the centre: " + Integer.toHexString(crate));
        int ground = image.getRGB(20, 390);
        assertTrue((ground & 0xFFFFFF) != 0, "the ground at the bottom");
    }

    @Test
    void litCratesShowEachFaceOfACrateInItsOwnLight(@TempDir Path dir) throws Exception {
        Path png = dir.resolve("lit.png");
        LitCrates.main(new String[] {png.toString()});
        BufferedImage image = ImageIO.read(png.toFile());
        // The middle crate's top, front (+z) and right (+x) faces: the sun from (2, 3, 1) gives them
        // N·L = 0.80, 0.27 and 0.53, so the top is the brightest and the front the darkest; the blue
        // lamp in front of the crates tints the front more than the top.
        double[] top = mean(image, 312, 156, 8, 6);
        double[] front = mean(image, 295, 205, 8, 8);
        double[] side = mean(image, 345, 195, 8, 8);
        assertTrue(top[0] > side[0] + 15 && side[0] > front[0] + 15, "top " + top[0] + ", side " + side[0]
                + ", front " + front[0] + ": each face its own brightness");
        assertTrue(front[2] / front[0] > top[2] / top[0] + 0.1, "the lamp's blue on the front face");
    }

    /** Mean r, g, b of a w x h block at (x, y). */
    private static double[] mean(BufferedImage image, int x, int y, int w, int h) {
        double[] m = new double[3];
        for (int j = y; j < y + h; j++) {
            for (int i = x; i < x + w; i++) {
                int c = image.getRGB(i, j);
                m[0] += (c >> 16 & 0xFF) / (double) (w * h);
                m[1] += (c >> 8 & 0xFF) / (double) (w * h);
                m[2] += (c & 0xFF) / (double) (w * h);
            }
        }
        return m;
    }

    @Test
    void wireframeAxesDrawsItsLines(@TempDir Path dir) throws Exception {
        Path png = dir.resolve("wire.png");
        WireframeAxes.main(new String[] {png.toString()});
        BufferedImage image = ImageIO.read(png.toFile());
        // The axes, grid, ball's wire, box's wire and wire box; then the axes' labels.
        int[] wanted = {0xFF0000, 0x00FF00, 0x0000FF, 0x606060, 0xFF40FF, 0xFFC040, 0x40C0FF, 0xFF4040, 0x40FF40,
            0x4080FF};
        int[] found = new int[wanted.length];
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                for (int i = 0; i < wanted.length; i++) {
                    found[i] += (image.getRGB(x, y) & 0xFFFFFF) == wanted[i] ? 1 : 0;
                }
            }
        }
        for (int i = 0; i < wanted.length; i++) {
            assertTrue(found[i] > 20, Integer.toHexString(wanted[i]) + ": " + found[i] + " pixels");
        }
    }

    @Test
    void transparentPaneWritesItsImage(@TempDir Path dir) throws Exception {
        Path png = dir.resolve("pane.png");
        TransparentPane.main(new String[] {png.toString()});
        BufferedImage image = ImageIO.read(png.toFile());
        assertTrue(image.getWidth() == 640 && image.getHeight() == 400, image.toString());
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

    /**
     * The overview page's quick start is a whole program: its first code block, taken from the page as
     * Javadoc shows it, compiles on its own against the library (so the quick start alone is enough to
     * write the cube example).
     */
    @Test
    void theOverviewsQuickStartCompilesAsItStands(@TempDir Path dir) throws Exception {
        String page = Files.readString(Path.of("src/main/javadoc/overview.html"));
        Matcher m = Pattern.compile("(?s)<pre>\\{@code\\R(.*?)\\R}</pre>").matcher(page);
        assertTrue(m.find(), "a code block on the overview page");
        String code = m.group(1).replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&");
        Matcher name = Pattern.compile("public final class (\\w+)").matcher(code);
        assertTrue(name.find(), "the quick start is a class:\n" + code);
        Path source = dir.resolve(name.group(1) + ".java");
        Files.writeString(source, code);
        ByteArrayOutputStream errors = new ByteArrayOutputStream();
        int status = ToolProvider.getSystemJavaCompiler().run(null, null,
                new PrintStream(errors, true, StandardCharsets.UTF_8), "-d", dir.toString(), "-cp",
                System.getProperty("java.class.path"), "-Xlint:all", "-Werror", source.toString());
        assertEquals(0, status, errors.toString(StandardCharsets.UTF_8) + "\n" + code);
        assertTrue(Files.exists(dir.resolve(name.group(1) + ".class")));
    }
}
