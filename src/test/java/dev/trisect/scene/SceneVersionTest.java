package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Transform;
import dev.trisect.mesh.Primitives;
import java.util.List;
import org.junit.jupiter.api.Test;

/** {@link Scene#version()} grows with every change a frame would show, in that scene alone. */
class SceneVersionTest {
    private static SceneObject box() {
        return new SceneObject(Primitives.box(1, 1, 1), Material.colour(0x808080));
    }

    @Test
    void everyChangeAFrameWouldShowCountsAnywhereInTheTree() {
        Scene scene = new Scene();
        Group group = new Group("g");
        SceneObject box = box();
        long v = scene.version();
        scene.add(group);
        assertTrue(scene.version() > v, "a group added");
        v = scene.version();
        group.add(box);
        assertTrue(scene.version() > v, "an object added inside a group");
        v = scene.version();
        box.setTransform(Transform.translation(1, 0, 0));
        assertTrue(scene.version() > v, "an object moved inside a group");
        v = scene.version();
        group.setVisible(false);
        assertTrue(scene.version() > v, "a group hidden");
        v = scene.version();
        box.setMaterials(List.of(Material.colour(0xFF0000)));
        assertTrue(scene.version() > v, "other materials");
        v = scene.version();
        group.remove(box);
        assertTrue(scene.version() > v, "an object removed");
        v = scene.version();
        box.setTransform(Transform.translation(2, 0, 0));
        box.setName("renamed");
        scene.snapshot();
        assertEquals(v, scene.version(), "an object in no scene, a name, a snapshot: no change to the scene");
        group.clear();
        assertTrue(scene.version() > v, "a group cleared");
    }

    @Test
    void aNodeMovedToAnotherSceneChangesBoth() {
        Scene a = new Scene();
        Scene b = new Scene();
        SceneObject box = box();
        a.add(box);
        long va = a.version();
        long vb = b.version();
        b.add(box);
        assertTrue(a.version() > va, "the scene it left");
        assertTrue(b.version() > vb, "the scene it joined");
        va = a.version();
        box.setVisible(false);
        assertEquals(va, a.version(), "the scene it left no longer hears of it");
    }
}
