package dev.trisect.content;

import dev.trisect.math.Mat4;
import dev.trisect.mesh.Lines;
import dev.trisect.mesh.Mesh;
import dev.trisect.pipeline.Draws;
import dev.trisect.scene.Camera;
import dev.trisect.scene.internal.BlendOrder;
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
 * @param lines       line segments drawn after the triangles, world space ({@link Lines#EMPTY} for none)
 */
public record SceneAsset(String name, String description, Mesh mesh, List<Texture> textures, Camera camera,
                    java.nio.file.Path source, List<java.nio.file.Path> inputs, Lines lines) {

    /** A scene without lines. */
    public SceneAsset(String name, String description, Mesh mesh, List<Texture> textures, Camera camera,
                      java.nio.file.Path source, List<java.nio.file.Path> inputs) {
        this(name, description, mesh, textures, camera, source, inputs, Lines.EMPTY);
    }

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

    /**
     * Sets {@code draws} to this scene seen through {@code viewProjection}: its mesh (each material
     * written as its texture's alpha says, {@link BlendOrder#states(Texture[])}), then its lines (if any)
     * {@code lineWidth} pixels wide.
     *
     * @param draws          cleared and filled
     * @param viewProjection world space to clip space
     * @param lineWidth      pixels, at least 1
     * @return {@code draws}
     */
    public Draws draws(Draws draws, Mat4 viewProjection, int lineWidth) {
        draws.clear();
        Texture[] textures = textureArray();
        draws.add(mesh, textures, BlendOrder.states(textures), viewProjection);
        if (!lines.isEmpty()) {
            draws.addLines(lines, viewProjection, lineWidth);
        }
        return draws;
    }

    /**
     * This scene with {@code lines} in place of its own.
     *
     * @param lines the segments, world space
     * @return the scene with those lines
     */
    public SceneAsset withLines(Lines lines) {
        return new SceneAsset(name, description, mesh, textures, camera, source, inputs, lines);
    }

    /** The textures as the array the renderer takes, indexed by material. */
    public Texture[] textureArray() {
        return textures.toArray(new Texture[0]);
    }
}
