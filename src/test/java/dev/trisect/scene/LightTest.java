package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Quaternion;
import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.Shading;
import dev.trisect.texture.ProceduralTextures;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Lights as scene content: what a frame's snapshot holds of them, moved by their groups. */
class LightTest {
    private static final double EPS = 1e-12;

    private static void near(Vec3 expected, Vec3 actual) {
        assertEquals(expected.x(), actual.x(), EPS);
        assertEquals(expected.y(), actual.y(), EPS);
        assertEquals(expected.z(), actual.z(), EPS);
    }

    @Test
    void aGroupMovesAPointLightAndTurnsADirectionalOne() {
        Scene scene = new Scene();
        Group g = new Group("rig");
        g.setTransform(Transform.translation(1, 2, 3).withRotation(Quaternion.ofY(90)));
        Light point = Light.point(new Vec3(1, 0, 0), Colour.WHITE, 1, 0.2, 0.05);
        Light sun = Light.directional(new Vec3(0, 0, 2), new Colour(1, 0.5, 0));
        g.add(point, sun);
        scene.add(g, Light.ambient(Colour.grey(0.2)));
        List<Scene.PlacedLight> lights = scene.capture().lights();
        assertEquals(3, lights.size());
        // 90° about y takes +x to -z and +z to +x.
        near(new Vec3(1, 2, 2), lights.get(0).vector());
        assertEquals(0.2, lights.get(0).kl(), EPS);
        near(new Vec3(1, 0, 0), lights.get(1).vector());
        assertEquals(new Colour(1, 0.5, 0), lights.get(1).colour());
        assertEquals(Light.Kind.AMBIENT, lights.get(2).kind());
        assertTrue(scene.capture().objects().isEmpty());
    }

    @Test
    void hiddenLightsAreOffAndEightShineAtOnce() {
        Scene scene = new Scene();
        for (int i = 0; i < 8; i++) {
            scene.add(Light.point(new Vec3(i, 1, 0), Colour.grey(0.1)));
        }
        Light off = Light.directional(Vec3.UP, Colour.WHITE);
        off.setVisible(false);
        scene.add(off);
        assertEquals(8, scene.capture().lights().size());
        assertEquals(9, scene.children().size());
        assertEquals(0, scene.objects().size());
    }

    @Test
    void changesAreSeenByTheNextSnapshot() {
        Scene scene = new Scene();
        Light lamp = Light.point(Vec3.ZERO, Colour.WHITE);
        scene.add(lamp);
        lamp.setVector(new Vec3(0, 3, 0));
        lamp.setColour(new Colour(0, 1, 0));
        lamp.setAttenuation(1, 0, 1);
        Scene.PlacedLight l = scene.capture().lights().get(0);
        near(new Vec3(0, 3, 0), l.vector());
        assertEquals(new Colour(0, 1, 0), l.colour());
        assertEquals(1, l.kq(), EPS);
        scene.setFog(Fog.exp(0.1, Colour.WHITE));
        assertEquals(0.1, scene.capture().fog().orElseThrow().density(), EPS);
        scene.setFog(null);
        assertTrue(scene.capture().fog().isEmpty());
    }

    @Test
    void badLightsAreRefusedWithAReason() {
        assertThrows(IllegalArgumentException.class, () -> Light.directional(Vec3.ZERO, Colour.WHITE));
        assertThrows(IllegalArgumentException.class, () -> Light.point(Vec3.ZERO, Colour.WHITE, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> new Colour(-1, 0, 0));
        assertThrows(IllegalStateException.class, () -> Light.ambient(Colour.WHITE).setAttenuation(1, 0, 0));
        assertThrows(IllegalStateException.class, () -> Light.ambient(Colour.WHITE).setVector(Vec3.UP));
        assertThrows(NullPointerException.class, () -> Light.ambient(null));
    }

    @Test
    void materialsAreUnlitUnlessAskedAndKeepTheirColours() {
        Material m = Material.of(ProceduralTextures.crate(16));
        assertEquals(Shading.NONE, m.shading());
        assertEquals(Colour.WHITE, m.diffuse());
        Material lit = m.withShading(Shading.FLAT).withDiffuse(new Colour(1, 0, 0)).withAmbient(Colour.grey(0.5));
        assertEquals(Shading.FLAT, lit.shading());
        assertEquals(new Colour(1, 0, 0), lit.diffuse());
        assertEquals(Colour.grey(0.5), lit.ambient());
        assertEquals(m.texture(), lit.texture());
        assertEquals(Shading.NONE, m.shading());
        new SceneObject(Primitives.box(1, 1, 1), lit);
    }
}
