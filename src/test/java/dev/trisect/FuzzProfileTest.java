package dev.trisect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * {@code mvn -Pfuzz test} fuzzes every Jazzer target. Jazzer fuzzes one {@code @FuzzTest} per JVM
 * and skips the others it finds, so a surefire execution of the fuzz profile that names a class
 * with two targets fuzzes only one of them: each target of such a class needs an execution of its
 * own, naming it as {@code Class#method}.
 */
class FuzzProfileTest {
    private static final Pattern FUZZ_TEST = Pattern.compile("^\\s*@FuzzTest\\b[^\\n]*\\n\\s*(?:@[^\\n]*\\n\\s*)*void (\\w+)\\(",
            Pattern.MULTILINE);

    @Test
    void everyFuzzTargetHasAFuzzExecutionOfItsOwn() throws Exception {
        TreeSet<String> targets = new TreeSet<>();
        List<String> classesWithOne = new ArrayList<>();
        try (Stream<Path> files = Files.walk(Path.of("src/test/java"))) {
            for (Path file : files.filter(p -> p.toString().endsWith(".java")).toList()) {
                List<String> methods = fuzzTargets(file);
                String cls = file.getFileName().toString().replace(".java", "");
                methods.forEach(m -> targets.add(cls + "#" + m));
                if (methods.size() == 1) {
                    classesWithOne.add(cls);
                }
            }
        }
        assertTrue(targets.size() >= 4, "the Jazzer targets found: " + targets);

        TreeSet<String> fuzzed = new TreeSet<>();
        for (String test : fuzzProfileTests()) {
            // A class named alone stands for its one target; with two or more, Jazzer fuzzes just one.
            fuzzed.add(classesWithOne.contains(test)
                    ? targets.stream().filter(t -> t.startsWith(test + "#")).findFirst().orElseThrow()
                    : test);
        }
        assertEquals(targets, fuzzed, "fuzz targets against the fuzz profile's executions");
    }

    /** The methods of {@code file} annotated {@code @FuzzTest}. */
    private static List<String> fuzzTargets(Path file) throws IOException {
        List<String> methods = new ArrayList<>();
        Matcher m = FUZZ_TEST.matcher(Files.readString(file));
        while (m.find()) {
            methods.add(m.group(1));
        }
        return methods;
    }

    /** The {@code test} of each surefire execution (and of the plugin itself) in the profile {@code fuzz}. */
    private static List<String> fuzzProfileTests() throws Exception {
        var pom = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(Path.of("pom.xml").toFile());
        NodeList profiles = pom.getElementsByTagName("profile");
        for (int i = 0; i < profiles.getLength(); i++) {
            Element profile = (Element) profiles.item(i);
            if (profile.getElementsByTagName("id").item(0).getTextContent().equals("fuzz")) {
                List<String> tests = new ArrayList<>();
                NodeList names = profile.getElementsByTagName("test");
                for (int k = 0; k < names.getLength(); k++) {
                    tests.add(names.item(k).getTextContent().trim());
                }
                return tests;
            }
        }
        throw new AssertionError("pom.xml has no profile fuzz");
    }
}
