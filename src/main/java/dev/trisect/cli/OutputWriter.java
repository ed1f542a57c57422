package dev.trisect.cli;

import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.Charset;

/**
 * Standard output as the commands write it: a {@link PrintWriter} that, unlike {@link System#out},
 * keeps the first write failure's reason ("No space left on device", "Broken pipe") so that the
 * command can end with that reason and a non-zero status instead of exiting 0 with its output lost.
 * See docs/reading-limits.md, "Standard output".
 */
final class OutputWriter extends PrintWriter {
    /** Keeps the first failure of the stream under it, and passes the failure on. */
    private static final class Recording extends OutputStream {
        private final OutputStream target;
        private volatile IOException failure;

        Recording(OutputStream target) {
            this.target = target;
        }

        private IOException record(IOException e) {
            if (failure == null) {
                failure = e;
            }
            return e;
        }

        @Override
        public void write(int b) throws IOException {
            try {
                target.write(b);
            } catch (IOException e) {
                throw record(e);
            }
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            try {
                target.write(b, off, len);
            } catch (IOException e) {
                throw record(e);
            }
        }

        @Override
        public void flush() throws IOException {
            try {
                target.flush();
            } catch (IOException e) {
                throw record(e);
            }
        }
    }

    private final Recording stream;

    private OutputWriter(Recording stream, Writer writer) {
        super(writer, true);
        this.stream = stream;
    }

    /** The process's standard output, unbuffered below this writer's own encoder, in the platform charset. */
    static OutputWriter standardOutput() {
        return over(new FileOutputStream(FileDescriptor.out));
    }

    /** A writer over {@code target} that keeps the first failure (tests inject failing streams here). */
    static OutputWriter over(OutputStream target) {
        Recording r = new Recording(target);
        return new OutputWriter(r, new OutputStreamWriter(r, Charset.defaultCharset()));
    }

    /**
     * Why writing failed, in the operating system's words, or null when nothing has failed. Flushes
     * first, so that what was printed but still buffered is tried too.
     */
    String failure() {
        if (!checkError()) {
            return null;
        }
        return reason(stream.failure);
    }

    /**
     * The reason a writer failed, one line: {@code out}'s recorded failure when it is an
     * {@code OutputWriter}, otherwise a general one. Null when {@code out} has not failed.
     */
    static String failure(PrintWriter out) {
        if (out instanceof OutputWriter w) {
            return w.failure();
        }
        return out.checkError() ? "the stream reported an error" : null;
    }

    private static String reason(IOException e) {
        if (e == null) {
            return "the stream reported an error";
        }
        String m = e.getMessage();
        return m == null || m.isBlank() ? e.getClass().getSimpleName() : m.replace('\n', ' ').replace('\r', ' ');
    }
}
