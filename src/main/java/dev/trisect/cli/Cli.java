package dev.trisect.cli;

import dev.trisect.base.InputException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.ParseResult;

/**
 * Runs the command line. Bad input ends in one line on standard error and a non-zero status:
 * 2 for a usage error (an unknown option, a value out of range), 1 for input that cannot be read.
 * A stack trace is printed only with {@code --verbose}.
 */
public final class Cli {
    private Cli() {
    }

    /** Runs {@code args} with the process's streams and returns the exit status. */
    public static int run(String... args) {
        return run(List.of(), args);
    }

    /**
     * Runs {@code args} with the process's streams and further subcommands (see
     * {@link #run(PrintWriter, PrintWriter, List, String...)}). Standard output is written through a
     * stream that reports failures (a full disk, a closed pipe): they end the command with exit status 1.
     */
    public static int run(List<Object> moreCommands, String... args) {
        return run(OutputWriter.standardOutput(), new PrintWriter(System.err, true), moreCommands, args);
    }

    /** Runs {@code args} writing to the given streams; returns the exit status. */
    public static int run(PrintWriter out, PrintWriter err, String... args) {
        return run(out, err, List.of(), args);
    }

    /**
     * Runs {@code args} with further picocli subcommands beside the built-in ones (the launcher adds
     * the desktop demo, which lives above this package, so that {@code --help} lists it).
     */
    public static int run(PrintWriter out, PrintWriter err, List<Object> moreCommands, String... args) {
        System.setProperty("trisect.processors", Integer.toString(Runtime.getRuntime().availableProcessors()));
        CommandLine cl = new CommandLine(new TrisectCommand());
        for (Object command : moreCommands) {
            cl.addSubcommand(command);
        }
        // Every command's help offers -V, --version; without the root's provider a subcommand printed nothing.
        for (CommandLine sub : cl.getSubcommands().values()) {
            sub.getCommandSpec().versionProvider(new Version());
        }
        // Every file name the user gives becomes a path through one converter, with one message for a name
        // the locale cannot map (see Converters.path).
        cl.registerConverter(Path.class, Converters::path);
        cl.setOut(out);
        cl.setErr(err);
        cl.setParameterExceptionHandler((ex, arguments) -> {
            String where = ex.getCommandLine().getCommandSpec().qualifiedName();
            err.println(where + ": " + firstLine(escapeValues(ex.getMessage(), args)) + " (see " + where + " --help)");
            err.flush();
            return 2;
        });
        cl.setExecutionExceptionHandler((ex, commandLine, parseResult) -> {
            boolean verbose = verbose(parseResult);
            int status;
            if (ex instanceof InputException ie) {
                err.println("trisect: " + oneLine(ie.getMessage()));
                status = ie.exitStatus();
            } else {
                err.println("trisect: internal error: " + oneLine(String.valueOf(ex))
                        + (verbose ? "" : " (run with --verbose for details)"));
                status = 3;
            }
            if (verbose) {
                ex.printStackTrace(err);
            }
            err.flush();
            return status;
        });
        // picocli lets a help option win over an unknown command or argument: trisect rendr --help printed
        // the root help with exit 0, saying nothing of 'rendr'. An unmatched argument is an error regardless.
        cl.setExecutionStrategy(parseResult -> {
            for (ParseResult r = parseResult; r != null; r = r.subcommand()) {
                if (!r.unmatched().isEmpty()) {
                    throw new CommandLine.UnmatchedArgumentException(r.commandSpec().commandLine(), r.unmatched());
                }
            }
            return new CommandLine.RunLast().execute(parseResult);
        });
        // Made before the work: when the heap is exhausted, building a message could fail too.
        // --size is what bounds a frame's memory (its buffers, and the pieces beyond one per triangle, which the
        // automatic budget gives per pixel); --max-frame-pieces cannot go below one piece per triangle, so it
        // did not help a large model. A model that does not fit while it is read gets its own message.
        String renderingOom = "trisect: out of memory (use a smaller --size, or give Java more with -Xmx)";
        String sceneOom = "trisect: out of memory: the scene needs more than the heap holds (give Java more with "
                + "-Xmx, e.g. java -Xmx4g -jar trisect.jar)";
        String otherOom = "trisect: out of memory (give Java more with -Xmx, e.g. java -Xmx4g -jar trisect.jar)";
        try {
            int status = cl.execute(args);
            // Whatever a command printed (help, a scene list) must have arrived; a command that failed
            // has said why already.
            String failure = status == 0 ? OutputWriter.failure(out) : null;
            if (failure != null) {
                err.println("trisect: " + Results.cannotWrite(failure));
                err.flush();
                return 1;
            }
            return status;
        } catch (OutOfMemoryError e) {
            // Only the commands that render a frame have --size, and only there does it decide the memory
            // (export refuses --size).
            // A small frame: a smaller --size would not help, the scene's storage is what fills the heap.
            err.println(!rendersFrame(cl) ? otherOom : Frames.frameMatters() ? renderingOom : sceneOom);
            err.flush();
            return 1;
        }
    }

    /**
     * {@code message} kept to one line: a value the user typed can hold a newline or other control
     * character ({@code --scene $'floor\nX'}), which is shown escaped as {@code \xNN}, as
     * {@link InputException#quote} does.
     */
    static String oneLine(String message) {
        StringBuilder sb = null;
        for (int i = 0; i < message.length(); i++) {
            char c = message.charAt(i);
            boolean control = c < 0x20 || (c >= 0x7f && c <= 0x9f);
            if (control && sb == null) {
                sb = new StringBuilder(message.length() + 8).append(message, 0, i);
            }
            if (control) {
                sb.append(String.format(java.util.Locale.ROOT, "\\x%02X", (int) c));
            } else if (sb != null) {
                sb.append(c);
            }
        }
        return sb == null ? message : sb.toString();
    }

    private static boolean rendersFrame(CommandLine cl) {
        ParseResult r = cl.getParseResult();
        while (r != null && r.subcommand() != null) {
            r = r.subcommand();
        }
        return r != null && r.commandSpec().userObject() instanceof SceneCommand;
    }

    private static boolean verbose(ParseResult result) {
        for (ParseResult r = result; r != null; r = r.subcommand()) {
            if (r.hasMatchedOption("--verbose")) {
                return true;
            }
        }
        return false;
    }

    /**
     * picocli's message with each argument that holds a control character escaped as {@link #oneLine}
     * does: its own messages may run over lines (a suggestion on the second), the user's values may not.
     */
    private static String escapeValues(String message, String[] args) {
        if (message == null) {
            return null;
        }
        for (String arg : args) {
            String escaped = oneLine(arg);
            if (!escaped.equals(arg)) {
                message = message.replace(arg, escaped);
                // An option given as --name=value reaches the message as the value alone.
                int eq = arg.indexOf('=');
                if (eq >= 0) {
                    message = message.replace(arg.substring(eq + 1), oneLine(arg.substring(eq + 1)));
                }
            }
        }
        return message;
    }

    private static String firstLine(String message) {
        if (message == null) {
            return "invalid arguments";
        }
        int nl = message.indexOf('\n');
        return (nl < 0 ? message : message.substring(0, nl)).trim();
    }
}
