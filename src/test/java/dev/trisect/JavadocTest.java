package dev.trisect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import javax.tools.Tool;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The API's Javadoc stays clean: every package says whether it is API or internal, and the javadoc
 * tool over the exported packages, with the overview page, reports nothing under the doclint groups
 * the build uses ({@link #DOCLINT}, the same as the pom's {@code maven-javadoc-plugin}, which also fails
 * on a warning).
 */
class JavadocTest {
    /** Every doclint check: every public and protected member documented, parameters and return values too. */
    static final String DOCLINT = "-Xdoclint:all";
    private static final Path SOURCES = Path.of("src/main/java/dev/trisect");

    @Test
    void everyPackageSaysWhetherItIsApiOrInternal() throws IOException {
        List<String> wrong = new ArrayList<>();
        List<Path> dirs;
        try (Stream<Path> s = Files.walk(SOURCES)) {
            dirs = s.filter(Files::isDirectory).sorted().toList();
        }
        int packages = 0;
        for (Path dir : dirs) {
            try (Stream<Path> s = Files.list(dir)) {
                if (s.noneMatch(f -> f.toString().endsWith(".java"))) {
                    continue;
                }
            }
            packages++;
            String pkg = SOURCES.relativize(dir).toString().replace(java.io.File.separatorChar, '.');
            Path info = dir.resolve("package-info.java");
            if (!Files.exists(info)) {
                wrong.add(dir + ": no package-info.java");
                continue;
            }
            String text = Files.readString(info);
            String want = ArchitectureTest.API.contains(pkg) ? "/**\n * <b>API.</b>"
                    : "/**\n * <b>Internal, not part of the API</b>";
            if (!text.startsWith(want)) {
                wrong.add(info + " does not start with " + want.substring(7));
            }
        }
        assertTrue(packages >= 20, "packages found: " + packages);
        assertEquals(List.of(), wrong);
    }

    @Test
    void theApiJavadocHasNoWarnings(@TempDir Path out) throws IOException {
        List<String> args = new ArrayList<>(List.of("-quiet", DOCLINT, "-Xmaxwarns", "10000", "-d", out.toString(),
                "-cp", System.getProperty("java.class.path"), "-overview", "src/main/javadoc/overview.html"));
        for (String pkg : ArchitectureTest.API) {
            try (Stream<Path> s = Files.list(SOURCES.resolve(pkg))) {
                s.filter(f -> f.toString().endsWith(".java")).sorted().map(Path::toString).forEach(args::add);
            }
        }
        assertEquals("", run(ToolProvider.getSystemDocumentationTool(), args), "javadoc said something");
        assertTrue(Files.exists(out.resolve("dev/trisect/scene/SceneRenderer.html")), "the pages were written");
    }

    /** Runs javac or javadoc, which must succeed; returns what it printed, stripped. */
    private static String run(Tool tool, List<String> args) {
        ByteArrayOutputStream log = new ByteArrayOutputStream();
        PrintStream print = new PrintStream(log, true, StandardCharsets.UTF_8);
        int status = tool.run(null, print, print, args.toArray(new String[0]));
        String text = log.toString(StandardCharsets.UTF_8);
        assertEquals(0, status, text);
        return text.strip();
    }
}
