package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/** {@link Camera#looking(Vec3, Vec3, Vec3)}: a camera with a chosen up and the default lens. */
class CameraLookingTest {

    @Test
    void isTheSixArgumentCameraWithTheDefaultLens() {
        Vec3 eye = new Vec3(1, 2, 3);
        Vec3 target = new Vec3(-1, 0, 0.5);
        Vec3 up = new Vec3(0, 0, 1);
        assertEquals(new Camera(eye, target, up, Camera.DEFAULT_FOV, Camera.DEFAULT_NEAR, Camera.DEFAULT_FAR),
                Camera.looking(eye, target, up));
        assertEquals(Camera.looking(eye, target, Vec3.UP), Camera.looking(eye, target));
    }

    /** Looking straight down with -z at the top: +x is to the right and -z up in the picture. */
    @Test
    void aTopDownCameraNeedsNoSixArgumentConstructor() {
        Scene scene = new Scene();
        scene.add(new SceneObject(Primitives.box(1, 1, 1), Material.colour(0xFF0000), Transform.translation(4, 0, 0)));
        scene.add(new SceneObject(Primitives.box(1, 1, 1), Material.colour(0x00FF00), Transform.translation(0, 0, -4)));
        Camera topDown = Camera.looking(new Vec3(0, 20, 0), Vec3.ZERO, new Vec3(0, 0, -1));
        BufferedImage image = SceneRenderer.renderImage(scene, topDown,
                RenderSettings.defaults().withMode(RenderMode.PERSPECTIVE), 200, 200);
        // 60 degrees at 20 units: the half-height of the view at y = 0 is 20 tan 30 = 11.5 units, so 4 units
        // from the centre is about 35 pixels.
        assertEquals(0xFF0000, image.getRGB(135, 100) & 0xFFFFFF, "+x to the right of the centre");
        assertEquals(0x00FF00, image.getRGB(100, 65) & 0xFFFFFF, "-z above it");
        assertEquals(0, image.getRGB(65, 100) & 0xFFFFFF);
        assertEquals(0, image.getRGB(100, 135) & 0xFFFFFF);
    }

    @Test
    void anUpAlongTheViewIsRefusedByName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Camera.looking(new Vec3(0, 20, 0), Vec3.ZERO, Vec3.UP));
        assertTrue(e.getMessage().contains("parallel to the view direction"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Camera.looking(Vec3.ZERO, Vec3.UP, Vec3.ZERO));
    }
}
