package dev.trisect.base.internal;

import dev.trisect.base.InputException;

/**
 * The one way a message about something that went wrong starts, wherever it shows — the command
 * line's standard error, the demo's status bar and dialogs, a view's message listeners: "trisect: ",
 * then what could not be done and why ("trisect: cannot save the screenshot: disk full"). Messages that
 * report success or give a hint start otherwise, so the prefix alone tells a problem.
 */
public final class ErrorLine {
    /** How every problem's message starts. */
    public static final String PREFIX = "trisect: ";

    private ErrorLine() {
    }

    /** A problem's message: {@link #PREFIX} and {@code what}. */
    public static String of(String what) {
        return PREFIX + what;
    }

    /**
     * A failure's message: "trisect: cannot {@code doing}: reason".
     *
     * @param doing      what could not be done ("draw the frame", "save the screenshot")
     * @param t          why
     * @param memoryHint what to do when {@code t} is running out of memory ("give Java more with -Xmx")
     */
    public static String cannot(String doing, Throwable t, String memoryHint) {
        return PREFIX + "cannot " + doing + ": " + reason(t, memoryHint);
    }

    /**
     * Why, in a few words: an input error's own message (which names the file and line), "out of memory
     * (hint)", or "internal error: " and the exception for anything else (a bug).
     */
    public static String reason(Throwable t, String memoryHint) {
        if (t instanceof InputException ie) {
            return ie.getMessage();
        }
        if (t instanceof OutOfMemoryError) {
            return "out of memory (" + memoryHint + ")";
        }
        return "internal error: " + t;
    }
}
