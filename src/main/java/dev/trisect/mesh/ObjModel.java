package dev.trisect.mesh;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Objects;

/**
 * A mesh read from a Wavefront OBJ file, with the diffuse texture file of each of its materials.
 *
 * @param mesh             the triangles; positions in the file's object space and units, UVs as written
 *                         ((0, 0) is the texture's bottom-left)
 * @param materialTextures one entry per material of {@code mesh.materialNames()}, same order: the
 *                         absolute, normalized path of its {@code map_Kd} file, or null where the
 *                         material has none (or was not read). The file's existence is not checked.
 *                         Unmodifiable; may contain nulls.
 * @param textureSources   one entry per material, same order: where its {@code map_Kd} was given, as
 *                         {@code mtl-file:line} for messages, or null where there is none. Unmodifiable.
 * @param materialLibraries the MTL files read for it ({@code mtllib}), absolute and normalized, in
 *                         the order the OBJ names them; empty when none was read. Unmodifiable.
 * @param lines            the {@code l} elements, in the mesh's object space, each segment coloured by
 *                         its material's {@code Kd} (white without one); {@link Lines#EMPTY} for none
 * @param materialColours  one entry per material, same order: its {@code Kd} as 0xRRGGBB (each channel
 *                         {@code round(255 * clamp(k, 0, 1))}), or null where the material has none.
 *                         Unmodifiable; may contain nulls.
 * @param materialAmbients one entry per material, same order: its {@code Ka} (the ambient colour: the
 *                         factor of the ambient light it reflects) as 0xRRGGBB in the same form, or
 *                         null where the material has none. Unmodifiable; may contain nulls.
 */
public record ObjModel(Mesh mesh, List<Path> materialTextures, List<String> textureSources,
                       List<Path> materialLibraries, Lines lines, List<Integer> materialColours,
                       List<Integer> materialAmbients) {

    /**
     * Checks that there is one entry per material in each list and keeps unmodifiable copies.
     *
     * @param mesh              the triangles
     * @param materialTextures  each material's texture file, or null
     * @param textureSources    where each material's texture was named, or null
     * @param materialLibraries the MTL files read
     * @param lines             the {@code l} elements
     * @param materialColours   each material's {@code Kd}, or null
     * @param materialAmbients  each material's {@code Ka}, or null
     * @throws IllegalArgumentException when a list's length is not the mesh's material count
     */
    public ObjModel {
        Objects.requireNonNull(mesh, "mesh");
        Objects.requireNonNull(lines, "lines");
        materialColours = Collections.unmodifiableList(new ArrayList<>(materialColours));
        materialAmbients = Collections.unmodifiableList(new ArrayList<>(materialAmbients));
        if (materialColours.size() != mesh.materialCount() || materialAmbients.size() != mesh.materialCount()) {
            throw new IllegalArgumentException(materialColours.size() + " material colours and "
                    + materialAmbients.size() + " ambient colours for " + mesh.materialCount() + " materials");
        }
        materialLibraries = List.copyOf(materialLibraries);
        // List.copyOf rejects nulls, which mean "no texture" here.
        materialTextures = Collections.unmodifiableList(new ArrayList<>(materialTextures));
        textureSources = Collections.unmodifiableList(new ArrayList<>(textureSources));
        if (materialTextures.size() != mesh.materialCount() || textureSources.size() != mesh.materialCount()) {
            throw new IllegalArgumentException(materialTextures.size() + " material textures and "
                    + textureSources.size() + " sources for " + mesh.materialCount() + " materials");
        }
    }

    /**
     * A model whose materials have no {@code Ka}.
     *
     * @param mesh              the triangles
     * @param materialTextures  each material's texture file, or null
     * @param textureSources    where each material's texture was named, or null
     * @param materialLibraries the MTL files read
     * @param lines             the {@code l} elements
     * @param materialColours   each material's {@code Kd}, or null
     */
    public ObjModel(Mesh mesh, List<Path> materialTextures, List<String> textureSources,
                    List<Path> materialLibraries, Lines lines, List<Integer> materialColours) {
        this(mesh, materialTextures, textureSources, materialLibraries, lines, materialColours,
                Collections.nCopies(mesh.materialCount(), null));
    }

    /**
     * A model without lines.
     *
     * @param mesh              the triangles
     * @param materialTextures  each material's texture file, or null
     * @param textureSources    where each material's texture was named, or null
     * @param materialLibraries the MTL files read
     */
    public ObjModel(Mesh mesh, List<Path> materialTextures, List<String> textureSources,
                    List<Path> materialLibraries) {
        this(mesh, materialTextures, textureSources, materialLibraries, Lines.EMPTY);
    }

    /**
     * A model whose materials have no {@code Kd}.
     *
     * @param mesh              the triangles
     * @param materialTextures  each material's texture file, or null
     * @param textureSources    where each material's texture was named, or null
     * @param materialLibraries the MTL files read
     * @param lines             the {@code l} elements
     */
    public ObjModel(Mesh mesh, List<Path> materialTextures, List<String> textureSources,
                    List<Path> materialLibraries, Lines lines) {
        this(mesh, materialTextures, textureSources, materialLibraries, lines,
                Collections.nCopies(mesh.materialCount(), null));
    }

    /**
     * A model read from no material library (the textures' sources given).
     *
     * @param mesh             the triangles
     * @param materialTextures each material's texture file, or null
     * @param textureSources   where each material's texture was named, or null
     */
    public ObjModel(Mesh mesh, List<Path> materialTextures, List<String> textureSources) {
        this(mesh, materialTextures, textureSources, List.of());
    }

    /**
     * A model whose textures have no recorded source.
     *
     * @param mesh             the triangles
     * @param materialTextures each material's texture file, or null
     */
    public ObjModel(Mesh mesh, List<Path> materialTextures) {
        this(mesh, materialTextures, Collections.nCopies(materialTextures.size(), null));
    }
}
