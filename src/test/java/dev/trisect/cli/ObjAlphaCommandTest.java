package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureReader;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code render --obj} writes each material as its texture's alpha says, as the view does: a texture
 * whose alpha is only 0 or 255 is a cut-out (alpha-tested), one with partial alpha blends over what was
 * drawn before it in the file, and an opaque one is drawn as before.
 */
class ObjAlphaCommandTest {
    @TempDir
    Path dir;

    /** A red quad at z = -1 behind, then a quad at z = 0 textured by a 2 x 1 PAM of these two texels. */
    private int[] render(int leftArgb, int rightArgb) throws IOException {
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

    @Test
    void anOpaqueTextureIsDrawnAsBefore() throws IOException {
        int[] px = render(0xFF00FF00, 0xFF0000FF);
        assertEquals(0xFF00FF00, px[0]);
        assertEquals(0xFF0000FF, px[1]);
    }
}
