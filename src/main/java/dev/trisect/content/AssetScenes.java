package dev.trisect.content;

import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.texture.Texture;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.WeakHashMap;

/**
 * A {@link SceneAsset} as a {@link Scene} graph, for drawing it in a view: one object, in world space
 * (identity transform, so its frame is the asset's frame bit for bit), named after the asset. The
 * scene remembers the asset it was made from, so that the developer tools can write the command
 * line that draws the same frame ({@code --scene NAME} or {@code --obj FILE}).
 */
public final class AssetScenes {
    /** Scenes made here, and their assets; weak, so a scene no longer shown is forgotten. */
    private static final Map<Scene, SceneAsset> MADE = new WeakHashMap<>();

    private AssetScenes() {
    }

    /** A new scene holding {@code asset}'s mesh with its textures. */
    public static Scene scene(SceneAsset asset) {
        List<Material> materials = new ArrayList<>();
        for (Texture t : asset.textures()) {
            materials.add(Material.of(t));
        }
        SceneObject object = new SceneObject(asset.mesh(), materials);
        object.setName(asset.name());
        Scene scene = new Scene();
        scene.setName(asset.name());
        scene.add(object);
        synchronized (MADE) {
            MADE.put(scene, asset);
        }
        return scene;
    }

    /** The asset {@code scene} was made from by {@link #scene}, if it was. */
    public static Optional<SceneAsset> assetOf(Scene scene) {
        synchronized (MADE) {
            return Optional.ofNullable(MADE.get(scene));
        }
    }
}
