package dev.trisect.content;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Colour;
import dev.trisect.render.Shading;
import dev.trisect.scene.Group;
import dev.trisect.scene.Light;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import java.util.List;
import org.junit.jupiter.api.Test;

/** One shading for a whole scene, objects in groups too, keeping each material's texture and colours. */
class SceneLightingTest {
    @Test
    void everyMaterialOfEveryObjectTakesTheShading() {
        Material red = Material.colour(0xFF0000).withDiffuse(new Colour(0.5, 0.5, 0.5));
        SceneObject a = new SceneObject(Primitives.box(1, 1, 1), red);
        SceneObject b = new SceneObject(Primitives.sphere(1, 8, 6), Material.colour(0x00FF00));
        Light sun = Light.directional(new Vec3(0, 1, 0), Colour.WHITE);
        Scene scene = new Scene();
        scene.add(a, new Group().add(b, sun));
        assertEquals(Shading.NONE, SceneLighting.shading(scene));
        SceneLighting.setShading(scene, Shading.FLAT);
        assertEquals(Shading.FLAT, SceneLighting.shading(scene));
        assertEquals(Shading.FLAT, b.materials().get(0).shading(), "inside a group too");
        Material m = a.materials().get(0);
        assertEquals(red.texture(), m.texture());
        assertEquals(red.diffuse(), m.diffuse());
        assertEquals(List.of(sun), SceneLighting.lights(scene));
    }
}
