package dev.trisect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;

/**
 * The library artifact is usable with only what it declares: a project depending on it gets its
 * compile and runtime dependencies that are not optional (Maven's rule for a dependency's
 * dependencies), and with those alone the examples compile and the headless one runs.
 *
 * <p>The consumer's class path is what Maven resolves (offline from the local repository, online if that fails) for a
 * consumer pom listing exactly those dependencies of this pom (with their exclusions); the library
 * itself is {@code target/classes}, the plain jar's content. All of it is the module path, so the
 * examples see the module {@code dev.trisect} as a user's program does: an API type that needs an
 * optional (application-only) library, a library the pom or the module descriptor forgets, or a package
 * the descriptor does not export, fails this test.
 */
class ArtifactTest {
    /** Runs the consumer's {@code dependency:build-classpath}; returns null when it succeeded, else Maven's output. */
    private static String buildClasspath(Path dir, Path cpFile, boolean offline) throws Exception {
        List<String> mvn = new ArrayList<>(List.of(System.getProperty("os.name").startsWith("Windows") ? "mvn.cmd"
                : "mvn", "-q", "-B", "dependency:build-classpath", "-Dmdep.outputFile=" + cpFile,
                "-Dmdep.includeScope=runtime"));
        if (offline) {
            mvn.add(1, "-o");
        }
        Process p = new ProcessBuilder(mvn).directory(dir.toFile()).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), "mvn dependency:build-classpath finished");
        return p.exitValue() == 0 ? null : out;
    }

    private static final Path POM = Path.of("pom.xml");
    private static final Pattern PROPERTY = Pattern.compile("\\$\\{([^}]+)}");

    @Test
    void examplesCompileAndRunWithTheDeclaredDependenciesAlone(@TempDir Path dir) throws Exception {
        Document pom = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(POM.toFile());
        Map<String, String> properties = properties(pom);
        StringBuilder deps = new StringBuilder();
        List<String> inherited = new ArrayList<>();
        Element project = pom.getDocumentElement();
        Element dependencies = child(project, "dependencies");
        for (Element d : children(dependencies, "dependency")) {
            String scope = text(d, "scope", "compile");
            boolean optional = Boolean.parseBoolean(text(d, "optional", "false"));
            if (optional || !(scope.equals("compile") || scope.equals("runtime"))) {
                continue;
            }
            String id = text(d, "groupId", null) + ":" + text(d, "artifactId", null);
            inherited.add(id);
            deps.append("<dependency><groupId>").append(text(d, "groupId", null)).append("</groupId><artifactId>")
                    .append(text(d, "artifactId", null)).append("</artifactId><version>")
                    .append(resolve(text(d, "version", null), properties)).append("</version><scope>").append(scope)
                    .append("</scope>");
            Element exclusions = child(d, "exclusions");
            if (exclusions != null) {
                deps.append("<exclusions>");
                for (Element e : children(exclusions, "exclusion")) {
                    deps.append("<exclusion><groupId>").append(text(e, "groupId", null)).append("</groupId><artifactId>")
                            .append(text(e, "artifactId", null)).append("</artifactId></exclusion>");
                }
                deps.append("</exclusions>");
            }
            deps.append("</dependency>");
        }
        assertFalse(inherited.stream().anyMatch(id -> id.contains("picocli") || id.contains("flatlaf")
                || id.contains("xchart") || id.contains("junit")), "application and test libraries reach users: "
                + inherited);
        Files.writeString(dir.resolve("pom.xml"), "<project><modelVersion>4.0.0</modelVersion><groupId>consumer</groupId>"
                + "<artifactId>consumer</artifactId><version>1</version><dependencies>" + deps
                + "</dependencies></project>");
        Path cpFile = dir.resolve("cp.txt");
        // Offline first (fast, and the local repository holds the library's dependencies once this
        // build has run); online when that fails, as on a fresh machine, where the dependency plugin
        // that resolves the class path has never run and its own dependencies are not there yet.
        String mvnOut = buildClasspath(dir, cpFile, true);
        if (mvnOut != null) {
            String online = buildClasspath(dir, cpFile, false);
            assertTrue(online == null, "offline:\n" + mvnOut + "\nonline:\n" + online);
        }
        String classpath = Path.of("target/classes").toAbsolutePath() + File.pathSeparator
                + Files.readString(cpFile).trim();
        assertFalse(classpath.contains("junit") || classpath.contains("picocli") || classpath.contains("xchart")
                || classpath.contains("flatlaf"), classpath);

        // On the module path, as the module dev.trisect: only its exported packages can be used.
        List<String> args = new ArrayList<>(List.of("-d", dir.resolve("classes").toString(), "--module-path",
                classpath, "--add-modules", "dev.trisect", "-Xlint:all", "-Werror"));
        try (Stream<Path> s = Files.walk(Path.of("src/examples/java"))) {
            s.filter(f -> f.toString().endsWith(".java")).map(Path::toString).forEach(args::add);
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        ByteArrayOutputStream errors = new ByteArrayOutputStream();
        int status = javac.run(null, null, new PrintStream(errors, true, StandardCharsets.UTF_8),
                args.toArray(new String[0]));
        assertEquals(0, status, errors.toString(StandardCharsets.UTF_8));

        // Run the headless example on that class path alone, in a JVM of its own.
        Path png = dir.resolve("cube.png");
        Process run = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "--module-path", classpath, "--add-modules", "dev.trisect", "-cp",
                dir.resolve("classes").toString(), "dev.trisect.examples.HeadlessRender", png.toString())
                .redirectErrorStream(true).start();
        String runOut = new String(run.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(run.waitFor(120, TimeUnit.SECONDS), "the example finished");
        assertEquals(0, run.exitValue(), runOut);
        assertTrue(Files.size(png) > 10_000, "a picture was written");
    }

    private static Map<String, String> properties(Document pom) {
        Map<String, String> out = new HashMap<>();
        Element props = child(pom.getDocumentElement(), "properties");
        for (Node n = props.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e) {
                out.put(e.getTagName(), e.getTextContent().trim());
            }
        }
        out.put("project.version", text(pom.getDocumentElement(), "version", null));
        return out;
    }

    private static String resolve(String value, Map<String, String> properties) {
        Matcher m = PROPERTY.matcher(value);
        StringBuilder sb = new StringBuilder();
        while (m.find()) {
            String v = properties.get(m.group(1));
            assertTrue(v != null, "unknown property " + m.group(1));
            m.appendReplacement(sb, Matcher.quoteReplacement(v));
        }
        return m.appendTail(sb).toString();
    }

    private static Element child(Element parent, String tag) {
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && e.getTagName().equals(tag)) {
                return e;
            }
        }
        return null;
    }

    private static List<Element> children(Element parent, String tag) {
        List<Element> out = new ArrayList<>();
        NodeList list = parent.getChildNodes();
        for (int i = 0; i < list.getLength(); i++) {
            if (list.item(i) instanceof Element e && e.getTagName().equals(tag)) {
                out.add(e);
            }
        }
        return out;
    }

    private static String text(Element parent, String tag, String fallback) {
        Element e = child(parent, tag);
        return e == null ? fallback : e.getTextContent().trim();
    }
}
