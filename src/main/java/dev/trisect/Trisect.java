package dev.trisect;

import dev.trisect.cli.Cli;
import dev.trisect.ui.DemoApp;
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
            status = DemoApp.launch(args.length == 0 ? args : Arrays.copyOfRange(args, 1, args.length));
            if (status < 0) {
                return; // the demo runs on; the JVM ends when its window closes
            }
        } else {
            // The demo joins the command list so that --help shows it; it is started above.
            status = Cli.run(List.of(new DemoApp()), args);
        }
        System.exit(status);
    }
}
