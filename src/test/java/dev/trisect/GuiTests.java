package dev.trisect;

import java.awt.AWTException;
import java.awt.GraphicsEnvironment;
import java.awt.Robot;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Assumptions;

/**
 * What the GUI tests share: skipping (and saying so) without a display unless
 * TRISECT_REQUIRE_DISPLAY is set, running code on the event thread, and bounded waiting.
 */
public final class GuiTests {
    private GuiTests() {
    }

    /** A robot that pauses 20 ms after each event, or null without a display (saying why the tests of {@code who} skip). */
    public static Robot robot(String who) throws AWTException {
        if (headless(who)) {
            return null;
        }
        Robot robot = new Robot();
        robot.setAutoDelay(20);
        return robot;
    }

    /**
     * Catches exceptions no thread handled, from {@link #start} until {@link #check}: a GUI test
     * asserts there were none on the event thread, the render thread or any other.
     */
    public static final class Uncaught {
        private final AtomicReference<Throwable> first = new AtomicReference<>();
        private Thread.UncaughtExceptionHandler previous;

        /** Starts catching; call before the test opens its windows. */
        public void start() {
            previous = Thread.getDefaultUncaughtExceptionHandler();
            Thread.setDefaultUncaughtExceptionHandler((t, e) -> first.compareAndSet(null, e));
        }

        /** Stops catching and fails if anything was caught. */
        public void check() {
            Thread.setDefaultUncaughtExceptionHandler(previous);
            Throwable t = first.get();
            if (t != null) {
                throw new AssertionError("uncaught exception: " + t, t);
            }
        }
    }

    /** Whether there is no display; prints once why the tests of {@code who} will be skipped. */
    public static boolean headless(String who) {
        boolean headless = GraphicsEnvironment.isHeadless();
        if (headless) {
            System.err.println(who + " SKIPPED: no display; the GUI tests need an X server "
                    + "(e.g. Xvfb :99 & export DISPLAY=:99)");
        }
        return headless;
    }

    /** Call before each GUI test: fails without a display when one is required, else skips. */
    public static void requireDisplay() {
        boolean headless = GraphicsEnvironment.isHeadless();
        if (headless && System.getenv("TRISECT_REQUIRE_DISPLAY") != null) {
            throw new AssertionError("TRISECT_REQUIRE_DISPLAY is set but there is no display (DISPLAY="
                    + System.getenv("DISPLAY") + ")");
        }
        Assumptions.assumeFalse(headless, "no display: the GUI tests need an X server (set DISPLAY, e.g. Xvfb :99)");
    }

    /** Runs {@code task} on the event thread and returns its result (rethrowing what it threw). */
    public static <T> T onEdt(Callable<T> task) throws Exception {
        AtomicReference<T> result = new AtomicReference<>();
        AtomicReference<Exception> failure = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            try {
                result.set(task.call());
            } catch (Exception e) {
                failure.set(e);
            }
        });
        if (failure.get() != null) {
            throw failure.get();
        }
        return result.get();
    }

    /** Runs {@code task} on the event thread and waits for it. */
    public static void edt(ThrowingRunnable task) throws Exception {
        onEdt(() -> {
            task.run();
            return null;
        });
    }

    /** A runnable that may throw. */
    public interface ThrowingRunnable {
        void run() throws Exception;
    }

    /** A condition polled until it holds. */
    public interface Check {
        boolean ok() throws Exception;
    }

    /** Waits until {@code check} holds: bounded waiting (up to about 20 s: 400 polls 50 ms apart), not timing. */
    public static void waitFor(String what, Check check) throws Exception {
        for (int poll = 0; poll < 400; poll++) {
            if (check.ok()) {
                return;
            }
            Thread.sleep(50);
        }
        throw new AssertionError("timed out waiting for " + what);
    }
}
