package dev.trisect.mesh;

import dev.trisect.base.InputException;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.function.Consumer;

/**
 * Reads Wavefront OBJ files (and their MTL material libraries) into an {@link ObjModel}.
 *
 * <p>What is read: {@code v x y z [w]} (object-space positions in the file's units; w and any further
 * numbers, such as vertex colours, are checked but not used), {@code vt u [v [w]]} (v defaults to 0),
 * {@code vn x y z} (object-space normals, kept as written), {@code f} with corners {@code v},
 * {@code v/vt}, {@code v/vt/vn} or {@code v//vn}, {@code l} (polylines, corners {@code v} or
 * {@code v/vt}; each segment coloured by its material's {@code Kd}, white without one), {@code usemtl}
 * and {@code mtllib}. Everything else ({@code o}, {@code g}, {@code s}, {@code p}, unknown statements,
 * comments) is skipped.
 *
 * <p>Numbers follow {@link Float#parseFloat}, plus C's {@code nan}, {@code inf} and {@code infinity}
 * in any case; NaN and infinite coordinates are kept (the renderer skips such triangles). Indices
 * are 1-based; negative ones count back from the last element defined before the face; positive ones
 * may refer forward and are checked against the totals at the end of the file. Polygons are
 * fan-triangulated as (v0, vi, vi+1) and triangles are numbered in file order. A corner without
 * {@code vt} gets UV index -1, one without {@code vn} normal index -1 (it takes its triangle's face
 * normal, {@link Mesh#cornerNormal}). Triangles before any {@code usemtl} get the material {@code default}.
 *
 * <p>Every problem with the input is an {@link InputException} whose message is one line,
 * {@code file:line: what is wrong}. What is read but may not be what the file meant gets a note
 * instead ({@link #read(Path, boolean, Consumer)}), once per file: {@code vn} normals without a
 * direction (NaN, infinite — beyond float's range, such as {@code 1e39} — or zero length), which a
 * lit material's corners take as lit by the ambient light alone ({@link Mesh#cornerNormal} gives
 * (0, 0, 0)).
 */
public final class ObjReader {
    // The statements are read here; what they build and check is owned by the package-private
    // ObjMeshArrays (the growing mesh and its limits), ObjFaces (corners, indices, triangulation) and
    // MtlLibraries (mtllib, newmtl, map_Kd), so that each part stays one thing.
    private final boolean readMaterials;
    private final LineScanner lines;
    private final ObjMeshArrays mesh;
    private final ObjFaces faces;
    private final MtlLibraries libraries;
    /** The {@code vn} without a direction: how many, and the line of the first. */
    private int directionless;
    private int firstDirectionless;
    /** Each material a {@code usemtl} names, with the line of its first, in the file's order. */
    private final Map<String, Integer> used = new LinkedHashMap<>();

    private ObjReader(Path obj, boolean readMaterials, LineScanner lines) {
        this.readMaterials = readMaterials;
        this.lines = lines;
        this.mesh = new ObjMeshArrays(lines);
        this.faces = new ObjFaces(lines, mesh);
        this.libraries = new MtlLibraries(obj, lines);
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
        return read(obj, readMaterials, note -> { });
    }

    /**
     * Reads an OBJ file, as {@link #read(Path, boolean)}, telling {@code notes} what it read but the
     * file may not have meant (see the class comment): one line each, {@code file:line: what}, at most
     * one per kind and file.
     *
     * @param obj           the OBJ file; messages name it as given
     * @param readMaterials whether to read the {@code mtllib} files (see {@link #read(Path, boolean)})
     * @param notes         receives the notes, after the whole file is read (none when it is refused)
     * @return the mesh, in the file's object space and units, and one texture path (or null) per material
     * @throws InputException when a file cannot be read or is malformed
     * @throws NullPointerException when {@code notes} is null
     */
    public static ObjModel read(Path obj, boolean readMaterials, Consumer<String> notes) {
        Objects.requireNonNull(notes, "notes is null");
        String label = obj.toString();
        LineScanner lines;
        try {
            lines = new LineScanner(obj, label);
        } catch (IOException e) {
            throw new InputException(label + ": cannot read: " + LineScanner.reason(e), e);
        }
        try (lines) {
            ObjReader reader = new ObjReader(obj, readMaterials, lines);
            ObjModel model = reader.parse();
            reader.notes(notes);
            return model;
        }
    }

