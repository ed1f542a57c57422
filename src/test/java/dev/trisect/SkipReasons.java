package dev.trisect;

import java.lang.reflect.Method;
import java.util.Optional;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.extension.TestWatcher;

/**
 * Prints one line to standard error for every test that is skipped — an assumption that failed (no
 * display, no {@code /dev/full}, permissions not enforced) or a disabled test — naming the test and why,
 * so that a build's "Skipped: N" can be read without opening the reports. Registered for every test
 * class through {@code META-INF/services} and {@code junit-platform.properties} (extension autodetection).
 */
public final class SkipReasons implements TestWatcher {
    @Override
    public void testAborted(ExtensionContext context, Throwable cause) {
        System.err.println(line(context, cause == null ? null : cause.getMessage()));
    }

    @Override
    public void testDisabled(ExtensionContext context, Optional<String> reason) {
        System.err.println(line(context, reason.orElse(null)));
    }

    /** "SKIPPED FooTest.bar: why", or "(no reason given)" when the skip names none. */
    static String line(ExtensionContext context, String reason) {
        String test = context.getTestClass().map(Class::getSimpleName).orElse("?")
                + context.getTestMethod().map(Method::getName).map(m -> "." + m).orElse("");
        String why = reason == null || reason.isBlank() ? "(no reason given)"
                : reason.replaceFirst("^Assumption failed: ", "");
        return "SKIPPED " + test + ": " + why;
    }
}
