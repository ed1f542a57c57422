package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/** A scene's fog reaches its frames, and leaves the background alone. */
class SceneFogTest {
    @Test
    void fogBlendsObjectsTowardsItsColourAndNotTheBackground() {
        Scene scene = new Scene();
        scene.add(new SceneObject(Primitives.box(1, 1, 1), Material.colour(0xFF0000), Transform.translation(0, 0, 0)));
        Camera camera = Camera.looking(new Vec3(0, 0, 5), Vec3.ZERO);
        BufferedImage clear = SceneRenderer.renderImage(scene, camera, 64, 48);
        assertTrue(scene.fog().isEmpty());
        // The box's front at z = 4.5 from the eye: exp(-0.2 · 4.5) = 0.4066 of red, the rest white.
        long version = scene.version();
        scene.setFog(Fog.exp(0.2, Colour.WHITE));
        assertTrue(scene.version() > version, "a view idling on a still scene redraws when the fog changes");
        BufferedImage fogged = SceneRenderer.renderImage(scene, camera, 64, 48);
        int centre = fogged.getRGB(32, 24) & 0xFFFFFF;
        double f = Math.exp(-0.2 * 4.5);
        assertEquals(255, centre >> 16);
        assertEquals(255 * (1 - f), (centre >> 8) & 0xFF, 1.2);
        assertEquals(clear.getRGB(0, 0), fogged.getRGB(0, 0), "the background is not fogged");
        assertNotEquals(clear.getRGB(32, 24), fogged.getRGB(32, 24));
        scene.setFog(null);
        assertEquals(clear.getRGB(32, 24), SceneRenderer.renderImage(scene, camera, 64, 48).getRGB(32, 24));
    }
}
