package dev.trisect.content;

import dev.trisect.math.Vec3;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.ObjModel;
import dev.trisect.mesh.ObjReader;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.SceneObject;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureReader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.function.Consumer;

/** Makes a {@link SceneAsset} from a user's Wavefront OBJ file. */
public final class SceneLoader {
    private SceneLoader() {
    }

    /**
     * Reads an OBJ scene.
     *
     * @param obj     the OBJ file
     * @param texture a texture for every material, or null to take each material's {@code map_Kd}
     *                (a material without one gets the built-in UV grid, and {@code notes} hears of it)
     * @param notes   receives one-line remarks for the user (never errors; those are thrown)
     * @throws dev.trisect.base.InputException for anything unreadable, with a one-line message
     */
    public static SceneAsset load(Path obj, Path texture, Consumer<String> notes) {
        return load(obj, texture, notes, false);
    }

    /**
     * As {@link #load(Path, Path, Consumer)}; with {@code placeholders}, a {@code map_Kd} texture that
     * cannot be read gets a placeholder and a note instead of rejecting the model (see
     * {@link SceneObject#load(Path, Consumer, boolean)}): for the demo, not for renders.
     */
    public static SceneAsset load(Path obj, Path texture, Consumer<String> notes, boolean placeholders) {
        Mesh mesh;
        dev.trisect.mesh.Lines lines;
        List<Texture> textures = new ArrayList<>();
        List<Path> inputs = new ArrayList<>(List.of(obj.toAbsolutePath()));
        if (texture != null) {
            ObjModel model = ObjReader.read(obj, false, notes);
            mesh = model.mesh();
            lines = model.lines();
            Texture t = TextureReader.read(texture);
            for (int i = 0; i < mesh.materialCount(); i++) {
                textures.add(t);
            }
            inputs.add(texture.toAbsolutePath());
        } else {
            ObjModel model = ObjReader.read(obj, true, notes);
            SceneObject object = SceneObject.load(model, String.valueOf(obj.getFileName()), notes, placeholders);
            mesh = object.mesh();
            lines = model.lines();
            for (Material m : object.materials()) {
                textures.add(m.texture());
            }
            inputs.addAll(model.materialLibraries());
            model.materialTextures().stream().filter(Objects::nonNull).distinct().forEach(inputs::add);
        }
        return new SceneAsset(String.valueOf(obj.getFileName()), "OBJ file " + obj, mesh, textures, frame(mesh),
                obj.toAbsolutePath(), inputs, lines);
    }

    /**
     * A camera that shows the whole mesh: from the front, a little above and to the right, at the
     * distance where the bounding sphere fits the default field of view.
     */
    static Camera frame(Mesh mesh) {
        float[] p = mesh.positions();
        double minX = Double.POSITIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double minZ = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        double maxZ = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < p.length; i += 3) {
            if (!(Float.isFinite(p[i]) && Float.isFinite(p[i + 1]) && Float.isFinite(p[i + 2]))) {
                continue;
            }
            minX = Math.min(minX, p[i]);
            maxX = Math.max(maxX, p[i]);
            minY = Math.min(minY, p[i + 1]);
            maxY = Math.max(maxY, p[i + 1]);
            minZ = Math.min(minZ, p[i + 2]);
            maxZ = Math.max(maxZ, p[i + 2]);
        }
        if (minX > maxX) {
            return Camera.looking(new Vec3(0, 0, 3), Vec3.ZERO);
        }
        Vec3 center = new Vec3((minX + maxX) / 2, (minY + maxY) / 2, (minZ + maxZ) / 2);
        double radius = Math.max(1e-6, new Vec3(maxX - minX, maxY - minY, maxZ - minZ).length() / 2);
        double distance = radius / Math.sin(Math.toRadians(Camera.DEFAULT_FOV) / 2) * 1.05;
        Vec3 eye = center.add(new Vec3(0.45, 0.35, 1).normalize().scale(distance));
        double near = Math.min(Camera.DEFAULT_NEAR, distance * 1e-3);
        double far = Math.max(Camera.DEFAULT_FAR, (distance + radius) * 2);
        return new Camera(eye, center, Vec3.UP, Camera.DEFAULT_FOV, near, far);
    }
}
