package dev.trisect.ui;

import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;

/**
 * The demo's memory between runs: the OBJ files opened last (newest first, at most {@link #MAX}) and
 * the folder Open OBJ showed last, kept in a small properties file ({@code ~/.config/trisect/demo.properties},
 * written whole or not at all). A file that cannot be read or written only forgets: the demo never
 * fails over it. Event thread only.
 */
final class RecentFiles {
    /** Files remembered at most. */
    static final int MAX = 8;
    private static final String FOLDER = "open-folder";
    private static final String FILE = "recent-";

    private final Path file;
    private final Properties store = new Properties();

    /** The demo's own file, in the user's configuration folder. */
    RecentFiles() {
        this(Path.of(System.getProperty("user.home"), ".config", "trisect", "demo.properties"));
    }

    /** Remembers in {@code file} (read now if it exists). */
    RecentFiles(Path file) {
        this.file = file;
        try (Reader in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            store.load(in);
        } catch (IOException | IllegalArgumentException e) {
            // Nothing remembered yet, or nothing readable: start afresh.
        }
    }

    /** The folder to open Open OBJ in: the last one used, if it still exists, else the working directory. */
    Path folder() {
        Path p = path(store.getProperty(FOLDER));
        return p != null && Files.isDirectory(p) ? p : Path.of("").toAbsolutePath();
    }

    /** The files opened, newest first. */
    List<Path> files() {
        List<Path> out = new ArrayList<>();
        for (int i = 0; i < MAX; i++) {
            Path p = path(store.getProperty(FILE + i));
            if (p != null) {
                out.add(p);
            }
        }
        return out;
    }

    /** Remembers a file just opened (first in the list, once) and its folder for Open OBJ. */
    void opened(Path file) {
        Path abs = file.toAbsolutePath().normalize();
        List<Path> list = new ArrayList<>(files());
        list.remove(abs);
        list.add(0, abs);
        write(list);
        if (abs.getParent() != null) {
            store.setProperty(FOLDER, abs.getParent().toString());
        }
        flush();
    }

    /** Forgets one file (it could not be opened). */
    void forget(Path file) {
        List<Path> list = new ArrayList<>(files());
        list.remove(file.toAbsolutePath().normalize());
        write(list);
        flush();
    }

    /** Forgets every file (the folder stays). */
    void clear() {
        write(List.of());
        flush();
    }

    private void write(List<Path> list) {
        for (int i = 0; i < MAX; i++) {
            if (i < list.size()) {
                store.setProperty(FILE + i, list.get(i).toString());
            } else {
                store.remove(FILE + i);
            }
        }
    }

    /** Writes the file whole (a partial one never takes its name). */
    private void flush() {
        Path part = file.resolveSibling(file.getFileName() + ".part");
        try {
            Files.createDirectories(file.getParent());
            try (Writer out = Files.newBufferedWriter(part, StandardCharsets.UTF_8)) {
                store.store(out, "Trisect demo: files opened lately and the folder Open OBJ showed last");
            }
            Files.move(part, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (IOException | SecurityException e) {
            // Not remembered on disk; this run still has it.
            try {
                Files.deleteIfExists(part);
            } catch (IOException ignored) {
                // Nothing more to do.
            }
        }
    }

    private static Path path(String s) {
        try {
            return s == null || s.isBlank() ? null : Path.of(s);
        } catch (InvalidPathException e) {
            return null;
        }
    }
}
