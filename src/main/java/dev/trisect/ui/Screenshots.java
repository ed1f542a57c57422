package dev.trisect.ui;

import dev.trisect.base.internal.ErrorLine;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.concurrent.ExecutionException;
import java.util.function.Consumer;
import javax.imageio.ImageIO;
import javax.swing.SwingWorker;

/**
 * Where Ctrl+S puts screenshots: the user's Pictures folder if there is one, else the home folder —
 * never the working directory, which under {@code mvn exec:java} is the repository — and how it saves
 * one.
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

    /**
     * Saves {@code image} (null: no frame yet) as a new PNG in {@link #folder()} on a background thread,
     * all or nothing, saying what happens through {@code status} on the event thread.
     */
    static void save(BufferedImage image, Consumer<String> status) {
        save(image, folder(), status);
    }

    /** As {@link #save(BufferedImage, Consumer)}, into {@code dir}. */
    static SwingWorker<Path, Void> save(BufferedImage image, Path dir, Consumer<String> status) {
        if (image == null) {
            status.accept("No frame to save yet.");
            return null;
        }
        Path target = newFile(dir, LocalDateTime.now());
        status.accept("Saving " + target + " \u2026");
        SwingWorker<Path, Void> worker = new SwingWorker<>() {
            @Override
            protected Path doInBackground() throws IOException {
                // All or nothing: a partial file never takes the final name.
                Path part = target.resolveSibling(target.getFileName() + ".part");
                try {
                    if (!ImageIO.write(image, "png", part.toFile())) {
                        throw new IOException("no PNG writer");
                    }
                    Files.move(part, target, StandardCopyOption.ATOMIC_MOVE);
                } finally {
                    Files.deleteIfExists(part);
                }
                return target;
            }

            @Override
            protected void done() {
                try {
                    status.accept("Saved screenshot to " + get());
                } catch (ExecutionException e) {
                    status.accept(ErrorLine.of("cannot save the screenshot: " + e.getCause().getMessage()));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        };
        worker.execute();
        return worker;
    }
}
