package dev.trisect.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.texture.TextureReader;
import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code compare --borders} measures the rendered image, never the yellow overlay drawn over it. */
class CompareOverlayTest {
    @TempDir
    Path dir;

    @Test
    void bordersChangeTheOutImageButNotOneNumber() throws IOException {
        String[] args = {"compare", "--scene", "demo", "--size", "320x180", "--split", "error", "--max-error", "0.5"};
        CliRun plain = CliRun.of(args);
        Path out = dir.resolve("b.png");
        String[] withBorders = java.util.Arrays.copyOf(args, args.length + 3);
        withBorders[args.length] = "--borders";
        withBorders[args.length + 1] = "--out";
        withBorders[args.length + 2] = out.toString();
        CliRun borders = CliRun.of(withBorders);
        assertEquals(0, plain.status() + borders.status(), borders.err());
        assertEquals(plain.out(), borders.out(), "the overlay is not measured");
        int yellow = 0;
        for (int p : TextureReader.read(out).argb()) {
            yellow += p == 0xFFFFFF00 ? 1 : 0;
        }
        assertTrue(yellow > 1000, "the --out image still shows the borders: " + yellow);
    }
}
