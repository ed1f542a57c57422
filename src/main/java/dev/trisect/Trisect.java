package dev.trisect;

import dev.trisect.cli.Cli;
import dev.trisect.io.OutputBatch;
import dev.trisect.ui.DemoApp;
import dev.trisect.ui.ReportFile;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

/**
 * The program's entry point: without arguments (or with {@code demo ...}) the desktop demo,
 * otherwise the command line.
 */
public final class Trisect {
    private Trisect() {
    }

    public static void main(String[] args) {
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
