package dev.trisect;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;

/** OBJ files for tests and measurements that need a model of a given size. */
public final class TestObjs {
    private TestObjs() {
    }

    /**
     * Writes a flat grid of n x n unit quads in the plane y = 0 (x and z from 0 to n), 2n² triangles,
     * each corner with its texture coordinate, facing up.
     */
    public static void grid(Path file, int n) throws IOException {
        try (Writer w = Files.newBufferedWriter(file)) {
            StringBuilder line = new StringBuilder();
            for (int j = 0; j <= n; j++) {
                line.setLength(0);
                for (int i = 0; i <= n; i++) {
                    line.append("v ").append(i).append(" 0 ").append(j).append("\nvt ").append((double) i / n)
                            .append(' ').append((double) j / n).append('\n');
                }
                w.append(line);
            }
            for (int j = 0; j < n; j++) {
                line.setLength(0);
                for (int i = 0; i < n; i++) {
                    int a = j * (n + 1) + i + 1;
                    int c = a + n + 1;
                    line.append("f ").append(a).append('/').append(a).append(' ').append(c).append('/').append(c)
                            .append(' ').append(a + 1).append('/').append(a + 1).append('\n');
                    line.append("f ").append(a + 1).append('/').append(a + 1).append(' ').append(c).append('/')
                            .append(c).append(' ').append(c + 1).append('/').append(c + 1).append('\n');
                }
                w.append(line);
            }
        }
    }
}
