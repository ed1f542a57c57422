package dev.trisect.cli;

import dev.trisect.base.InputException;
import dev.trisect.base.internal.Counts;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * One run of bench's {@code --glref} program: a temporary folder for the scene it draws, the program
 * started with its output going to a file there, and the mean frame time it prints
 * ({@code ms_per_frame X}).
 *
 * <p>Nothing of it outlives the command, however the command ends: {@link #close} (and, should the
 * program be stopped by Ctrl-C or SIGTERM first, a shutdown hook) stops the program and its children and
 * deletes the folder. Before, an interrupted bench left the exported scene in the system's temporary
 * folder and the program running. The program's output goes to a file, not a pipe, so that the run
 * waits for the program itself, at most {@link #TIMEOUT_MINUTES}: reading a pipe to its end waited
 * forever for a program that hung.
 */
final class GlrefRun implements AutoCloseable {
    /** The longest a glref run may take. */
    static final long TIMEOUT_MINUTES = 10;
    /** The longest part of the program's output a message quotes. */
    private static final int QUOTED = 200;
    /** The most of the program's output read (its end): glref prints one line. */
    private static final int TAIL = 1 << 16;
    private static final Pattern MS_PER_FRAME = Pattern.compile("ms_per_frame\\s+(\\S+)");

    private final Path program;
    private final long timeoutMs;
    private final Path dir;
    private final Thread hook;
    /** Guarded by this: the running program, and whether the run is over (no program may start then). */
    private Process process;
    private boolean closed;

    /** Makes the temporary folder (see {@link #dir}) for a run of {@code program}. */
    GlrefRun(Path program) throws IOException {
        this(program, TimeUnit.MINUTES.toMillis(TIMEOUT_MINUTES));
    }

    /** As {@link #GlrefRun(Path)}, stopping the program after {@code timeoutMs} (tests shorten it). */
    GlrefRun(Path program, long timeoutMs) throws IOException {
        this.program = program;
        this.timeoutMs = timeoutMs;
        this.dir = Files.createTempDirectory("trisect-bench");
        this.hook = new Thread(this::stop, "trisect-glref-cleanup");
        Runtime.getRuntime().addShutdownHook(hook);
    }

    /** The temporary folder, for the files the program reads and writes; deleted with its files by {@link #close}. */
    Path dir() {
        return dir;
    }

    /** Writes the files the program reads into the run's folder and gives the program's arguments. */
    interface Inputs {
        List<String> write(Path dir) throws IOException;
    }

    /**
     * Writes the program's files with {@code inputs}, runs it with the arguments that gives and
     * {@code environment} added to this process's, and gives the mean frame time it printed.
     *
     * @return milliseconds per frame, positive and finite
     * @throws InputException (exit status 1) when it cannot start, fails, takes longer than
     *                        {@link #TIMEOUT_MINUTES} or prints no time: one line, with the end of its output
     */
    double meanMs(Inputs inputs, Map<String, String> environment) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(program.toString()));
        try {
            cmd.addAll(inputs.write(dir));
        } catch (IOException | RuntimeException e) {
            awaitHaltIfStopped(); // the shutdown hook deleted the folder under the writes
            throw e;
        }
        Path log = dir.resolve("glref-output.txt");
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new java.io.File("/dev/null")));
        pb.environment().putAll(environment);
        Process p;
        synchronized (this) {
            awaitHaltIfStopped();
            try {
                p = pb.start();
            } catch (IOException e) {
                throw new InputException(program + ": cannot run: " + e.getMessage(), e);
            }
            process = p;
        }
        try {
            if (!p.waitFor(timeoutMs, TimeUnit.MILLISECONDS)) {
                throw new InputException(program + ": did not finish in "
                        + Counts.of((timeoutMs + 999) / 1000, "second") + "; stopped it" + quoted(log));
            }
        } finally {
            destroy(p);
            synchronized (this) {
                process = null;
            }
        }
        // The hook ended the program (Ctrl-C): its exit status is no failure to report.
        awaitHaltIfStopped();
        if (p.exitValue() != 0) {
            throw new InputException(program + ": failed with exit status " + p.exitValue() + quoted(log));
        }
        Matcher m = MS_PER_FRAME.matcher(tail(log));
        if (!m.find()) {
            throw new InputException(program + ": printed no ms_per_frame" + quoted(log));
        }
        double ms;
        try {
            ms = Double.parseDouble(m.group(1));
        } catch (NumberFormatException e) {
            ms = Double.NaN;
        }
        if (!(ms > 0 && ms < Double.POSITIVE_INFINITY)) {
            throw new InputException(program + ": printed ms_per_frame " + InputException.quote(m.group(1), 40)
                    + ", not a positive number of milliseconds");
        }
        return ms;
    }

    /**
     * Once the shutdown hook has run (Ctrl-C, SIGTERM), waits for the end of the program rather than
     * report what the hook's cleaning did to the run as a failure of its own.
     */
    private synchronized void awaitHaltIfStopped() throws InterruptedException {
        while (closed) {
            wait();
        }
    }

    /** ": " and the last line the program printed (shortened), or " and printed nothing". */
    private static String quoted(Path log) {
        String output;
        try {
            output = tail(log).strip();
        } catch (IOException e) {
            return "";
        }
        if (output.isEmpty()) {
            return " and printed nothing";
        }
        String last = output.substring(output.lastIndexOf('\n') + 1).strip();
        return ": " + shorten(last);
    }

    /**
     * The end of the program's output, at most {@link #TAIL} bytes: a program that printed gigabytes is
     * no reason to run out of memory.
     */
    private static String tail(Path log) throws IOException {
        try (java.nio.channels.SeekableByteChannel channel = Files.newByteChannel(log)) {
            long size = channel.size();
            java.nio.ByteBuffer buffer = java.nio.ByteBuffer.allocate((int) Math.min(size, TAIL));
            channel.position(size - buffer.capacity());
            while (buffer.hasRemaining() && channel.read(buffer) >= 0) {
                // read on
            }
            return new String(buffer.array(), 0, buffer.position(), StandardCharsets.ISO_8859_1);
        }
    }

    private static String shorten(String text) {
        return text.length() <= QUOTED ? text : text.substring(0, QUOTED) + "...";
    }

    /** Stops the program, if running, and deletes the folder; the shutdown hook does the same. */
    @Override
    public void close() {
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException e) {
            // The program is being stopped: the hook does it.
            return;
        }
        stop();
    }

    private void stop() {
        Process p;
        synchronized (this) {
            closed = true;
            p = process;
        }
        if (p != null) {
            destroy(p);
        }
        // A file being written as the folder is emptied can make the folder's deletion fail once.
        for (int attempt = 0; attempt < 3 && Files.exists(dir); attempt++) {
            try (Stream<Path> files = Files.list(dir)) {
                for (Path f : files.toList()) {
                    Files.deleteIfExists(f);
                }
                Files.deleteIfExists(dir);
            } catch (IOException e) {
                // Tried again; a folder left behind is only a temporary folder.
            }
        }
    }

    /** Ends {@code p} and the processes it started (a script's children), politely first. */
    private static void destroy(Process p) {
        List<ProcessHandle> children = p.descendants().toList();
        p.destroy();
        children.forEach(ProcessHandle::destroy);
        try {
            if (!p.waitFor(2, TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        } catch (InterruptedException e) {
            p.destroyForcibly();
            Thread.currentThread().interrupt();
        }
        children.stream().filter(ProcessHandle::isAlive).forEach(ProcessHandle::destroyForcibly);
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "GlrefRun[%s in %s]", program, dir);
    }
}
