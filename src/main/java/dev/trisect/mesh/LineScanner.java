package dev.trisect.mesh;

import dev.trisect.base.InputException;
import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;

/**
 * Streams the logical lines of a text file in the OBJ/MTL style and splits each into tokens.
 *
 * <p>Lines are split on bytes, so no content can cause an error there; a UTF-8 byte-order mark at the
 * start of the file is skipped. Tokens handed out as strings (names of files, materials, groups) are
 * decoded as UTF-8, the encoding of file names on the systems Trisect runs on; a token that is not
 * valid UTF-8 is refused with its line, its bytes shown as escapes. Lines end at {@code \n}, {@code \r\n} or a lone {@code \r}
 * (classic Mac OS). Every byte up to {@code 0x20} separates tokens. A line whose last non-blank byte is
 * a backslash continues on the next one. A token starting with {@code #} starts a comment that runs to
 * the end of its physical line: the OBJ specification (Appendix B1, "Comments") says comments are not
 * processed, so a backslash ending a comment is part of the comment and continues nothing.
 */
final class LineScanner implements Closeable {
    /** Longest logical line accepted, in bytes: a guard against runaway memory on garbage input. */
    static final int MAX_LINE = 1 << 24;

    private final String label;
    private final InputStream in;
    private final byte[] chunk = new byte[1 << 16];
    private int chunkPos;
    private int chunkLen;
    private boolean atEof;
    private boolean started;
    /** The previous physical line ended in {@code \r}: a {@code \n} right after it belongs to that end. */
    private boolean skipLineFeed;

    private byte[] line = new byte[256];
    private int lineLen;
    private int physicalLines;
    private int lineNumber;

    private int[] starts = new int[16];
    private int[] ends = new int[16];
    private int count;

    /**
     * Opens {@code file} for scanning.
     *
     * @param label the file's name as messages should show it
     * @throws IOException when the file cannot be opened; {@link #reason} describes it for users
     */
    LineScanner(Path file, String label) throws IOException {
        if (Files.isDirectory(file)) {
            throw new FileSystemException(file.toString(), null, "is a directory");
        }
        // A pipe or device could block forever or never end; only regular files are read.
        if (Files.exists(file) && !Files.isRegularFile(file)) {
            throw new FileSystemException(file.toString(), null, "is not a regular file");
        }
        this.in = Files.newInputStream(file);
        this.label = label;
    }

    /** A short, user-facing description of why a file could not be opened or read. */
    static String reason(IOException e) {
        if (e instanceof NoSuchFileException) {
            return "no such file";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof FileSystemException && ((FileSystemException) e).getReason() != null) {
            return ((FileSystemException) e).getReason();
        }
        return e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
    }

    /**
     * Advances to the next logical line and tokenizes it.
     *
     * @return false at the end of the file
     */
    boolean next() {
        count = 0;
        lineLen = 0;
        lineNumber = physicalLines + 1;
        while (true) {
            int before = lineLen;
            boolean ended = appendPhysicalLine();
            if (!ended && lineLen == 0) {
                return false;
            }
            physicalLines++;
            int end = lineLen;
            // Only this physical line is scanned back, so long runs of continued blank lines stay linear.
            while (end > before && (line[end - 1] & 0xff) <= ' ') {
                end--;
            }
            boolean continues = end > before && line[end - 1] == '\\' && !hasComment(before, end);
            if (continues) {
                line[end - 1] = ' ';
            }
            if (!continues) {
                break;
            }
        }
        tokenize();
        return true;
    }

    /** Whether bytes [from, to) of the line, which start a token, contain the start of a comment. */
    private boolean hasComment(int from, int to) {
        boolean tokenStart = true;
        for (int k = from; k < to; k++) {
            boolean blank = (line[k] & 0xff) <= ' ';
            if (tokenStart && line[k] == '#') {
                return true;
            }
            tokenStart = blank;
        }
        return false;
    }

    /** Appends bytes up to the next line end (dropped); false when the file ended first. */
    private boolean appendPhysicalLine() {
        while (true) {
            if (chunkPos == chunkLen && !fill()) {
                return false;
            }
            if (skipLineFeed) {
                skipLineFeed = false;
                if (chunk[chunkPos] == '\n') {
                    chunkPos++;
                    continue;
                }
            }
            int from = chunkPos;
            int i = from;
            while (i < chunkLen && chunk[i] != '\n' && chunk[i] != '\r') {
                i++;
            }
            append(from, i);
            chunkPos = i;
            if (i < chunkLen) {
                skipLineFeed = chunk[i] == '\r';
                chunkPos++;
                return true;
            }
        }
    }

    private boolean fill() {
        if (atEof) {
            return false;
        }
        try {
            // The first read fills the chunk, so a byte-order mark is seen whole.
            int n = started ? in.read(chunk) : in.readNBytes(chunk, 0, chunk.length);
            chunkPos = 0;
            if (!started) {
                started = true;
                if (n >= 3 && chunk[0] == (byte) 0xEF && chunk[1] == (byte) 0xBB && chunk[2] == (byte) 0xBF) {
                    chunkPos = 3;
                }
            }
            chunkLen = Math.max(n, 0);
            if (n <= 0) {
                atEof = true;
                return false;
            }
            return chunkPos < chunkLen || fill();
        } catch (IOException e) {
            throw new InputException(label + ": cannot read: " + reason(e), e);
        }
    }

