package dev.trisect.cli;

import dev.trisect.base.InputException;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;

/** Checks on the programs a command runs (bench's {@code --glref}), made before any work. */
final class Programs {
    private Programs() {
    }

    /**
     * Refuses a program that cannot be started, before anything is measured rather than after the
     * paths' rows: a name with a folder must be an executable file; a bare name is looked up on the
     * {@code PATH}, as {@link ProcessBuilder} starts it (an empty entry is the working directory).
     *
     * @param option  the option that named it, for the message
     * @param program the program
     * @throws InputException (exit status 1) naming the program and what is wrong
     */
    static void checkRunnable(String option, Path program) {
        if (program.getParent() != null) {
            if (!Files.isRegularFile(program) || !Files.isExecutable(program)) {
                throw new InputException(program + ": cannot run (" + option + "): "
                        + (Files.exists(program) ? "not an executable file" : "no such file"));
            }
            return;
        }
        String path = System.getenv("PATH");
        for (String dir : path == null ? new String[0] : path.split(File.pathSeparator, -1)) {
            Path candidate = Path.of(dir.isEmpty() ? "." : dir).resolve(program);
            if (Files.isRegularFile(candidate) && Files.isExecutable(candidate)) {
                return;
            }
        }
        throw new InputException(program + ": cannot run (" + option + "): no such program on the PATH");
    }
}
