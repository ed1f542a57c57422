package dev.trisect.io;

import dev.trisect.base.InputException;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AccessDeniedException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.concurrent.ThreadLocalRandom;

/** Writing a file all or nothing, and wording I/O failures for users. Package-private plumbing. */
final class OutputFiles {
    /** Writes a file's whole content to a stream. */
    interface Content {
        void writeTo(OutputStream out) throws IOException;
    }

    private OutputFiles() {
    }

    /**
     * Writes {@code content} to a new temporary file beside {@code out}, then renames it over
     * {@code out}. On any failure the temporary file is deleted and {@code out}, if it existed, is
     * untouched.
     *
     * @throws InputException "{@code out}: cannot write: reason" when the file cannot be written
     */
    static void writeAtomically(Path out, Content content) {
        if (Files.isDirectory(out)) {
            throw cannotWrite(out, "it is a directory", null);
        }
        Path target = out.toAbsolutePath();
        Path temporary = null;
        try {
            OutputStream raw = null;
            // A name of our own with CREATE_NEW rather than Files.createTempFile, whose 0600 mode
            // would stick to the final file; this one gets the usual permissions from the umask.
            for (int attempt = 0; raw == null; attempt++) {
                Path candidate = target.resolveSibling("." + target.getFileName() + "."
                        + Long.toHexString(ThreadLocalRandom.current().nextLong() >>> 16) + ".tmp");
                try {
                    raw = Files.newOutputStream(candidate, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
                    temporary = candidate;
                } catch (FileAlreadyExistsException taken) {
                    if (attempt == 9) {
                        throw taken;
                    }
                }
            }
            try (OutputStream stream = new BufferedOutputStream(raw, 1 << 16)) {
                content.writeTo(stream);
            }
            move(temporary, target);
            temporary = null;
        } catch (IOException e) {
            throw cannotWrite(out, reason(e, target.getParent()), e);
        } finally {
            if (temporary != null) {
                try {
                    Files.deleteIfExists(temporary);
                } catch (IOException ignored) {
                    // Nothing better to do: the original failure is what the user needs to see.
                }
            }
        }
    }

    private static void move(Path from, Path to) throws IOException {
        try {
            // rename(2): readers see the old file or the new one, never a mixture.
            Files.move(from, to, StandardCopyOption.ATOMIC_MOVE);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(from, to, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    private static InputException cannotWrite(Path out, String reason, Throwable cause) {
        return new InputException(out + ": cannot write: " + reason, cause);
    }

    /**
     * A short, one-line reason for an I/O failure on a file in {@code directory}: the operating
     * system's words where there are some, without the temporary file's name.
     */
    static String reason(IOException e, Path directory) {
        if (e instanceof NoSuchFileException) {
            return directory != null && !Files.isDirectory(directory)
                    ? "no such directory " + directory : "no such file";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        String reason = e instanceof FileSystemException fs ? fs.getReason() : e.getMessage();
        if (reason == null || reason.isBlank()) {
            reason = e.getClass().getSimpleName();
        }
        return reason.replace('\n', ' ');
    }
}
