package dev.trisect.io;

import dev.trisect.base.InputException;
import java.io.BufferedOutputStream;
import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ThreadLocalRandom;
import java.util.function.UnaryOperator;

/**
 * The outputs of one command, written as one transaction: each file goes to a temporary file beside
 * its target, and only {@link #commit} renames them all into place. Until then, and whenever anything
 * fails, no target is touched; {@link #close} without a commit deletes the temporary files.
 *
 * <p>A shutdown hook (run on SIGTERM, SIGINT or {@code System.exit}) deletes the temporary files of
 * every open batch. A commit and the hook exclude each other, so an interrupted command leaves either
 * all of its outputs renamed or none: an image and its UV output always belong together.
 *
 * <p>Each output can be {@linkplain #reserve reserved} before the work that computes it: that creates its
 * temporary file at once, so a missing folder or a folder that cannot be written is reported before
 * a long render rather than after it. The target is the file a symbolic link points to (the link
 * stays, as editors keep it), and a replaced file keeps its permissions. Temporary files are locked
 * while in use, so that those a killed run left behind can be told apart and cleaned
 * ({@link Temporaries}).
 *
 * <p>Usage: {@code try (OutputBatch batch = new OutputBatch()) { batch.reserve(out); ...work...;
 * ImageFiles.write(batch, out, ...); Pfm.write(batch, ...); batch.commit(); }}
 */
public final class OutputBatch implements AutoCloseable {
    /** Guards {@link #OPEN} and {@link #shuttingDown}; held through every commit and by the hook. */
    private static final Object LOCK = new Object();
    private static final Set<OutputBatch> OPEN = new HashSet<>();
    private static boolean shuttingDown;

    /** Tests only: wraps each temporary file's stream, to inject a full disk at a chosen write. */
    static volatile UnaryOperator<OutputStream> faults;

    static {
        Runtime.getRuntime().addShutdownHook(new Thread(OutputBatch::abandonAll, "trisect-output-cleanup"));
    }

    /** A stream whose close leaves the channel under it open, and locked, until the commit. */
    private static final class Unclosed extends FilterOutputStream {
        Unclosed(OutputStream channel) {
            super(channel);
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            out.write(b, off, len);
        }

        @Override
        public void close() throws IOException {
            flush();
        }
    }

    /** One output: its target (absolute, links followed) and its open, locked temporary file. */
    private static final class Entry {
        final Path target;
        Path temporary;
        FileChannel channel;
        boolean written;

        Entry(Path target) {
            this.target = target;
        }
    }

    private final List<Entry> entries = new ArrayList<>();
    private final Set<Path> targets = new HashSet<>();
    private boolean done;

    /** Opens an empty batch. */
    public OutputBatch() {
        synchronized (LOCK) {
            OPEN.add(this);
        }
    }

    /**
     * Checks now that {@code out} can be written, by creating its temporary file, and keeps that file
     * for the later write of {@code out}. Call it before the work: a missing or read-only folder then
     * costs nothing.
     *
     * @throws InputException "{@code out}: cannot write: reason", or a usage error when the batch
     *                        already holds {@code out}
     */
    public void reserve(Path out) {
        open(out);
    }

    /**
     * Writes {@code content} to {@code out}'s temporary file (the one {@link #reserve} made, or a new
     * one); nothing visible changes until {@link #commit}. On a failure the temporary file is deleted.
     *
     * @throws InputException "{@code out}: cannot write: reason" when the file cannot be written, or a
     *                        usage error when the batch already holds {@code out}
     */
    void write(Path out, OutputFiles.Content content) {
        Entry e = null;
        synchronized (LOCK) {
            checkOpen();
            Path target = target(out);
            for (Entry x : entries) {
                if (x.target.equals(target) && !x.written) {
                    e = x;
                }
            }
        }
        if (e == null) {
            e = open(out);
        }
        boolean ok = false;
        try {
            FileChannel channel = e.channel;
            channel.truncate(0);
            channel.position(0);
            OutputStream raw = new Unclosed(Channels.newOutputStream(channel));
            UnaryOperator<OutputStream> inject = faults;
            try (OutputStream stream = new BufferedOutputStream(inject == null ? raw : inject.apply(raw), 1 << 16)) {
                content.writeTo(stream);
            }
            e.written = true;
            ok = true;
        } catch (IOException ex) {
            synchronized (LOCK) {
                // The hook closed the file under this write.
                checkOpen();
            }
            throw OutputFiles.cannotWrite(out, OutputFiles.reason(ex, e.target.getParent()), ex);
        } finally {
            if (!ok) {
                drop(e);
            }
        }
    }

