package dev.trisect.mesh;

import static dev.trisect.mesh.ObjMeshArrays.V;
import static dev.trisect.mesh.ObjMeshArrays.VN;
import static dev.trisect.mesh.ObjMeshArrays.VT;

import dev.trisect.base.InputException;
import java.util.Arrays;

/**
 * The {@code f} statements of an OBJ file: parsing each corner ({@code v}, {@code v/vt},
 * {@code v/vt/vn}, {@code v//vn}), resolving its 1-based indices (negative ones against what is
 * defined so far, positive ones beyond it remembered and checked against the file's totals at the
 * end), fan-triangulating the polygon as (v0, vi, vi+1) into {@link ObjMeshArrays}, and the messages
 * of all of it, each naming the OBJ file and line.
 */
final class ObjFaces {
    private static final String[] ONE = {"vertex", "texture coordinate", "normal"};
    private static final String[] MANY = {"vertices", "texture coordinates", "normals"};

    private final LineScanner lines;
    private final ObjMeshArrays mesh;
    private final ForwardIndices[] forward = {new ForwardIndices(), new ForwardIndices(), new ForwardIndices()};

    /** The corner being parsed: position, UV and normal index (0-based, UV and normal -1 for none). */
    private int cornerPosition;
    private int cornerUv;
    private int cornerNormal;

    ObjFaces(LineScanner lines, ObjMeshArrays mesh) {
        this.lines = lines;
        this.mesh = mesh;
    }

    /** Reads the {@code f} statement on the current line into triangles of the current material. */
    void face() {
        int corners = lines.count() - 1;
        if (corners < 3) {
            throw lines.error("face has " + corners + (corners == 1 ? " corner" : " corners")
                    + "; needs at least 3");
        }
        if (!mesh.hasMaterial()) {
            mesh.useMaterial("default");
        }
        int firstPosition = 0;
        int firstUv = 0;
        int firstNormal = 0;
        int previousPosition = 0;
        int previousUv = 0;
        int previousNormal = 0;
        for (int i = 1; i <= corners; i++) {
            corner(i);
            if (i == 1) {
                firstPosition = cornerPosition;
                firstUv = cornerUv;
                firstNormal = cornerNormal;
            } else if (i >= 3) {
                mesh.triangle(firstPosition, previousPosition, cornerPosition, firstUv, previousUv, cornerUv,
                        firstNormal, previousNormal, cornerNormal);
            }
            previousPosition = cornerPosition;
            previousUv = cornerUv;
            previousNormal = cornerNormal;
        }
    }

    /**
     * Reads the {@code l} statement on the current line (a polyline, corners {@code v} or {@code v/vt})
     * into segments between consecutive corners, of the current material.
     */
    void line() {
        int corners = lines.count() - 1;
        if (corners < 2) {
            throw lines.error("line has " + corners + (corners == 1 ? " point" : " points") + "; needs at least 2");
        }
        int previous = 0;
        for (int i = 1; i <= corners; i++) {
            corner(i);
            if (i >= 2) {
                mesh.segment(previous, cornerPosition);
            }
            previous = cornerPosition;
        }
    }

    /** Parses corner token {@code i} into {@link #cornerPosition}, {@link #cornerUv} and {@link #cornerNormal}. */
    private void corner(int i) {
        int start = lines.start(i);
        int end = lines.end(i);
        int slash = slash(start, end);
        cornerPosition = index(V, start, slash, i);
        cornerUv = -1;
        cornerNormal = -1;
        if (slash == end) {
            return;
        }
        int second = slash(slash + 1, end);
        if (second == end || second > slash + 1) {
            cornerUv = index(VT, slash + 1, second, i);
        }
        if (second < end) {
            if (slash(second + 1, end) < end) {
                throw malformedCorner(i);
            }
            cornerNormal = index(VN, second + 1, end, i);
        }
    }

    /** Offset of the first '/' in [from, to), or {@code to}. */
    private int slash(int from, int to) {
        int k = from;
        while (k < to && lines.byteAt(k) != '/') {
            k++;
        }
        return k;
    }

    private InputException malformedCorner(int i) {
        return lines.error("malformed " + (lines.is(0, "l") ? "line point " : "face corner ")
                + LineScanner.quote(lines.text(i)));
    }

    /**
     * Parses the index in [from, to) of corner token {@code token} and returns it 0-based. Positive
     * indices beyond what is defined so far are remembered and checked at the end of the file.
     */
    private int index(int kind, int from, int to, int token) {
        int k = from;
        boolean negative = k < to && lines.byteAt(k) == '-';
        if (k < to && (negative || lines.byteAt(k) == '+')) {
            k++;
        }
        if (k == to) {
            throw malformedCorner(token);
        }
        long value = 0;
        for (; k < to; k++) {
            int digit = lines.byteAt(k) - '0';
            if (digit < 0 || digit > 9) {
                throw malformedCorner(token);
            }
            // Saturates just above the int range: any such index is out of range anyway.
            if (value <= Integer.MAX_VALUE) {
                value = value * 10 + digit;
            }
        }
        String what = ONE[kind] + " index " + lines.slice(from, to);
        if (value == 0) {
            throw lines.error(what + " is not valid (OBJ indices start at 1)");
        }
        int defined = mesh.count(kind);
        if (negative) {
            if (value > defined) {
                throw lines.error(what + " reaches before the first " + ONE[kind] + " ("
                        + amount(defined, kind) + " defined so far)");
            }
            return defined - (int) value;
        }
        if (value > Integer.MAX_VALUE) {
            throw lines.error(what + " is out of range (too large)");
        }
        if (value > defined) {
            forward[kind].note((int) value, lines.lineNumber());
        }
        return (int) value - 1;
    }

    /**
     * Once the whole file is read: reports the first face (in file order) with a positive index beyond
     * the file's totals.
     */
    void checkForwardIndices() {
        int worstLine = Integer.MAX_VALUE;
        String message = null;
        for (int kind = V; kind <= VN; kind++) {
            int r = forward[kind].firstAbove(mesh.count(kind));
            if (r >= 0 && forward[kind].lines[r] < worstLine) {
                worstLine = forward[kind].lines[r];
                message = ONE[kind] + " index " + forward[kind].values[r] + " is out of range ("
                        + amount(mesh.count(kind), kind) + ")";
            }
        }
        if (message != null) {
            throw lines.errorAt(worstLine, message);
        }
    }

    private static String amount(int n, int kind) {
        return n + " " + (n == 1 ? ONE[kind] : MANY[kind]);
    }

    /**
     * Positive indices that were beyond the count defined at their line, kept only when larger than
     * every earlier one. The first face whose index exceeds the final count is then the first entry
     * that does, so this stays small and answers in one pass.
     */
    private static final class ForwardIndices {
        int[] values = new int[8];
        int[] lines = new int[8];
        int size;

        void note(int value, int line) {
            if (size > 0 && value <= values[size - 1]) {
                return;
            }
            if (size == values.length) {
                values = Arrays.copyOf(values, size * 2);
                lines = Arrays.copyOf(lines, size * 2);
            }
            values[size] = value;
            lines[size] = line;
            size++;
        }

        /** Index of the first entry above {@code count}, or -1. */
        int firstAbove(int count) {
            for (int r = 0; r < size; r++) {
                if (values[r] > count) {
                    return r;
                }
            }
            return -1;
        }
    }
}
