package dev.trisect.io;

import dev.trisect.base.InputException;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

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
     * {@code out}: a batch of one (see {@link OutputBatch}). On any failure the temporary file is
     * deleted and {@code out}, if it existed, is untouched.
     *
     * @throws InputException "{@code out}: cannot write: reason" when the file cannot be written
     */
    static void writeAtomically(Path out, Content content) {
        try (OutputBatch batch = new OutputBatch()) {
            batch.write(out, content);
            batch.commit();
        }
    }

    static InputException cannotWrite(Path out, String reason, Throwable cause) {
        return new InputException(out + ": cannot write: " + reason, cause);
    }

    /**
     * A short, one-line reason for an I/O failure on a file in {@code directory}: the operating
     * system's words where there are some, without the temporary file's name.
     */
    static String reason(IOException e, Path directory) {
        // Encoders wrap the stream's failure ("I/O error writing PNG file!"): the cause has the reason.
        while (e.getCause() instanceof IOException cause && cause != e) {
            e = cause;
        }
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
