package dev.trisect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.module.ModuleDescriptor;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Packages depend only downward, in this order; {@code cli} never reaches {@code ui}; the demo
 * ({@code ui}) uses the API packages (the view through its public API alone, never
 * {@code view.internal} or {@code devtools}) and the content it shares with the command line; only the view's packages and the demo touch Swing, and {@code raster} touches no
 * AWT at all.
 */
class ArchitectureTest {
    /** Bottom to top. A package may use itself and the ones before it. */
    static final List<String> LAYERS = List.of(
            "base", "math", "mesh", "texture", "render", "light", "tessellate", "raster", "pipeline", "metrics", "scene", "content", "io",
            "perf", "view.internal", "devtools", "view", "ui", "cli");

    /**
     * What the demo ({@code ui}) may use: the API packages, as any program, plus the built-in scenes
     * and OBJ loading it shares with the command line ({@code content}) and the base package's
     * internals (its soak report's JSON).
     */
    static final java.util.function.Predicate<String> DEMO_MAY_USE = pkg -> ArchitectureTest.API.contains(pkg)
            || pkg.equals("content") || pkg.startsWith("base.") || pkg.equals("ui");

    /** Packages that may use Swing: the view, its engine room and developer tools, and the demo. */
    static final List<String> SWING = List.of("view.internal", "devtools", "view", "ui");

    /** A reference to a class: the package path (lower-case segments) before a capitalised name. */
    private static final Pattern REFERENCE = Pattern.compile("\\bdev\\.trisect\\.((?:[a-z]\\w*\\.)+)[A-Z]");
    private static final Path SOURCES = Path.of("src/main/java/dev/trisect");

    @Test
    void packagesDependOnlyDownward() throws IOException {
        List<String> violations = new ArrayList<>();
        int checked = 0;
        for (Path file : javaFiles()) {
            String own = packageOf(file);
            if (own.isEmpty()) {
                continue; // the launcher in the base package wires the top layers together
            }
            int ownRank = rank(own);
            assertTrue(ownRank >= 0, "package " + own + " is not in the layer list");
            Matcher m = REFERENCE.matcher(code(file));
            while (m.find()) {
                checked++;
                String used = m.group(1).substring(0, m.group(1).length() - 1);
                int usedRank = rank(used);
                String usedLayer = usedRank < 0 ? "" : LAYERS.get(usedRank);
                boolean ok = usedRank >= 0 && usedRank <= ownRank
                        && !(own.equals("cli") && usedLayer.equals("ui"))
                        && !(own.equals("ui") && !DEMO_MAY_USE.test(used));
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
            String own = packageOf(file);
            String code = code(file);
            if (code.contains("javax.swing") && !(rank(own) >= 0 && SWING.contains(LAYERS.get(rank(own))))) {
                violations.add(SOURCES.relativize(file) + " uses Swing");
            }
            if (code.contains("java.awt") && rank(own) == LAYERS.indexOf("raster")) {
                violations.add(SOURCES.relativize(file) + " uses AWT");
            }
        }
        assertEquals(List.of(), violations);
    }

    /** The packages of the public API (module-info exports these alone); see docs/view.md and the Javadoc overview. */
    static final List<String> API = List.of("base", "math", "mesh", "texture", "render", "scene", "view");

    /** The module exports exactly the API packages (ApiSignaturesTest checks what their signatures name). */
    @Test
    void theModuleExportsTheApiPackagesAlone() throws IOException {
        assertEquals(API.stream().map(p -> "dev.trisect." + p).sorted().toList(), exported().stream().sorted().toList());
    }

    /** The packages {@code module-info} exports (compiled, read as the JVM reads it). */
    private static Set<String> exported() throws IOException {
        try (var in = Files.newInputStream(Path.of("target/classes/module-info.class"))) {
            Set<String> out = new HashSet<>();
            for (ModuleDescriptor.Exports e : ModuleDescriptor.read(in).exports()) {
                assertTrue(e.targets().isEmpty(), "an export to everyone: " + e);
                out.add(e.source());
            }
            return out;
        }
    }

    /** The examples are what a user writes: they import the API packages alone. */
    @Test
    void examplesUseTheApiAlone() throws IOException {
        List<String> violations = new ArrayList<>();
        // The package of each imported type: its lower-case segments (so view.internal is not view).
        Pattern imports = Pattern.compile("^import (static )?(dev\\.trisect\\.((?:[a-z]\\w*\\.)*[a-z]\\w*)\\.[A-Z][\\w.]*);",
                Pattern.MULTILINE);
        List<Path> examples;
        try (Stream<Path> s = Files.walk(Path.of("src/examples/java"))) {
            examples = s.filter(p -> p.toString().endsWith(".java")).sorted().toList();
        }
        assertTrue(examples.size() >= 2, "examples found: " + examples);
        for (Path file : examples) {
            Matcher m = imports.matcher(Files.readString(file));
            while (m.find()) {
                if (!API.contains(m.group(3))) {
                    violations.add(file + " imports " + m.group(2));
                }
            }
        }
        assertEquals(List.of(), violations);
    }

    /** The package below dev.trisect a source file is in, dotted ("view.internal"); "" for dev.trisect itself. */
    private static String packageOf(Path file) {
        Path dir = SOURCES.relativize(file).getParent();
        return dir == null ? "" : dir.toString().replace(java.io.File.separatorChar, '.');
    }

    /** The layer of a package: the longest entry of {@link #LAYERS} that is it or a parent of it; -1 if none. */
    static int rank(String pkg) {
        int best = -1;
        for (int i = 0; i < LAYERS.size(); i++) {
            String layer = LAYERS.get(i);
            if ((pkg.equals(layer) || pkg.startsWith(layer + "."))
                    && (best < 0 || layer.length() > LAYERS.get(best).length())) {
                best = i;
            }
        }
        return best;
    }

    @Test
    void aPackageRanksAsItsLongestListedParent() {
        assertEquals(LAYERS.indexOf("view.internal"), rank("view.internal"));
        assertEquals(LAYERS.indexOf("view"), rank("view"));
        assertEquals(LAYERS.indexOf("base"), rank("base.internal"));
        assertEquals(-1, rank("viewer"));
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
