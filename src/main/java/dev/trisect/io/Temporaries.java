package dev.trisect.io;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.HashSet;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.ThreadLocalRandom;
import java.util.regex.Pattern;

/**
 * The temporary files of {@link OutputBatch}: their names, and the cleaning of those a killed run
 * (SIGKILL, a power cut) left behind.
 *
 * <p>A temporary file is named {@code .NAME.HEX.tmp} beside its target {@code NAME}, HEX twelve random
 * hexadecimal digits. While a batch uses one it holds an exclusive lock on it ({@link FileChannel#tryLock},
 * a POSIX record lock, which the operating system drops when the process ends, however it ends). So a
 * temporary file of our pattern that nobody holds locked is stale: the first batch that writes into its
 * folder deletes it. Only names of the outputs Trisect writes are touched (.png, .ppm, .pfm, .obj, .mtl,
 * .json), never a file of another pattern.
 */
final class Temporaries {
    /** Our temporary files' names: a hidden name, one of our extensions, twelve hex digits, .tmp. */
    private static final Pattern NAME =
            Pattern.compile("\\..+\\.(png|ppm|pfm|obj|mtl|json)\\.[0-9a-f]{12}\\.tmp", Pattern.CASE_INSENSITIVE);
    /** Folders already cleaned by this process: once each is enough. */
    private static final Set<Path> CLEANED = new HashSet<>();

    private Temporaries() {
    }

    /** A fresh temporary name beside {@code target}. */
    static Path name(Path target) {
        long bits = ThreadLocalRandom.current().nextLong() >>> 16;
        return target.resolveSibling("." + target.getFileName() + "." + String.format(Locale.ROOT, "%012x", bits)
                + ".tmp");
    }

    /** Whether {@code file}'s name is of our temporaries' pattern. */
    static boolean ours(Path file) {
        return NAME.matcher(file.getFileName().toString()).matches();
    }

    /**
     * Deletes the stale temporary files in {@code folder}: those of our pattern that no process holds
     * locked. Done once per folder and process; failures are ignored (cleaning is a courtesy).
     */
    static void cleanStale(Path folder) {
        synchronized (CLEANED) {
            if (folder == null || !CLEANED.add(folder)) {
                return;
            }
        }
        try (DirectoryStream<Path> files = Files.newDirectoryStream(folder, ".*.tmp")) {
            for (Path file : files) {
                if (ours(file) && Files.isRegularFile(file, LinkOption.NOFOLLOW_LINKS)) {
                    deleteIfUnlocked(file);
                }
            }
        } catch (IOException | RuntimeException ignored) {
            // An unreadable folder: the write itself will say what is wrong.
        }
    }

    private static void deleteIfUnlocked(Path file) {
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.WRITE)) {
            FileLock lock = channel.tryLock();
            if (lock != null) {
                Files.deleteIfExists(file);
            }
        } catch (OverlappingFileLockException inUseHere) {
            // A batch of this process holds it.
        } catch (IOException ignored) {
            // Gone already, or not ours to delete.
        }
    }
}