    private ObjModel parse() {
        while (lines.next()) {
            if (lines.count() == 0) {
                continue;
            }
            if (lines.is(0, "v")) {
                triple(ObjMeshArrays.V, "vertex");
            } else if (lines.is(0, "vt")) {
                textureCoordinate();
            } else if (lines.is(0, "vn")) {
                triple(ObjMeshArrays.VN, "normal");
            } else if (lines.is(0, "f")) {
                faces.face();
            } else if (lines.is(0, "l")) {
                faces.line();
            } else if (lines.is(0, "usemtl")) {
                String name = lines.rest(1);
                if (name.isEmpty()) {
                    throw lines.error("usemtl without a material name");
                }
                mesh.useMaterial(name);
                used.putIfAbsent(name, lines.lineNumber());
            } else if (lines.is(0, "mtllib") && readMaterials) {
                if (lines.count() < 2) {
                    throw lines.error("mtllib without a file name");
                }
                for (int i = 1; i < lines.count(); i++) {
                    libraries.read(lines.name(i));
                }
            }
        }
        if (mesh.triangleCount() == 0 && mesh.segmentCount() == 0) {
            throw new InputException(lines.label() + ": no faces or lines");
        }
        faces.checkForwardIndices();
        mesh.applyUvTransforms(libraries);
        Mesh built = mesh.toMesh();
        List<Path> materialTextures = new ArrayList<>();
        List<String> sources = new ArrayList<>();
        List<Integer> colours = new ArrayList<>();
        List<Integer> ambients = new ArrayList<>();
        for (String name : mesh.materialNames()) {
            materialTextures.add(libraries.texture(name));
            sources.add(libraries.source(name));
            colours.add(libraries.hasDiffuse(name) ? libraries.diffuse(name) : null);
            ambients.add(libraries.ambient(name));
        }
        return new ObjModel(built, materialTextures, sources, libraries.files(),
                mesh.toLines(built.positions(), libraries::diffuse), colours, ambients);
    }

    private void notes(Consumer<String> notes) {
        if (readMaterials) {
            // A name no library defines is most often a typo or a missing mtllib; it draws as the UV grid.
            List<String> undefined = used.keySet().stream().filter(m -> !libraries.defines(m)).toList();
            if (!undefined.isEmpty()) {
                String first = undefined.get(0);
                notes.accept(lines.label() + ":" + used.get(first) + ": usemtl " + first + ": no mtllib of the file "
                        + "defines it" + (undefined.size() > 1 ? ", nor " + String.join(", ", undefined.subList(1,
                        undefined.size())) : ""));
            }
        }
        if (directionless > 0) {
            notes.accept(lines.label() + ":" + firstDirectionless + ": normal (vn) without a direction (NaN, "
                    + "infinite or zero length)" + (directionless > 1 ? ", as are " + (directionless - 1) + " more"
                    : "") + ": lit corners that use " + (directionless > 1 ? "them" : "it")
                    + " take the ambient light alone");
        }
    }

    /** A {@code v} ({@link ObjMeshArrays#V}) or {@code vn} ({@link ObjMeshArrays#VN}): x y z, then any numbers. */
    private void triple(int kind, String what) {
        int n = lines.count() - 1;
        if (n < 3) {
            throw lines.error(what + " has " + n + (n == 1 ? " coordinate" : " coordinates") + "; needs x y z");
        }
        mesh.roomForTriple(kind);
        float x = number(1, what);
        float y = number(2, what);
        float z = number(3, what);
        checkNumbers(4, what);
        // As Mesh.cornerNormal sees it: a float square sum stays finite and non-zero in double.
        double squares = (double) x * x + (double) y * y + (double) z * z;
        if (kind == ObjMeshArrays.VN && !(squares > 0 && squares < Double.POSITIVE_INFINITY)
                && directionless++ == 0) {
            firstDirectionless = lines.lineNumber();
        }
        mesh.addTriple(kind, x, y, z);
    }

    private void textureCoordinate() {
        int n = lines.count() - 1;
        if (n < 1) {
            throw lines.error("texture coordinate without u");
        }
        mesh.roomForUv();
        float u = number(1, "texture coordinate");
        float v = n >= 2 ? number(2, "texture coordinate") : 0f;
        checkNumbers(3, "texture coordinate");
        mesh.addUv(u, v);
    }

    /** Checks that tokens from {@code first} on are numbers: they are not used, but garbage is an error. */
    private void checkNumbers(int first, String where) {
        for (int i = first; i < lines.count(); i++) {
            number(i, where);
        }
    }

    private float number(int i, String where) {
        String text = lines.text(i);
        Float value = parseNumber(text);
        if (value == null) {
            throw lines.error("malformed number " + LineScanner.quote(text) + " in " + where);
        }
        return value;
    }

    /**
     * An OBJ or MTL number: {@link Float#parseFloat}'s spellings and C's {@code nan}, {@code inf} and
     * {@code infinity} in any case (beyond float's range it is infinite); null when it is none.
     */
    static Float parseNumber(String text) {
        try {
            return Float.parseFloat(text);
        } catch (NumberFormatException e) {
            return cSpecial(text);
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
}
