package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureReader;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code bench --alpha-test} times the alpha-tested write against the opaque one; {@code render --obj} writes each material as its texture's alpha says, as the view does: a texture
 * whose alpha is only 0 or 255 is a cut-out (alpha-tested), one with partial alpha blends over what was
 * drawn before it in the file, and an opaque one is drawn as before.
 */
class ObjAlphaCommandTest {
    @Test
    void benchTimesTheAlphaTestAgainstTheOpaqueFrameOnTheSamePixels() {
        String[] args = {"bench", "--scene", "boxes", "--size", "96x64", "--modes", "perspective,tessellated",
            "--frames", "2", "--warmup", "0", "--json"};
        CliRun plain = CliRun.of(args);
        assertEquals(0, plain.status(), plain.err());
        CliRun tested = CliRun.of(concat(args, "--alpha-test"));
        assertEquals(0, tested.status(), tested.err());
        List<String> a = plain.out().lines().toList();
        List<String> b = tested.out().lines().toList();
        assertEquals(2, b.size(), tested.out());
        for (int i = 0; i < 2; i++) {
            // Opaque textures: every fragment passes the test, so the alpha-tested frame writes the same pixels.
            assertEquals(field(a.get(i), "pixels_written"), field(b.get(i), "pixels_written"), b.get(i));
            assertTrue(Double.parseDouble(field(b.get(i), "alpha_test_ratio")) > 0,
                    b.get(i));
        }
        CliRun table = CliRun.of("bench", "--scene", "boxes", "--size", "64x48", "--modes", "affine", "--frames", "1",
                "--warmup", "0", "--alpha-test");
        assertEquals(0, table.status(), table.err());
        assertTrue(table.out().lines().anyMatch(l -> l.startsWith("affine")
                && l.matches(".* alpha_test [0-9.]+x opaque")), table.out());
        CliRun both = CliRun.of("bench", "--scene", "boxes", "--alpha-test", "--labels", "3");
        assertEquals(2, both.status(), both.err());
    }

    private static String field(String json, String key) {
        Matcher m = Pattern.compile("\"" + key + "\":([-0-9.eE]+)").matcher(json);
        assertTrue(m.find(), key + " in " + json);
        return m.group(1);
    }

    private static String[] concat(String[] a, String... b) {
        String[] out = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }

    @TempDir
    Path dir;

    /** A red quad at z = -1 behind, then a quad at z = 0 textured by a 2 x 1 PAM of these two texels. */
    private int[] render(int leftArgb, int rightArgb) throws IOException {
        return render(scene(leftArgb, rightArgb));
    }

    /** The OBJ of {@link #render(int, int)}'s scene, with its MTL and PAM beside it. */
    private Path scene(int leftArgb, int rightArgb) throws IOException {
        ByteArrayOutputStream pam = new ByteArrayOutputStream();
        pam.writeBytes("P7\nWIDTH 2\nHEIGHT 1\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n"
                .getBytes(StandardCharsets.US_ASCII));
        for (int argb : new int[] {leftArgb, rightArgb}) {
            pam.write(argb >> 16 & 255);
            pam.write(argb >> 8 & 255);
            pam.write(argb & 255);
            pam.write(argb >>> 24);
        }
        Files.write(dir.resolve("front.pam"), pam.toByteArray());
        Files.writeString(dir.resolve("a.mtl"), "newmtl back\nKd 1 0 0\nnewmtl front\nmap_Kd front.pam\n");
        Path obj = Files.writeString(dir.resolve("a.obj"), "mtllib a.mtl\n"
                + "v -3 -3 -1\nv 3 -3 -1\nv 3 3 -1\nv -3 3 -1\n"
                + "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                + "usemtl back\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n"
                + "usemtl front\nf 5/1 6/2 7/3\nf 5/1 7/3 8/4\n");
        return obj;
    }

    /** Two pixels of {@code obj} rendered from (0, 0, 3), a quarter in from each side of the front quad. */
    private int[] render(Path obj) throws IOException {
        Path out = dir.resolve("out.png");
        CliRun r = CliRun.of("render", "--obj", obj.toString(), "--eye", "0,0,3", "--target", "0,0,0",
                "--size", "80x60", "--out", out.toString());
        assertEquals(0, r.status(), r.err());
        Texture image = TextureReader.read(out);
        int w = image.width();
        int y = image.height() / 2;
        // A quarter in from each side of the front quad, which spans the middle of the frame.
        return new int[] {image.argb()[y * w + w / 2 - 8], image.argb()[y * w + w / 2 + 8]};
    }

    @Test
    void aCutOutShowsWhatIsBehindWhereItsAlphaIsZero() throws IOException {
        int[] px = render(0x0000FF00, 0xFF0000FF);
        assertEquals(0xFFFF0000, px[0], "alpha 0: the red quad behind shows");
        assertEquals(0xFF0000FF, px[1], "alpha 255: the texel");
    }

    @Test
    void partialAlphaBlendsOverWhatWasDrawnBefore() throws IOException {
        int[] px = render(0x400000FF, 0xFF00FF00);
        // src * a + dst * (1 - a), rounded: blue at 64/255 over red.
        int red = Math.round((255 * (255 - 64)) / 255f);
        int blue = Math.round(255 * 64 / 255f);
        assertEquals(0xFF000000 | red << 16 | blue, px[0]);
        assertEquals(0xFF00FF00, px[1]);
    }

    /** {@code export} keeps a texture's alpha (as a PAM): the exported cut-out and blend render as the original. */
    @Test
    void anExportedSceneKeepsItsTransparency() throws IOException {
        for (int[] texels : new int[][] {{0x0000FF00, 0xFF0000FF}, {0x400000FF, 0xFF00FF00}}) {
            Path obj = scene(texels[0], texels[1]);
            int[] original = render(obj);
            Path exported = dir.resolve("e").resolve("e.obj");
            CliRun r = CliRun.of("export", "--obj", obj.toString(), "--to", exported.toString());
            assertEquals(0, r.status(), r.err());
            assertTrue(Files.isRegularFile(dir.resolve("e").resolve("e-front.pam")), r.out());
            assertEquals(original[0], render(exported)[0], "the texel with alpha " + (texels[0] >>> 24));
            assertEquals(original[1], render(exported)[1]);
        }
    }

    @Test
    void anOpaqueTextureIsDrawnAsBefore() throws IOException {
        int[] px = render(0xFF00FF00, 0xFF0000FF);
        assertEquals(0xFF00FF00, px[0]);
        assertEquals(0xFF0000FF, px[1]);
    }
}
