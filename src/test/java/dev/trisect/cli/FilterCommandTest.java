package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.io.Pfm;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureReader;
import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code --filter} end to end through {@code render}, in every path. */
class FilterCommandTest {
    @TempDir
    Path dir;

    private record Frame(int[] argb, float[] uv) {
    }

    private Frame render(String mode, String filter) throws IOException {
        Path png = dir.resolve(mode + "-" + filter + ".png");
        Path uv = dir.resolve(mode + "-" + filter + ".pfm");
        CliRun r = CliRun.of("render", "--scene", "floor", "--size", "160x90", "--mode", mode, "--filter", filter,
                "--out", png.toString(), "--uv-out", uv.toString());
        assertEquals(0, r.status(), r.err());
        Texture image = TextureReader.read(png);
        return new Frame(image.argb(), Pfm.read(uv).data());
    }

    /** Number of distinct colours: filtering mixes texels, so it makes colours the texture lacks. */
    private static long colours(int[] argb) {
        return java.util.Arrays.stream(argb).distinct().count();
    }

    @Test
    void eachFilterRendersInEachPathWithTheSameUvOutput() throws IOException {
        for (String mode : new String[] {"perspective", "affine", "tessellated", "spans"}) {
            Frame nearest = render(mode, "nearest");
            Frame bilinear = render(mode, "bilinear");
            Frame trilinear = render(mode, "trilinear");
            assertArrayEquals(nearest.uv(), bilinear.uv(), mode);
            assertArrayEquals(nearest.uv(), trilinear.uv(), mode);
            assertTrue(colours(bilinear.argb()) > 2 * colours(nearest.argb()), mode);
            assertTrue(colours(trilinear.argb()) > 2 * colours(nearest.argb()), mode);
            int differ = 0;
            for (int i = 0; i < bilinear.argb().length; i++) {
                differ += bilinear.argb()[i] != trilinear.argb()[i] ? 1 : 0;
            }
            // Near the horizon trilinear minifies and bilinear does not.
            assertTrue(differ > 1000, mode + ": " + differ);
        }
    }

    @Test
    void nearestIsTheDefault() throws IOException {
        Path png = dir.resolve("default.png");
        assertEquals(0, CliRun.of("render", "--scene", "floor", "--size", "160x90", "--mode", "perspective",
                "--out", png.toString()).status());
        assertArrayEquals(render("perspective", "nearest").argb(), TextureReader.read(png).argb());
    }

    @Test
    void benchRowsNameTheFilter() {
        CliRun r = CliRun.of("bench", "--scene", "floor", "--size", "64x48", "--frames", "2", "--warmup", "0",
                "--filter", "trilinear", "--json");
        assertEquals(0, r.status(), r.err());
        long rows = r.out().lines().filter(l -> l.contains("\"filter\":\"trilinear\"")).count();
        assertEquals(4, rows, r.out());
    }

    @Test
    void anUnknownFilterIsAUsageError() {
        CliRun r = CliRun.of("render", "--scene", "floor", "--size", "8x8", "--filter", "anisotropic",
                "--out", dir.resolve("o.png").toString());
        assertEquals(2, r.status());
        assertTrue(r.err().contains("'anisotropic' is not a texture filter: use nearest, bilinear or trilinear"),
                r.err());
    }
}