    private void append(int from, int to) {
        int n = to - from;
        if (n == 0) {
            return;
        }
        if (lineLen + n > MAX_LINE) {
            throw error("line is longer than " + MAX_LINE + " characters");
        }
        if (lineLen + n > line.length) {
            byte[] bigger = new byte[Math.min(MAX_LINE, Math.max(line.length * 2, lineLen + n))];
            System.arraycopy(line, 0, bigger, 0, lineLen);
            line = bigger;
        }
        System.arraycopy(chunk, from, line, lineLen, n);
        lineLen += n;
    }

    private void tokenize() {
        int i = 0;
        while (true) {
            while (i < lineLen && (line[i] & 0xff) <= ' ') {
                i++;
            }
            if (i == lineLen || line[i] == '#') {
                return;
            }
            int start = i;
            while (i < lineLen && (line[i] & 0xff) > ' ') {
                i++;
            }
            if (count == starts.length) {
                starts = Arrays.copyOf(starts, count * 2);
                ends = Arrays.copyOf(ends, count * 2);
            }
            starts[count] = start;
            ends[count] = i;
            count++;
        }
    }

    /** Number of tokens on the current line (0 for blank and comment lines). */
    int count() {
        return count;
    }

    /**
     * Token {@code i} as a string, one character per byte (ISO-8859-1): for keywords, numbers and the
     * quotes of messages, which never fail on any byte. Names go through {@link #name}.
     */
    String text(int i) {
        return new String(line, starts[i], ends[i] - starts[i], StandardCharsets.ISO_8859_1);
    }

    /**
     * Token {@code i} as a name (of a file or material), decoded as UTF-8.
     *
     * @throws InputException when the token is not valid UTF-8
     */
    String name(int i) {
        return slice(starts[i], ends[i]);
    }

    /**
     * The bytes from offset {@code from} to {@code to} of the current line, decoded as UTF-8.
     *
     * @throws InputException when the bytes are not valid UTF-8 (malformed or truncated sequences)
     */
    String slice(int from, int to) {
        boolean ascii = true;
        for (int k = from; k < to && ascii; k++) {
            ascii = line[k] >= 0;
        }
        if (ascii) {
            return new String(line, from, to - from, StandardCharsets.ISO_8859_1);
        }
        try {
            return StandardCharsets.UTF_8.newDecoder()
                    .onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT)
                    .decode(ByteBuffer.wrap(line, from, to - from))
                    .toString();
        } catch (CharacterCodingException e) {
            throw error(escaped(from, to) + " is not valid UTF-8");
        }
    }

    /** Bytes [from, to) in single quotes, printable ASCII as is and every other byte as {@code \xHH}. */
    private String escaped(int from, int to) {
        StringBuilder text = new StringBuilder("'");
        int shown = Math.min(to, from + 40);
        for (int k = from; k < shown; k++) {
            int b = line[k] & 0xff;
            if (b >= 0x20 && b < 0x7f && b != '\'' && b != '\\') {
                text.append((char) b);
            } else {
                text.append(String.format("\\x%02X", b));
            }
        }
        return text.append(shown < to ? "...'" : "'").toString();
    }

    /** Whether token {@code i} is exactly {@code keyword} (ASCII). */
    boolean is(int i, String keyword) {
        int s = starts[i];
        int n = ends[i] - s;
        if (n != keyword.length()) {
            return false;
        }
        for (int k = 0; k < n; k++) {
            if (line[s + k] != keyword.charAt(k)) {
                return false;
            }
        }
        return true;
    }

    /**
     * The name from token {@code i} to the last token, inner blanks kept, decoded as UTF-8; empty when
     * there is none.
     *
     * @throws InputException when the text is not valid UTF-8
     */
    String rest(int i) {
        if (i >= count) {
            return "";
        }
        return slice(starts[i], ends[count - 1]);
    }

    /** First byte offset of token {@code i}, for {@link #byteAt}. */
    int start(int i) {
        return starts[i];
    }

    /** Offset just past token {@code i}. */
    int end(int i) {
        return ends[i];
    }

    /** The byte at offset {@code k} of the current line. */
    byte byteAt(int k) {
        return line[k];
    }

    /** The (first physical) line number of the current logical line, from 1. */
    int lineNumber() {
        return lineNumber;
    }

    /** The file's name as messages show it. */
    String label() {
        return label;
    }

    /** An error about the current line: {@code file:line: what}. */
    InputException error(String what) {
        return errorAt(lineNumber, what);
    }

    /** An error about line {@code lineNumber} of this file. */
    InputException errorAt(int lineNumber, String what) {
        return new InputException(label + ":" + lineNumber + ": " + what);
    }

    /** {@code text} quoted for a message: see {@link InputException#quote}; at most 40 characters shown. */
    static String quote(String text) {
        return InputException.quote(text, 40);
    }

    @Override
    public void close() {
        try {
            in.close();
        } catch (IOException e) {
            // Nothing was lost: the file was only read.
        }
    }
}
