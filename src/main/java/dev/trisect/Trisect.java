package dev.trisect;

import dev.trisect.cli.Cli;

/**
 * The program's entry point: with arguments, the command line; without, the desktop demo.
 */
public final class Trisect {
    private Trisect() {
    }

    public static void main(String[] args) {
        int status = Cli.run(args);
        if (status != 0 || args.length > 0) {
            System.exit(status);
        }
    }
}
