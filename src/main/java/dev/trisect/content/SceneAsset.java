package dev.trisect.content;

import dev.trisect.mesh.Mesh;
import dev.trisect.scene.Camera;
import dev.trisect.texture.Texture;
import java.util.List;

/**
 * Something to draw: a mesh in world space, the texture of each of its materials, and the camera it
 * is best seen from.
 *
 * @param name        short identifier (a built-in scene's name, or the OBJ file's name)
 * @param description one line for listings
 * @param mesh        the triangles, world space
 * @param textures    one texture per material, in the mesh's material order
 * @param camera      the scene's own camera, used when the user gives none
 * @param source      the OBJ file it was read from, or null for a built-in scene
 * @param inputs      every file it was read from (the OBJ, the MTL files it names and read, and its
 *                    textures), absolute: what an output must not replace. Empty for a built-in scene.
 */
public record SceneAsset(String name, String description, Mesh mesh, List<Texture> textures, Camera camera,
                    java.nio.file.Path source, List<java.nio.file.Path> inputs) {

    /** A built-in scene (no source file). */
    public SceneAsset(String name, String description, Mesh mesh, List<Texture> textures, Camera camera) {
        this(name, description, mesh, textures, camera, null);
    }

    /** A scene read from {@code source} alone (or built in, when it is null). */
    public SceneAsset(String name, String description, Mesh mesh, List<Texture> textures, Camera camera,
                      java.nio.file.Path source) {
        this(name, description, mesh, textures, camera, source, source == null ? List.of() : List.of(source));
    }

    public SceneAsset {
        textures = List.copyOf(textures);
        inputs = List.copyOf(inputs);
        if (textures.size() != mesh.materialCount()) {
            throw new IllegalArgumentException(name + ": " + mesh.materialCount() + " materials but "
                    + textures.size() + " textures");
        }
    }

    /** The textures as the array the renderer takes, indexed by material. */
    public Texture[] textureArray() {
        return textures.toArray(new Texture[0]);
    }
}
