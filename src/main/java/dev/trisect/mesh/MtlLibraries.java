package dev.trisect.mesh;

import dev.trisect.base.InputException;
import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The MTL material libraries an OBJ file names with {@code mtllib}: finding each beside the OBJ file,
 * reading each once, and what their {@code newmtl}, {@code map_Kd}, {@code Kd} and {@code Ka} statements give each material —
 * its texture file (absolute, normalized, relative names resolved against the MTL's directory), where
 * that was given ({@code mtl-file:line}) and its texel-coordinate transform ({@code -s}, {@code -o}).
 * Its messages name the MTL file and line, or the OBJ line of the {@code mtllib} for a library that
 * cannot be found or read.
 */
final class MtlLibraries {
    private final Path obj;
    /** The OBJ file's lines, positioned at the {@code mtllib} being read. */
    private final LineScanner objLines;

    private final Map<String, Path> textures = new HashMap<>();
    /** Where each material's map_Kd was given, as {@code file:line}. */
    private final Map<String, String> textureSources = new HashMap<>();
    /** Each material's map_Kd {@code -s} and {@code -o}: {su, sv, ou, ov}; absent for none. */
    private final Map<String, float[]> uvTransforms = new HashMap<>();
    /** Each material's {@code Kd} as 0xRRGGBB; absent for none. */
    private final Map<String, Integer> diffuse = new HashMap<>();
    /** Each material's {@code Ka} as 0xRRGGBB; absent for none. */
    private final Map<String, Integer> ambient = new HashMap<>();
    /** Absolute and normalized, in the order the OBJ names them. */
    private final Set<Path> librariesRead = new LinkedHashSet<>();
    /** Every material a library read defines ({@code newmtl}), with or without statements. */
    private final Set<String> defined = new HashSet<>();

    MtlLibraries(Path obj, LineScanner objLines) {
        this.obj = obj;
        this.objLines = objLines;
    }

    /** The texture file of {@code material}, or null when no library read gives it one. */
    Path texture(String material) {
        return textures.get(material);
    }

    /** Where the texture of {@code material} was given, as {@code mtl-file:line}, or null. */
    String source(String material) {
        return textureSources.get(material);
    }

    /**
     * The diffuse colour ({@code Kd}) of {@code material} as 0xRRGGBB, each channel
     * {@code round(255 * clamp(k, 0, 1))}; white when no library read gives it one.
     */
    int diffuse(String material) {
        return diffuse.getOrDefault(material, 0xFFFFFF);
    }

    /** The ambient colour ({@code Ka}) of {@code material} as {@link #diffuse} gives Kd, or null for none. */
    Integer ambient(String material) {
        return ambient.get(material);
    }

    /** Whether a library read defines {@code material} by a {@code newmtl}. */
    boolean defines(String material) {
        return defined.contains(material);
    }

    /** Whether a library read gives {@code material} a {@code Kd}. */
    boolean hasDiffuse(String material) {
        return diffuse.containsKey(material);
    }

    /** The libraries read, absolute and normalized, in the order the OBJ named them. */
    List<Path> files() {
        return List.copyOf(librariesRead);
    }

    boolean hasUvTransforms() {
        return !uvTransforms.isEmpty();
    }

    /** The texel-coordinate transform {su, sv, ou, ov} of {@code material}, or null for none. */
    float[] uvTransform(String material) {
        return uvTransforms.get(material);
    }

    /** Reads the library {@code name} of the current OBJ line, unless it has been read already. */
    void read(String name) {
        Path mtl;
        try {
            mtl = obj.resolveSibling(name);
        } catch (InvalidPathException e) {
            throw objLines.error("invalid material library name " + LineScanner.quote(name));
        }
        if (!librariesRead.add(mtl.toAbsolutePath().normalize())) {
            return;
        }
        LineScanner mtlLines;
        try {
            mtlLines = new LineScanner(mtl, mtl.toString());
        } catch (IOException e) {
            throw new InputException(objLines.label() + ":" + objLines.lineNumber()
                    + ": cannot read material library " + LineScanner.quote(name) + ": " + LineScanner.reason(e), e);
        }
        try (mtlLines) {
            readLibrary(mtlLines, mtl);
        }
    }

    /**
     * Reads {@code newmtl} and {@code map_Kd} from an MTL file into {@link #textures}, with where each
     * was given and its texel-coordinate transform. A material defined again replaces the earlier
     * definition.
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
                defined.add(material);
                textures.remove(material);
                textureSources.remove(material);
                uvTransforms.remove(material);
                diffuse.remove(material);
                ambient.remove(material);
            } else if (mtlLines.is(0, "map_Kd")) {
                if (material == null) {
                    throw mtlLines.error("map_Kd before any newmtl");
                }
                mapKd(mtlLines, mtl, material);
            } else if (mtlLines.is(0, "Kd")) {
                if (material == null) {
                    throw mtlLines.error("Kd before any newmtl");
                }
                diffuse.put(material, colour(mtlLines, "Kd"));
            } else if (mtlLines.is(0, "Ka")) {
                if (material == null) {
                    throw mtlLines.error("Ka before any newmtl");
                }
                ambient.put(material, colour(mtlLines, "Ka"));
            }
        }
    }

    /**
     * {@code Kd r [g b]} or {@code Ka r [g b]} ({@code what}): the MTL specification's RGB form (g and b
     * default to r). The {@code spectral} and {@code xyz} forms are refused rather than misread.
     */
    private static int colour(LineScanner mtlLines, String what) {
        int n = mtlLines.count() - 1;
        if (n >= 1 && (mtlLines.is(1, "spectral") || mtlLines.is(1, "xyz"))) {
            throw mtlLines.error(what + " " + mtlLines.text(1) + " is not supported: give r g b (or one grey level)");
        }
        if (n != 1 && n != 3) {
            throw mtlLines.error(what + " needs r g b (or one grey level), got " + n + (n == 1 ? " value" : " values"));
        }
        int rgb = 0;
        for (int i = 1; i <= 3; i++) {
            String text = mtlLines.text(n == 1 ? 1 : i);
            // The OBJ's spellings (nan, inf...), so that a special value is named for what it is.
            Float k = ObjReader.parseNumber(text);
            if (k == null) {
                throw mtlLines.error(what + ": malformed number " + LineScanner.quote(text)
                        + " (only the r g b form is supported)");
            }
            if (!Float.isFinite(k)) {
                // Digits that came out infinite overflowed float (1e39): say so, or the message reads as false.
                boolean overflow = !Float.isNaN(k) && text.matches("[-+]?[0-9.].*");
                throw mtlLines.error(what + ": " + LineScanner.quote(text) + " is not a finite number"
                        + (overflow ? " (beyond float's 3.4e38)" : "") + ": a colour must be finite");
            }
            rgb = rgb << 8 | Math.round(255 * Math.max(0f, Math.min(1f, k)));
        }
        return rgb;
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
}
