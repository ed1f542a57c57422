package dev.trisect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;

/**
 * The README's "Use it in your program" pom stays true to this build: it names this artifact and
 * version, Java 17 by {@code maven.compiler.release}, and the compiler plugin at the version this pom
 * uses (Maven 3's default binding, 3.1, ignores {@code release} and compiles for Java 5, which JDK 17
 * refuses). Compiling a project with it against the installed jar was checked by hand
 * ({@code mvn install}, then {@code mvn compile} of that pom with the README's quick start).
 */
class ReadmePomTest {

    private static Element parse(String xml) throws Exception {
        Document d = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8)));
        return d.getDocumentElement();
    }

    private static String text(Element e, String tag) {
        return e.getElementsByTagName(tag).item(0).getTextContent().strip();
    }

    /** The version of the first plugin named {@code artifactId}. */
    private static String pluginVersion(Element project, String artifactId) {
        var plugins = project.getElementsByTagName("plugin");
        for (int i = 0; i < plugins.getLength(); i++) {
            Element p = (Element) plugins.item(i);
            if (text(p, "artifactId").equals(artifactId)) {
                return text(p, "version");
            }
        }
        return null;
    }

    @Test
    void theReadmesPomNamesThisBuild() throws Exception {
        String readme = Files.readString(Path.of("README.md"));
        String section = readme.substring(readme.indexOf("## Use it in your program"));
        Matcher xml = Pattern.compile("```xml\n(.*?)```", Pattern.DOTALL).matcher(section);
        assertTrue(xml.find(), "a pom in the section");
        Element user = parse(xml.group(1));
        Element ours = parse(Files.readString(Path.of("pom.xml")));
        Element dependency = (Element) user.getElementsByTagName("dependency").item(0);
        assertEquals(text(ours, "groupId"), text(dependency, "groupId"));
        assertEquals(text(ours, "artifactId"), text(dependency, "artifactId"));
        assertEquals(text(ours, "version"), text(dependency, "version"));
        assertEquals("17", text(user, "maven.compiler.release"));
        assertEquals(pluginVersion(ours, "maven-compiler-plugin"), pluginVersion(user, "maven-compiler-plugin"));
        assertTrue(section.contains(text(ours, "groupId") + ":" + text(ours, "artifactId") + ":" + text(ours, "version")),
                "the prose names the same coordinates");
    }

    /**
     * The build's own exec steps (the loop generator's compile and run) give their command line as
     * {@code commandlineArgs}, which the exec goal takes before {@code <arguments>} and before the
     * {@code exec.args} property: so a user's {@code -Dexec.args} for an example run by exec:java does
     * not replace them (with {@code <arguments>} it did, and javac failed with "invalid flag").
     * Checked by hand: {@code mvn -q test-compile exec:java -Dmain.class=dev.trisect.examples.HeadlessRender
     * -Dexec.classpathScope=test -Dexec.args=out.png} writes out.png.
     */
    @Test
    void theBuildsExecStepsIgnoreExecArgs() throws Exception {
        Element ours = parse(Files.readString(Path.of("pom.xml")));
        var executions = ours.getElementsByTagName("execution");
        int steps = 0;
        for (int i = 0; i < executions.getLength(); i++) {
            Element e = (Element) executions.item(i);
            if (e.getElementsByTagName("id").getLength() == 0 || e.getElementsByTagName("goal").getLength() == 0) {
                continue;
            }
            String id = text(e, "id");
            if ((id.equals("loop-generator") || id.equals("loops")) && text(e, "goal").equals("exec")) {
                steps++;
                assertEquals(1, e.getElementsByTagName("commandlineArgs").getLength(), id + ": a command line of its own");
                assertEquals(0, e.getElementsByTagName("arguments").getLength(), id + ": no <arguments>");
            }
        }
        assertEquals(2, steps, "the loop generator's two exec steps");
    }
}
