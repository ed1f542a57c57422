package dev.trisect.base;

/**
 * Bad input from a user: a file that cannot be read or parsed, or a value out of range.
 *
 * <p>The message is one line meant for the user as it is, naming the file (and the line, where there
 * is one) and what is wrong, for example {@code scene.obj:12: vertex index 9 is out of range (1..8)}.
 * The command line prints it without a stack trace; the desktop demo shows it in a dialog.
 */
public final class InputException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** Whether the input could not be read at all (exit status 1) or was a usage error (exit status 2). */
    public enum Kind {
        /** The input could not be read, or is malformed: exit status 1. */
        UNREADABLE,
        /** A value the user gave is out of range or inconsistent: exit status 2. */
        USAGE
    }

    /** Usage error or unreadable input. */
    private final Kind kind;

    /**
     * An unreadable or malformed input file: exit status 1.
     *
     * @param message one line naming the file, the line and the problem
     */
    public InputException(String message) {
        this(Kind.UNREADABLE, message, null);
    }

    /**
     * An unreadable or malformed input file, with the low-level cause kept for {@code --verbose}.
     *
     * @param message one line naming the file, the line and the problem
     * @param cause   what the reading code threw
     */
    public InputException(String message, Throwable cause) {
        this(Kind.UNREADABLE, message, cause);
    }

    private InputException(Kind kind, String message, Throwable cause) {
        super(message, cause);
        this.kind = kind;
    }

    /**
     * A value the user gave that is out of range or inconsistent (exit status 2).
     *
     * @param message one line naming the option or value and what is wrong
     * @return the error, to throw
     */
    public static InputException usage(String message) {
        return new InputException(Kind.USAGE, message, null);
    }

    /**
     * Whether this is a usage error (exit 2) or unreadable input (exit 1).
     *
     * @return {@link Kind#USAGE} or {@link Kind#UNREADABLE}
     */
    public Kind kind() {
        return kind;
    }

    /**
     * The conventional process exit status for this error.
     *
     * @return 2 for a usage error, 1 for unreadable input
     */
    public int exitStatus() {
        return kind == Kind.USAGE ? 2 : 1;
    }

    /**
     * {@code text} quoted for a one-line message: in single quotes, control characters escaped as
     * {@code \xNN} so the message stays one printable line, and cut to {@code max} characters
     * (then ending in {@code ...}).
      *
     * @param text any text, from a file or an option
     * @param max  characters of {@code text} kept
     * @return the quoted, escaped, possibly cut text
     */
    public static String quote(String text, int max) {
        StringBuilder sb = new StringBuilder("'");
        for (int k = 0; k < text.length() && k < max; k++) {
            char c = text.charAt(k);
            if (c < 0x20 || (c >= 0x7f && c <= 0x9f)) {
                sb.append(String.format(java.util.Locale.ROOT, "\\x%02X", (int) c));
            } else {
                sb.append(c);
            }
        }
        if (text.length() > max) {
            sb.append("...");
        }
        return sb.append('\'').toString();
    }
}
