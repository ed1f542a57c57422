package dev.trisect.io;

import dev.trisect.base.InputException;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ThreadLocalRandom;

/**
 * The outputs of one command, written as one transaction: each file goes to a temporary file beside
 * its target, and only {@link #commit} renames them all into place. Until then, and whenever anything
 * fails, no target is touched; {@link #close} without a commit deletes the temporary files.
 *
 * <p>A shutdown hook (run on SIGTERM, SIGINT or {@code System.exit}) deletes the temporary files of
 * every open batch. A commit and the hook exclude each other, so an interrupted command leaves either
 * all of its outputs renamed or none: an image and its UV output always belong together.
 *
 * <p>Usage: {@code try (OutputBatch batch = new OutputBatch()) { ImageFiles.write(batch, ...);
 * Pfm.write(batch, ...); batch.commit(); }}
 */
public final class OutputBatch implements AutoCloseable {
    /** Guards {@link #OPEN} and {@link #shuttingDown}; held through every commit and by the hook. */
    private static final Object LOCK = new Object();
    private static final Set<OutputBatch> OPEN = new HashSet<>();
    private static boolean shuttingDown;

    static {
        Runtime.getRuntime().addShutdownHook(new Thread(OutputBatch::abandonAll, "trisect-output-cleanup"));
    }

    /** Target and temporary file of each output, in the order written. */
    private final List<Path[]> entries = new ArrayList<>();
    private final Set<Path> targets = new LinkedHashSet<>();
    private boolean done;

    /** Opens an empty batch. */
    public OutputBatch() {
        synchronized (LOCK) {
            OPEN.add(this);
        }
    }

    /**
     * Writes {@code content} to a new temporary file beside {@code out}; nothing visible changes until
     * {@link #commit}. On a failure the temporary file is deleted at once.
     *
     * @throws InputException "{@code out}: cannot write: reason" when the file cannot be written, or a
     *                        usage error when the batch already holds {@code out}
     */
    void write(Path out, OutputFiles.Content content) {
        if (done) {
            throw new IllegalStateException("the batch is committed or closed");
        }
        if (Files.isDirectory(out)) {
            throw OutputFiles.cannotWrite(out, "it is a directory", null);
        }
        Path target = out.toAbsolutePath().normalize();
        if (!targets.add(target)) {
            throw InputException.usage(out + ": named for two outputs of one command");
        }
        Path temporary = null;
        boolean written = false;
        try {
            OutputStream raw = null;
            // A name of our own with CREATE_NEW rather than Files.createTempFile, whose 0600 mode
            // would stick to the final file; this one gets the usual permissions from the umask.
            for (int attempt = 0; raw == null; attempt++) {
                Path candidate = target.resolveSibling("." + target.getFileName() + "."
                        + Long.toHexString(ThreadLocalRandom.current().nextLong() >>> 16) + ".tmp");
                try {
                    synchronized (LOCK) {
                        if (shuttingDown) {
                            throw new IOException("the program is being stopped");
                        }
                        raw = Files.newOutputStream(candidate, StandardOpenOption.CREATE_NEW,
                                StandardOpenOption.WRITE);
                        temporary = candidate;
                        entries.add(new Path[] {target, temporary});
                    }
                } catch (FileAlreadyExistsException taken) {
                    if (attempt == 9) {
                        throw taken;
                    }
                }
            }
            try (OutputStream stream = new BufferedOutputStream(raw, 1 << 16)) {
                content.writeTo(stream);
            }
            written = true;
        } catch (IOException e) {
            throw OutputFiles.cannotWrite(out, OutputFiles.reason(e, target.getParent()), e);
        } finally {
            if (!written) {
                targets.remove(target);
                if (temporary != null) {
                    forget(temporary);
                }
            }
        }
    }

    /**
     * Renames every temporary file over its target. Should a rename fail, the targets already replaced
     * get their previous content back (kept as a hard link until the end), so the batch still changes
     * all or nothing.
     *
     * @throws InputException "{@code out}: cannot write: reason" for the first output that failed
     */
    public void commit() {
        synchronized (LOCK) {
            if (done || shuttingDown) {
                throw new IllegalStateException(done ? "the batch is committed or closed" : "shutting down");
            }
            List<Path[]> backups = new ArrayList<>();
            List<Path> placed = new ArrayList<>();
            Path failed = null;
            try {
                for (Path[] e : entries) {
                    failed = e[0];
                    if (Files.exists(e[0])) {
                        backups.add(new Path[] {e[0], backup(e[0])});
                    }
                    move(e[1], e[0]);
                    placed.add(e[0]);
                }
            } catch (IOException ex) {
                rollBack(placed, backups);
                throw OutputFiles.cannotWrite(failed, OutputFiles.reason(ex, failed.getParent()), ex);
            } finally {
                for (Path[] b : backups) {
                    deleteQuietly(b[1]);
                }
                for (Path[] e : entries) {
                    deleteQuietly(e[1]);
                }
                entries.clear();
                done = true;
                OPEN.remove(this);
            }
        }
    }

    /** Deletes the temporary files of an uncommitted batch; a committed one is left as it is. */
    @Override
    public void close() {
        synchronized (LOCK) {
            for (Path[] e : entries) {
                deleteQuietly(e[1]);
            }
            entries.clear();
            done = true;
            OPEN.remove(this);
        }
    }

    private void forget(Path temporary) {
        synchronized (LOCK) {
            deleteQuietly(temporary);
            entries.removeIf(e -> e[1].equals(temporary));
        }
    }

    /** The shutdown hook: waits for a commit in progress, then deletes every open batch's temporaries. */
    static void abandonAll() {
        synchronized (LOCK) {
            shuttingDown = true;
            for (OutputBatch b : OPEN) {
                for (Path[] e : b.entries) {
                    deleteQuietly(e[1]);
                }
                b.entries.clear();
                b.done = true;
            }
            OPEN.clear();
        }
    }

    /** A hard link to the current target, so a failed batch can put it back; null when none can be made. */
    private static Path backup(Path target) {
        Path link = target.resolveSibling("." + target.getFileName() + "."
                + Long.toHexString(ThreadLocalRandom.current().nextLong() >>> 16) + ".old");
        try {
            return Files.createLink(link, target);
        } catch (IOException | UnsupportedOperationException e) {
            return null;
        }
    }

    private static void rollBack(List<Path> placed, List<Path[]> backups) {
        for (Path target : placed) {
            Path saved = null;
            for (Path[] b : backups) {
                if (b[0].equals(target)) {
                    saved = b[1];
                }
            }
            try {
                if (saved != null) {
                    move(saved, target);
                } else {
                    Files.deleteIfExists(target);
                }
            } catch (IOException ignored) {
                // Nothing better to do: the original failure is what the user needs to see.
            }
        }
    }

    static void move(Path from, Path to) throws IOException {
        try {
            // rename(2): readers see the old file or the new one, never a mixture.
            Files.move(from, to, StandardCopyOption.ATOMIC_MOVE);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(from, to, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    private static void deleteQuietly(Path file) {
        if (file == null) {
            return;
        }
        try {
            Files.deleteIfExists(file);
        } catch (IOException ignored) {
            // A temporary file we could not delete is harmless; the output is what matters.
        }
    }
}
