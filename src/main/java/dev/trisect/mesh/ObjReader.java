package dev.trisect.mesh;

import dev.trisect.base.InputException;
import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Reads Wavefront OBJ files (and their MTL material libraries) into an {@link ObjModel}.
 *
 * <p>What is read: {@code v x y z [w]} (object-space positions in the file's units; w and any further
 * numbers, such as vertex colours, are checked but not used), {@code vt u [v [w]]} (v defaults to 0),
 * {@code vn} (only counted, to check normal indices), {@code f} with corners {@code v}, {@code v/vt},
 * {@code v/vt/vn} or {@code v//vn}, {@code usemtl} and {@code mtllib}. Everything else ({@code o},
 * {@code g}, {@code s}, {@code l}, {@code p}, unknown statements, comments) is skipped.
 *
 * <p>Numbers follow {@link Float#parseFloat}, plus C's {@code nan}, {@code inf} and {@code infinity}
 * in any case; NaN and infinite coordinates are kept (the renderer skips such triangles). Indices
 * are 1-based; negative ones count back from the last element defined before the face; positive ones
 * may refer forward and are checked against the totals at the end of the file. Polygons are
 * fan-triangulated as (v0, vi, vi+1) and triangles are numbered in file order. A corner without
 * {@code vt} gets UV index -1. Triangles before any {@code usemtl} get the material {@code default}.
 *
 * <p>Every problem with the input is an {@link InputException} whose message is one line,
 * {@code file:line: what is wrong}.
 */
public final class ObjReader {
    private static final int V = 0;
    private static final int VT = 1;
    private static final int VN = 2;
    private static final String[] ONE = {"vertex", "texture coordinate", "normal"};
    private static final String[] MANY = {"vertices", "texture coordinates", "normals"};
    /** Largest array the JVM reliably allocates. */
    private static final long MAX_ARRAY = Integer.MAX_VALUE - 8;

    private final Path obj;
    private final boolean readMaterials;
    private final LineScanner lines;

    private float[] positions = new float[3 * 256];
    private float[] uvs = new float[2 * 256];
    private final int[] counts = new int[3];
    private int[] cornerPositions = new int[3 * 256];
    private int[] cornerUvs = new int[3 * 256];
    private int[] triangleMaterials = new int[256];
    private int triangleCount;

    private final List<String> materialNames = new ArrayList<>();
    private final Map<String, Integer> materialIndex = new HashMap<>();
    private int currentMaterial = -1;
    private final Map<String, Path> textures = new HashMap<>();
    /** Where each material's map_Kd was given, as {@code file:line}. */
    private final Map<String, String> textureSources = new HashMap<>();
    /** Each material's map_Kd {@code -s} and {@code -o}: {su, sv, ou, ov}; absent for none. */
    private final Map<String, float[]> uvTransforms = new HashMap<>();
    private final Set<Path> librariesRead = new HashSet<>();

    private final ForwardIndices[] forward = {new ForwardIndices(), new ForwardIndices(), new ForwardIndices()};

    /** The corner being parsed: position index and UV index (0-based, UV -1 for none). */
    private int cornerPosition;
    private int cornerUv;

    private ObjReader(Path obj, boolean readMaterials, LineScanner lines) {
        this.obj = obj;
        this.readMaterials = readMaterials;
        this.lines = lines;
    }

    /**
     * Reads an OBJ file.
     *
     * @param obj           the OBJ file; messages name it as given
     * @param readMaterials whether to read the {@code mtllib} files for their {@code map_Kd} textures;
     *                      when false, {@code mtllib} lines are ignored (a missing library is then no
     *                      error) but {@code usemtl} still names the materials
     * @return the mesh, in the file's object space and units, and one texture path (or null) per material
     * @throws InputException when a file cannot be read or is malformed
     */
    public static ObjModel read(Path obj, boolean readMaterials) {
        String label = obj.toString();
        LineScanner lines;
        try {
            lines = new LineScanner(obj, label);
        } catch (IOException e) {
            throw new InputException(label + ": cannot read: " + LineScanner.reason(e), e);
        }
        try (lines) {
            return new ObjReader(obj, readMaterials, lines).parse();
        }
    }

    private ObjModel parse() {
        while (lines.next()) {
            if (lines.count() == 0) {
                continue;
            }
            if (lines.is(0, "v")) {
                vertex();
            } else if (lines.is(0, "vt")) {
                textureCoordinate();
            } else if (lines.is(0, "vn")) {
                counts[VN]++;
            } else if (lines.is(0, "f")) {
                face();
            } else if (lines.is(0, "usemtl")) {
                String name = lines.rest(1);
                if (name.isEmpty()) {
                    throw lines.error("usemtl without a material name");
                }
                useMaterial(name);
            } else if (lines.is(0, "mtllib") && readMaterials) {
                if (lines.count() < 2) {
                    throw lines.error("mtllib without a file name");
                }
                for (int i = 1; i < lines.count(); i++) {
                    library(lines.name(i));
                }
            }
        }
        if (triangleCount == 0) {
            throw new InputException(lines.label() + ": no faces");
        }
        checkForwardIndices();
        applyUvTransforms();
        Mesh mesh = new Mesh(Arrays.copyOf(positions, 3 * counts[V]), Arrays.copyOf(uvs, 2 * counts[VT]),
                Arrays.copyOf(cornerPositions, 3 * triangleCount), Arrays.copyOf(cornerUvs, 3 * triangleCount),
                Arrays.copyOf(triangleMaterials, triangleCount), materialNames);
        List<Path> materialTextures = new ArrayList<>();
        List<String> sources = new ArrayList<>();
        for (String name : materialNames) {
            materialTextures.add(textures.get(name));
            sources.add(textureSources.get(name));
        }
        return new ObjModel(mesh, materialTextures, sources);
    }

    private void vertex() {
        int n = lines.count() - 1;
        if (n < 3) {
            throw lines.error("vertex has " + n + (n == 1 ? " coordinate" : " coordinates") + "; needs x y z");
        }
        positions = room(positions, 3L * counts[V] + 3);
        int at = 3 * counts[V];
        positions[at] = number(1, "vertex");
        positions[at + 1] = number(2, "vertex");
        positions[at + 2] = number(3, "vertex");
        checkNumbers(4, "vertex");
        counts[V]++;
    }

    private void textureCoordinate() {
        int n = lines.count() - 1;
        if (n < 1) {
            throw lines.error("texture coordinate without u");
        }
        uvs = room(uvs, 2L * counts[VT] + 2);
        int at = 2 * counts[VT];
        uvs[at] = number(1, "texture coordinate");
        uvs[at + 1] = n >= 2 ? number(2, "texture coordinate") : 0f;
        checkNumbers(3, "texture coordinate");
        counts[VT]++;
    }

    /** Checks that tokens from {@code first} on are numbers: they are not used, but garbage is an error. */
    private void checkNumbers(int first, String where) {
        for (int i = first; i < lines.count(); i++) {
            number(i, where);
        }
    }

    private float number(int i, String where) {
        String text = lines.text(i);
        try {
            return Float.parseFloat(text);
        } catch (NumberFormatException e) {
            Float special = cSpecial(text);
            if (special == null) {
                throw lines.error("malformed number " + LineScanner.quote(text) + " in " + where);
            }
            return special;
        }
    }

    /** C's spellings of the special values, as strtof accepts them, or null. */
    private static Float cSpecial(String text) {
        boolean negative = text.startsWith("-");
        String word = negative || text.startsWith("+") ? text.substring(1) : text;
        if (word.equalsIgnoreCase("nan")) {
            return Float.NaN;
        }
        if (word.equalsIgnoreCase("inf") || word.equalsIgnoreCase("infinity")) {
            return negative ? Float.NEGATIVE_INFINITY : Float.POSITIVE_INFINITY;
        }
        return null;
    }

    private void face() {
        int corners = lines.count() - 1;
        if (corners < 3) {
            throw lines.error("face has " + corners + (corners == 1 ? " corner" : " corners")
                    + "; needs at least 3");
        }
        if (currentMaterial < 0) {
            useMaterial("default");
        }
        int firstPosition = 0;
        int firstUv = 0;
        int previousPosition = 0;
        int previousUv = 0;
        for (int i = 1; i <= corners; i++) {
            corner(i);
            if (i == 1) {
                firstPosition = cornerPosition;
                firstUv = cornerUv;
            } else if (i >= 3) {
                triangle(firstPosition, previousPosition, cornerPosition, firstUv, previousUv, cornerUv);
            }
            previousPosition = cornerPosition;
            previousUv = cornerUv;
        }
    }

    /** Parses corner token {@code i} into {@link #cornerPosition} and {@link #cornerUv}. */
    private void corner(int i) {
        int start = lines.start(i);
        int end = lines.end(i);
        int slash = slash(start, end);
        cornerPosition = index(V, start, slash, i);
        cornerUv = -1;
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
            index(VN, second + 1, end, i);
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
        return lines.error("malformed face corner " + LineScanner.quote(lines.text(i)));
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
        int defined = counts[kind];
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

    private void triangle(int p0, int p1, int p2, int t0, int t1, int t2) {
        triangleMaterials = room(triangleMaterials, triangleCount + 1L);
        cornerPositions = room(cornerPositions, 3L * triangleCount + 3);
        cornerUvs = room(cornerUvs, 3L * triangleCount + 3);
        int c = 3 * triangleCount;
        cornerPositions[c] = p0;
        cornerPositions[c + 1] = p1;
        cornerPositions[c + 2] = p2;
        cornerUvs[c] = t0;
        cornerUvs[c + 1] = t1;
        cornerUvs[c + 2] = t2;
        triangleMaterials[triangleCount++] = currentMaterial;
    }

    /** As {@link MeshBuilder#material}, but with a hash lookup so many materials stay linear. */
    private void useMaterial(String name) {
        currentMaterial = materialIndex.computeIfAbsent(name, n -> {
            materialNames.add(n);
            return materialNames.size() - 1;
        });
    }

    /** Reports the first face (in file order) with a positive index beyond the file's totals. */
    private void checkForwardIndices() {
        int worstLine = Integer.MAX_VALUE;
        String message = null;
        for (int kind = V; kind <= VN; kind++) {
            int r = forward[kind].firstAbove(counts[kind]);
            if (r >= 0 && forward[kind].lines[r] < worstLine) {
                worstLine = forward[kind].lines[r];
                message = ONE[kind] + " index " + forward[kind].values[r] + " is out of range ("
                        + amount(counts[kind], kind) + ")";
            }
        }
        if (message != null) {
            throw lines.errorAt(worstLine, message);
        }
    }

    private static String amount(int n, int kind) {
        return n + " " + (n == 1 ? ONE[kind] : MANY[kind]);
    }

    private void library(String name) {
        Path mtl;
        try {
            mtl = obj.resolveSibling(name);
        } catch (InvalidPathException e) {
            throw lines.error("invalid material library name " + LineScanner.quote(name));
        }
        if (!librariesRead.add(mtl.toAbsolutePath().normalize())) {
            return;
        }
        LineScanner mtlLines;
        try {
            mtlLines = new LineScanner(mtl, mtl.toString());
        } catch (IOException e) {
            throw new InputException(lines.label() + ":" + lines.lineNumber() + ": cannot read material library "
                    + LineScanner.quote(name) + ": " + LineScanner.reason(e), e);
        }
        try (mtlLines) {
            readLibrary(mtlLines, mtl);
        }
    }

    /**
     * Reads {@code newmtl} and {@code map_Kd} from an MTL file into {@link #textures} (material name to
     * absolute texture path, relative names resolved against the MTL's directory), with where each was
     * given and its texel-coordinate transform. A material defined again replaces the earlier definition.
     */
    private void readLibrary(LineScanner mtlLines, Path mtl) {
        String material = null;
        while (mtlLines.next()) {
            if (mtlLines.count() == 0) {
                continue;
            }
            if (mtlLines.is(0, "newmtl")) {
                material = mtlLines.rest(1);
                if (material.isEmpty()) {
                    throw mtlLines.error("newmtl without a material name");
                }
                textures.remove(material);
                textureSources.remove(material);
                uvTransforms.remove(material);
            } else if (mtlLines.is(0, "map_Kd")) {
                if (material == null) {
                    throw mtlLines.error("map_Kd before any newmtl");
                }
                mapKd(mtlLines, mtl, material);
            }
        }
    }

    /**
     * {@code map_Kd [-s u [v [w]]] [-o u [v [w]]] file name}: the options come first (MTL specification,
     * "Texture map statements"); the file name is the rest of the line, inner blanks kept. Texel
     * coordinates of the material become {@code (u * su + ou, v * sv + ov)}; w, for 3D textures, is
     * checked but not used. Any other option is refused rather than silently ignored.
     */
    private void mapKd(LineScanner mtlLines, Path mtl, String material) {
        float[] transform = {1, 1, 0, 0};
        boolean transformed = false;
        int i = 1;
        while (i < mtlLines.count() && mtlLines.byteAt(mtlLines.start(i)) == '-') {
            String option = mtlLines.text(i);
            int at;
            if (option.equals("-s")) {
                at = 0;
            } else if (option.equals("-o")) {
                at = 2;
            } else {
                throw mtlLines.error("map_Kd option " + LineScanner.quote(option) + " is not supported (only -s and "
                        + "-o are)");
            }
            i++;
            int numbers = 0;
            while (numbers < 3 && i < mtlLines.count()) {
                float value;
                try {
                    value = Float.parseFloat(mtlLines.text(i));
                } catch (NumberFormatException e) {
                    break;
                }
                if (!Float.isFinite(value)) {
                    throw mtlLines.error("map_Kd " + option + " needs finite numbers");
                }
                if (numbers < 2) {
                    transform[at + numbers] = value;
                }
                numbers++;
                i++;
            }
            if (numbers == 0) {
                throw mtlLines.error("map_Kd " + option + " needs 1 to 3 numbers");
            }
            transformed = true;
        }
        String file = mtlLines.rest(i);
        if (file.isEmpty()) {
            throw mtlLines.error("map_Kd without a file name");
        }
        try {
            textures.put(material, mtl.resolveSibling(file).toAbsolutePath().normalize());
        } catch (InvalidPathException e) {
            throw mtlLines.error("invalid file name " + LineScanner.quote(file));
        }
        textureSources.put(material, mtlLines.label() + ":" + mtlLines.lineNumber());
        if (transformed) {
            uvTransforms.put(material, transform);
        } else {
            uvTransforms.remove(material);
        }
    }

    /**
     * Gives the triangles of materials with a map_Kd {@code -s}/{@code -o} their own transformed copies
     * of the texel coordinates they use (a coordinate may be shared with other materials).
     */
    private void applyUvTransforms() {
        if (uvTransforms.isEmpty()) {
            return;
        }
        float[][] byMaterial = new float[materialNames.size()][];
        for (int m = 0; m < byMaterial.length; m++) {
            byMaterial[m] = uvTransforms.get(materialNames.get(m));
        }
        Map<Long, Integer> copies = new HashMap<>();
        for (int t = 0; t < triangleCount; t++) {
            int m = triangleMaterials[t];
            float[] x = byMaterial[m];
            if (x == null) {
                continue;
            }
            for (int c = 3 * t; c < 3 * t + 3; c++) {
                int source = cornerUvs[c];
                if (source < 0) {
                    continue;
                }
                cornerUvs[c] = copies.computeIfAbsent((long) source * byMaterial.length + m, key -> {
                    uvs = room(uvs, 2L * counts[VT] + 2);
                    int at = 2 * counts[VT];
                    uvs[at] = uvs[2 * source] * x[0] + x[2];
                    uvs[at + 1] = uvs[2 * source + 1] * x[1] + x[3];
                    return counts[VT]++;
                });
            }
        }
    }

    private float[] room(float[] a, long needed) {
        return needed <= a.length ? a : Arrays.copyOf(a, newLength(a.length, needed));
    }

    private int[] room(int[] a, long needed) {
        return needed <= a.length ? a : Arrays.copyOf(a, newLength(a.length, needed));
    }

    private int newLength(int length, long needed) {
        if (needed > MAX_ARRAY) {
            throw lines.error("too much data: the mesh does not fit in memory");
        }
        return (int) Math.min(MAX_ARRAY, Math.max(needed, 2L * length));
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
