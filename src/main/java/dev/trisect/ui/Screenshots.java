package dev.trisect.ui;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;

/**
 * Where Ctrl+S puts screenshots: the user's Pictures folder if there is one, else the home folder —
 * never the working directory, which under {@code mvn exec:java} is the repository.
 */
final class Screenshots {
    private Screenshots() {
    }

    /** The folder for screenshots, given the user's home folder. */
    static Path folder(Path home) {
        Path pictures = home.resolve("Pictures");
        return Files.isDirectory(pictures) ? pictures : home;
    }

    /** The folder for this user (from {@code user.home}). */
    static Path folder() {
        return folder(Path.of(System.getProperty("user.home")));
    }

    /** A new file name in {@code dir}, stamped with {@code time}, that does not exist yet. */
    static Path newFile(Path dir, LocalDateTime time) {
        String stamp = time.format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss"));
        Path out = dir.resolve("trisect-" + stamp + ".png");
        for (int n = 2; Files.exists(out); n++) {
            out = dir.resolve("trisect-" + stamp + "-" + n + ".png");
        }
        return out;
    }
}
