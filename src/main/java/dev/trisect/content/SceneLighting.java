package dev.trisect.content;

import dev.trisect.render.Shading;
import dev.trisect.scene.Group;
import dev.trisect.scene.Light;
import dev.trisect.scene.Material;
import dev.trisect.scene.Node;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import java.util.ArrayList;
import java.util.List;

/**
 * How a whole scene is lit, as the demo's lighting key and the developer tools change it: one shading
 * for every material of every object. Any thread (the scene's own methods are).
 */
public final class SceneLighting {
    private SceneLighting() {
    }

    /**
     * Gives every material of every object of {@code scene} (in groups too) the shading {@code shading},
     * keeping its texture and colours; one change of the scene ({@link Scene#update}).
     */
    public static void setShading(Scene scene, Shading shading) {
        scene.update(() -> {
            for (SceneObject o : objects(scene)) {
                List<Material> lit = new ArrayList<>();
                for (Material m : o.materials()) {
                    lit.add(m.withShading(shading));
                }
                o.setMaterials(lit);
            }
        });
    }

    /**
     * The word the demo and the developer tools show for {@code shading}: "off" (the lighting is off),
     * "flat" or "smooth" — one word per idea wherever the user reads it.
     */
    public static String word(Shading shading) {
        return switch (shading) {
            case NONE -> "off";
            case FLAT -> "flat";
            case SMOOTH -> "smooth";
        };
    }

    /** The shading of the scene's first material, or {@link Shading#NONE} without one. */
    public static Shading shading(Scene scene) {
        for (SceneObject o : objects(scene)) {
            if (!o.materials().isEmpty()) {
                return o.materials().get(0).shading();
            }
        }
        return Shading.NONE;
    }

    /** Every light of {@code group} and its groups, hidden ones too, depth-first. */
    public static List<Light> lights(Group group) {
        return nodes(group, Light.class);
    }

    /** Every object of {@code group} and its groups, depth-first. */
    static List<SceneObject> objects(Group group) {
        return nodes(group, SceneObject.class);
    }

    /** Every node of {@code type} in {@code group} and its groups, depth-first. */
    private static <T extends Node> List<T> nodes(Group group, Class<T> type) {
        List<T> out = new ArrayList<>();
        for (Node n : group.children()) {
            if (type.isInstance(n)) {
                out.add(type.cast(n));
            } else if (n instanceof Group g) {
                out.addAll(nodes(g, type));
            }
        }
        return out;
    }
}
