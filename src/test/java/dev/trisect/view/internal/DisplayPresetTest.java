package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.TessellationSettings;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.SceneRenderer;
import dev.trisect.texture.ProceduralTextures;
import dev.trisect.texture.TextureFilter;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/**
 * One look unless told otherwise: a new view draws with {@link RenderSettings#display()}, and so does
 * {@link SceneRenderer#renderImage(Scene, Camera, int, int)}; the command line's
 * {@link RenderSettings#defaults()} stay OpenGL's.
 */
class DisplayPresetTest {

    @Test
    void aNewViewAndAHeadlessPictureShareTheDisplayPreset() {
        assertEquals(RenderSettings.display(), ViewSettings.defaults().render());
        RenderSettings display = RenderSettings.display();
        assertEquals(TextureFilter.TRILINEAR, display.filter());
        assertEquals(RenderSettings.SKY, display.background());
        assertEquals(RenderSettings.defaults().withFilter(TextureFilter.TRILINEAR).withBackground(RenderSettings.SKY)
                .withBorderStyle(display.borderStyle()), display, "otherwise the defaults");

        Scene scene = new Scene();
        scene.add(new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.crate(64)),
                Transform.translation(0, 0.5, 0)));
        Camera camera = Camera.looking(new Vec3(2, 1.5, 2.5), new Vec3(0, 0.5, 0));
        BufferedImage picture = SceneRenderer.renderImage(scene, camera, 120, 90);
        BufferedImage displayed = SceneRenderer.renderImage(scene, camera, display, 120, 90);
        assertArrayEquals(picture.getRGB(0, 0, 120, 90, null, 0, 120), displayed.getRGB(0, 0, 120, 90, null, 0, 120));
        assertEquals(RenderSettings.SKY, picture.getRGB(0, 0) & 0xFFFFFF, "the sky behind");
    }

    @Test
    void theCommandLinesDefaultsStayOpenGls() {
        RenderSettings d = RenderSettings.defaults();
        assertEquals(TextureFilter.NEAREST, d.filter());
        assertEquals(0, d.background());
        assertEquals(TessellationSettings.defaults(), d.tessellation());
        assertNotEquals(d, RenderSettings.display());
    }
}
