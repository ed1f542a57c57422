package dev.trisect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Packages depend only downward, in this order; {@code cli} never reaches {@code ui}; only {@code view}
 * (the public view component) and {@code ui} (the demo) touch Swing, and {@code raster} touches no AWT at all.
 */
class ArchitectureTest {
    /** Bottom to top. A package may use itself and the ones before it. */
    static final List<String> LAYERS = List.of(
            "base", "math", "mesh", "texture", "tessellate", "raster", "pipeline", "metrics", "scene", "content", "io",
            "perf", "view", "ui", "cli");

    private static final Pattern REFERENCE = Pattern.compile("\\bdev\\.trisect\\.(\\w+)\\.");
    private static final Path SOURCES = Path.of("src/main/java/dev/trisect");

    @Test
    void packagesDependOnlyDownward() throws IOException {
        List<String> violations = new ArrayList<>();
        int checked = 0;
        for (Path file : javaFiles()) {
            String own = SOURCES.relativize(file).getName(0).toString();
            if (own.endsWith(".java")) {
                continue; // the launcher in the base package wires the top layers together
            }
            int ownRank = LAYERS.indexOf(own);
            assertTrue(ownRank >= 0, "package " + own + " is not in the layer list");
            Matcher m = REFERENCE.matcher(code(file));
            while (m.find()) {
                checked++;
                String used = m.group(1);
                int usedRank = LAYERS.indexOf(used);
                boolean ok = usedRank >= 0 && usedRank <= ownRank && !(own.equals("cli") && used.equals("ui"));
                if (!ok) {
                    violations.add(SOURCES.relativize(file) + " uses dev.trisect." + used);
                }
            }
        }
        assertTrue(checked > 10, "the check saw the code's references");
        assertEquals(List.of(), violations);
    }

    @Test
    void swingOnlyInViewAndUiAndNoAwtInRaster() throws IOException {
        List<String> violations = new ArrayList<>();
        for (Path file : javaFiles()) {
            String own = SOURCES.relativize(file).getName(0).toString();
            String code = code(file);
            if (code.contains("javax.swing") && !own.equals("ui") && !own.equals("view")) {
                violations.add(SOURCES.relativize(file) + " uses Swing");
            }
            if (code.contains("java.awt") && own.equals("raster")) {
                violations.add(SOURCES.relativize(file) + " uses AWT");
            }
        }
        assertEquals(List.of(), violations);
    }

    /** The packages of the public API (module-info exports these alone); see /work/notes/api-design.md. */
    static final List<String> API = List.of("base", "math", "mesh", "texture", "render", "scene", "view");
    /** API types still in internal packages until the move to {@code render} (issue 17); none once it is done. */
    private static final List<String> PENDING_MOVE = List.of("dev.trisect.pipeline.RenderSettings",
            "dev.trisect.pipeline.RenderMode", "dev.trisect.pipeline.FrameStats", "dev.trisect.pipeline.CullMode",
            "dev.trisect.raster.Framebuffer");

    /** The examples are what a user writes: they import the API packages alone. */
    @Test
    void examplesUseTheApiAlone() throws IOException {
        List<String> violations = new ArrayList<>();
        Pattern imports = Pattern.compile("^import (static )?(dev\\.trisect\\.(\\w+)\\.[\\w.]+);", Pattern.MULTILINE);
        List<Path> examples;
        try (Stream<Path> s = Files.walk(Path.of("src/examples/java"))) {
            examples = s.filter(p -> p.toString().endsWith(".java")).sorted().toList();
        }
        assertTrue(examples.size() >= 2, "examples found: " + examples);
        for (Path file : examples) {
            Matcher m = imports.matcher(Files.readString(file));
            while (m.find()) {
                if (!API.contains(m.group(3)) && !PENDING_MOVE.contains(m.group(2))) {
                    violations.add(file + " imports " + m.group(2));
                }
            }
        }
        assertEquals(List.of(), violations);
    }

    private static List<Path> javaFiles() throws IOException {
        try (Stream<Path> s = Files.walk(SOURCES)) {
            return s.filter(p -> p.toString().endsWith(".java")).sorted().toList();
        }
    }

    /** Source without comments, so Javadoc links do not count as dependencies. */
    private static String code(Path file) throws IOException {
        String src = Files.readString(file);
        return src.replaceAll("(?s)/\\*.*?\\*/", "").replaceAll("//[^\n]*", "");
    }
}
