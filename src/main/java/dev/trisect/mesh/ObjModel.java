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
 */
public record ObjModel(Mesh mesh, List<Path> materialTextures) {

    /** Checks that there is one texture entry per material and keeps an unmodifiable copy. */
    public ObjModel {
        Objects.requireNonNull(mesh, "mesh");
        // List.copyOf rejects nulls, which mean "no texture" here.
        materialTextures = Collections.unmodifiableList(new ArrayList<>(materialTextures));
        if (materialTextures.size() != mesh.materialCount()) {
            throw new IllegalArgumentException(materialTextures.size() + " material textures for "
                    + mesh.materialCount() + " materials");
        }
    }
}
