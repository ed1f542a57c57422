package dev.trisect;

import dev.trisect.cli.Cli;
import dev.trisect.io.OutputBatch;
import dev.trisect.ui.DemoApp;
import dev.trisect.ui.ReportFile;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The program's entry point: without arguments (or with {@code demo ...}) the desktop demo,
 * otherwise the command line.
 */
public final class Trisect {
    private Trisect() {
    }

    /**
     * The application's own libraries, each with a class of it: the installed artifact is the
     * library, which depends on them only optionally, so {@code java -jar} on it finds none of them.
     */
    private static final String[][] APPLICATION_LIBRARIES = {
        {"picocli", "picocli.CommandLine"},
        {"FlatLaf", "com.formdev.flatlaf.FlatDarkLaf"},
        {"XChart", "org.knowm.xchart.XYChart"},
    };

    public static void main(String[] args) {
        List<String> missing = missingLibraries(Trisect.class.getClassLoader());
        if (!missing.isEmpty()) {
            // Without this, the first class that needs one fails with a NoClassDefFoundError's trace.
            System.err.println("trisect: " + String.join(", ", missing) + " not found: this is the library jar"
                    + " without the application's libraries; run the application jar (target/trisect.jar, made by"
                    + " mvn package) or put them on the class path");
            System.exit(1);
        }
        int status;
        if (args.length == 0 || args[0].equals("demo")) {
            status = DemoApp.launch(Trisect::openReport,
                    args.length == 0 ? args : Arrays.copyOfRange(args, 1, args.length));
            if (status < 0) {
                return; // the demo runs on; the JVM ends when its window closes
            }
        } else {
            // The demo joins the command list so that --help shows it; it is started above.
            status = Cli.run(List.of(new DemoApp()), args);
        }
        System.exit(status);
    }

    /** The application libraries ({@link #APPLICATION_LIBRARIES}) that {@code loader} cannot find, by name. */
    static List<String> missingLibraries(ClassLoader loader) {
        List<String> missing = new ArrayList<>();
        for (String[] library : APPLICATION_LIBRARIES) {
            try {
                Class.forName(library[1], false, loader);
            } catch (ClassNotFoundException | LinkageError e) {
                missing.add(library[0]);
            }
        }
        return missing;
    }

    /** The demo's soak report, written by the command line's all-or-nothing writer. */
    static ReportFile openReport(Path file) {
        OutputBatch batch = new OutputBatch();
        try {
            batch.reserve(file);
        } catch (RuntimeException e) {
            batch.close();
            throw e;
        }
        return new ReportFile() {
            @Override
            public void write(String text) {
                batch.writeText(file, text);
                batch.commit();
            }

            @Override
            public void close() {
                batch.close();
            }
        };
    }
}
