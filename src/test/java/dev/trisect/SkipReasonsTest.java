package dev.trisect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.nio.charset.StandardCharsets;
import java.util.Optional;
import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtensionContext;

/** Skipped tests say why: SkipReasons is registered for every test class, and its line names the test and the reason. */
class SkipReasonsTest {
    @Test
    void everyTestClassGetsTheWatcher() throws Exception {
        Properties p = new Properties();
        try (InputStream in = SkipReasonsTest.class.getResourceAsStream("/junit-platform.properties")) {
            p.load(in);
        }
        assertEquals("true", p.getProperty("junit.jupiter.extensions.autodetection.enabled"));
        try (InputStream in = SkipReasonsTest.class.getResourceAsStream(
                "/META-INF/services/org.junit.jupiter.api.extension.Extension")) {
            assertTrue(new String(in.readAllBytes(), StandardCharsets.UTF_8).lines()
                    .anyMatch(l -> l.trim().equals(SkipReasons.class.getName())));
        }
    }

    @Test
    void theLineNamesTheTestAndWhy() throws Exception {
        ExtensionContext context = context(SkipReasonsTest.class.getDeclaredMethod("theLineNamesTheTestAndWhy"));
        assertEquals("SKIPPED SkipReasonsTest.theLineNamesTheTestAndWhy: no display",
                SkipReasons.line(context, "Assumption failed: no display"));
        assertEquals("SKIPPED SkipReasonsTest.theLineNamesTheTestAndWhy: (no reason given)",
                SkipReasons.line(context, null));
    }

    /** A context that knows only its test class and method. */
    private static ExtensionContext context(Method method) {
        return (ExtensionContext) Proxy.newProxyInstance(ExtensionContext.class.getClassLoader(),
                new Class<?>[] {ExtensionContext.class}, (proxy, m, args) -> switch (m.getName()) {
                    case "getTestClass" -> Optional.of(method.getDeclaringClass());
                    case "getTestMethod" -> Optional.of(method);
                    default -> throw new UnsupportedOperationException(m.getName());
                });
    }
}