    /**
     * Writes {@code text} as UTF-8 to {@code out} as part of this batch (a report, say).
     *
     * @throws InputException "{@code out}: cannot write: reason"
     */
    public void writeText(Path out, String text) {
        write(out, stream -> stream.write(text.getBytes(java.nio.charset.StandardCharsets.UTF_8)));
    }

    /** A new entry for {@code out} with its temporary file created, locked and registered. */
    private Entry open(Path out) {
        synchronized (LOCK) {
            checkOpen();
        }
        if (Files.isDirectory(out)) {
            throw OutputFiles.cannotWrite(out, "it is a directory", null);
        }
        Path target;
        try {
            target = target(out);
        } catch (UncheckedIOException ex) {
            throw OutputFiles.cannotWrite(out, OutputFiles.reason(ex.getCause(), null), ex);
        }
        // A FIFO, device or socket would be replaced by a regular file, its node gone (found by the fault
        // probe: --out on a FIFO named p.png); outputs replace regular files only, as readers read only them.
        if (Files.exists(target) && !Files.isRegularFile(target)) {
            throw OutputFiles.cannotWrite(out, "it is not a regular file (a FIFO, device or socket), which the "
                    + "output would replace", null);
        }
        synchronized (LOCK) {
            if (!targets.add(target)) {
                throw InputException.usage(out + ": named for two outputs of one command");
            }
        }
        Entry e = new Entry(target);
        try {
            Temporaries.cleanStale(target.getParent());
            for (int attempt = 0; e.channel == null; attempt++) {
                Path candidate = Temporaries.name(target);
                try {
                    synchronized (LOCK) {
                        checkOpen();
                        // A name of our own with CREATE_NEW rather than Files.createTempFile, whose 0600 mode
                        // would stick to a new file; this one gets the usual permissions from the umask.
                        e.channel = FileChannel.open(candidate, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
                        e.temporary = candidate;
                        entries.add(e);
                    }
                } catch (FileAlreadyExistsException taken) {
                    if (attempt == 9) {
                        throw taken;
                    }
                    continue;
                }
                lock(e.channel);
                if (!Files.exists(candidate)) {
                    // Another process's cleaning took it before the lock: start again with a new name.
                    drop(e);
                    synchronized (LOCK) {
                        targets.add(target);
                    }
                    e = new Entry(target);
                }
            }
            return e;
        } catch (IOException ex) {
            drop(e);
            throw OutputFiles.cannotWrite(out, OutputFiles.reason(ex, target.getParent()), ex);
        }
    }

    /** Marks the temporary file as in use for other processes' cleaning; best effort. */
    private static void lock(FileChannel channel) {
        try {
            channel.tryLock();
        } catch (IOException | RuntimeException ignored) {
            // A file system without locks: the file is then never cleaned as stale by others either.
        }
    }

    /**
     * Where writing {@code out} goes: its absolute path, with symbolic links followed to the file they
     * name (which need not exist yet), so that replacing it keeps the link.
     */
    private static Path target(Path out) {
        Path p = out.toAbsolutePath().normalize();
        try {
            for (int hops = 0; Files.isSymbolicLink(p); hops++) {
                if (hops == 40) {
                    throw new FileSystemException(out.toString(), null, "Too many levels of symbolic links");
                }
                p = p.resolveSibling(Files.readSymbolicLink(p)).normalize();
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return p;
    }

    /**
     * Refuses to go on once the program is being stopped (SIGTERM, SIGINT): the shutdown hook has deleted
     * the temporary files, and the command ends with this one line rather than an internal error.
     */
    private void checkOpen() {
        if (shuttingDown) {
            throw stopped();
        }
        if (done) {
            throw new IllegalStateException("the batch is committed or closed");
        }
    }

    /** Forgets an entry and deletes its temporary file. */
    private void drop(Entry e) {
        synchronized (LOCK) {
            entries.remove(e);
            targets.remove(e.target);
            release(e);
        }
    }

    /**
     * Renames every written temporary file over its target (a reserved one never written is dropped),
     * the target's permissions kept. Should a rename fail, the targets already replaced get their
     * previous content back (kept as a hard link until the end), so the batch still changes all or
     * nothing.
     *
     * @throws InputException "{@code out}: cannot write: reason" for the first output that failed
     */
    public void commit() {
        synchronized (LOCK) {
            checkOpen();
            List<Path[]> backups = new ArrayList<>();
            List<Path> placed = new ArrayList<>();
            Path failed = null;
            try {
                for (Entry e : entries) {
                    if (!e.written) {
                        continue;
                    }
                    failed = e.target;
                    if (Files.exists(e.target)) {
                        keepPermissions(e.target, e.temporary);
                        backups.add(new Path[] {e.target, backup(e.target)});
                    }
                    move(e.temporary, e.target);
                    e.temporary = null;
                    placed.add(e.target);
                }
            } catch (IOException ex) {
                rollBack(placed, backups);
                throw OutputFiles.cannotWrite(failed, OutputFiles.reason(ex, failed.getParent()), ex);
            } finally {
                for (Path[] b : backups) {
                    deleteQuietly(b[1]);
                }
                releaseAll(this);
                OPEN.remove(this);
            }
        }
    }

    /** Deletes the temporary files of an uncommitted batch; a committed one is left as it is. */
    @Override
    public void close() {
        synchronized (LOCK) {
            releaseAll(this);
            OPEN.remove(this);
        }
    }

    private static InputException stopped() {
        return new InputException("stopped: no output was written or changed");
    }

    /** The shutdown hook: waits for a commit in progress, then deletes every open batch's temporaries. */
    static void abandonAll() {
        synchronized (LOCK) {
            shuttingDown = true;
            for (OutputBatch b : OPEN) {
                releaseAll(b);
            }
            OPEN.clear();
        }
    }

    private static void releaseAll(OutputBatch b) {
        for (Entry e : b.entries) {
            release(e);
        }
        b.entries.clear();
        b.done = true;
    }

    /** Closes an entry's channel (dropping its lock) and deletes its temporary file, if still there. */
    private static void release(Entry e) {
        if (e.channel != null) {
            try {
                e.channel.close();
            } catch (IOException ignored) {
                // Closing a file we only wrote: nothing to lose.
            }
        }
        deleteQuietly(e.temporary);
        e.temporary = null;
    }

    /** Gives the new file the old one's permission bits (mode 600 stays 600); best effort. */
    private static void keepPermissions(Path from, Path to) {
        try {
            Files.setPosixFilePermissions(to, Files.getPosixFilePermissions(from));
        } catch (IOException | UnsupportedOperationException ignored) {
            // Not a POSIX file system, or not ours to read: the umask's permissions stay.
        }
    }

    /**
     * Creates {@code folder} and any missing parents.
     *
     * @throws InputException "cannot create the directory D: reason", D the folder that could not be made
     *                        and the reason in the operating system's words ("permission denied", "a file
     *                        of that name is in the way")
     */
    public static void createFolders(Path folder) {
        try {
            Files.createDirectories(folder);
        } catch (IOException e) {
            Path failed = e instanceof FileSystemException fs && fs.getFile() != null ? Path.of(fs.getFile()) : folder;
            String reason = e instanceof FileAlreadyExistsException ? "a file of that name is in the way"
                    : OutputFiles.reason(e, null);
            throw new InputException("cannot create the directory " + failed + ": " + reason, e);
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
