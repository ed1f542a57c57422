package dev.trisect.scene;

import dev.trisect.base.InputException;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.ObjModel;
import dev.trisect.render.Colour;
import dev.trisect.texture.ProceduralTextures;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureReader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

/**
 * The materials of an OBJ model as {@link SceneObject#load(ObjModel, String, Consumer, boolean)} gives
 * them: each material's {@code map_Kd} texture (read once per file), else its {@code Kd} colour, else the
 * built-in UV grid; its {@code Ka}, where given, is its ambient colour under light.
 */
final class ObjMaterials {
    private ObjMaterials() {
    }

    /** The materials of {@code model}, by material index; {@code name} is the file named in notes. */
    static List<Material> of(ObjModel model, String name, Consumer<String> notes, boolean placeholders) {
        Mesh mesh = model.mesh();
        List<Material> materials = new ArrayList<>();
        Map<Path, Material> loaded = new HashMap<>();
        Material grid = null;
        List<String> untextured = new ArrayList<>();
        // A material only lines use (OBJ l elements take its Kd) needs no texture: no note for it.
        boolean[] filled = new boolean[mesh.materialCount()];
        for (int m : mesh.triangleMaterials()) {
            filled[m] = true;
        }
        for (int i = 0; i < mesh.materialCount(); i++) {
            Path map = model.materialTextures().get(i);
            Integer kd = model.materialColours().get(i);
            if (map == null && kd != null) {
                materials.add(Material.colour(kd));
            } else if (map == null) {
                if (grid == null) {
                    grid = Material.of(ProceduralTextures.uvGrid(512));
                }
                materials.add(grid);
                if (filled[i]) {
                    untextured.add(mesh.materialNames().get(i));
                }
            } else {
                String source = model.textureSources().get(i);
                Material textured = loaded.computeIfAbsent(map, file -> {
                    try {
                        return Material.of(readMapKd(file, source));
                    } catch (InputException e) {
                        if (!placeholders) {
                            throw e;
                        }
                        notes.accept(e.getMessage() + "; drawn with a magenta checkerboard instead");
                        return Material.of(ProceduralTextures.checker(64, 8, 0xFFFF00FF, 0xFF000000));
                    }
                });
                // With a map_Kd, Kd is the diffuse colour under light (the texture shows unchanged unlit).
                materials.add(kd == null ? textured : textured.withDiffuse(Colour.of(kd)));
            }
        }
        for (int i = 0; i < mesh.materialCount(); i++) {
            Integer ka = model.materialAmbients().get(i);
            if (ka != null) {
                materials.set(i, materials.get(i).withAmbient(Colour.of(ka)));
            }
        }
        if (!untextured.isEmpty()) {
            notes.accept(name + ": no texture for material" + (untextured.size() > 1 ? "s " : " ")
                    + String.join(", ", untextured) + " (no map_Kd); using the built-in UV grid");
        }
        return materials;
    }

    /** Reads a material's texture; a failure names the MTL file and line that gave it. */
    private static Texture readMapKd(Path file, String source) {
        try {
            return TextureReader.read(file);
        } catch (InputException e) {
            throw source == null ? e : new InputException(source + ": map_Kd: " + e.getMessage(), e);
        }
    }
}
