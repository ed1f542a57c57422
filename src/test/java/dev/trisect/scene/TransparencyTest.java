package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Materials' alpha modes, opacity, and blended objects drawn farthest first whatever their scene order. */
class TransparencyTest {
    private static final int W = 64;
    private static final int H = 48;

    @Test
    void theAlphaModeFollowsTheTexturesAlphaAndOpacityBlends() {
        assertEquals(Material.AlphaMode.OPAQUE, Material.colour(0x123456).alphaMode());
        Texture cut = new Texture("cut", 2, 1, new int[] {0xFFFF0000, 0x00000000});
        assertEquals(Material.AlphaMode.ALPHA_TEST, Material.of(cut).alphaMode());
        Material half = Material.colour(0xFF0000).withOpacity(0.5);
        assertEquals(Material.AlphaMode.BLEND, half.alphaMode());
        assertEquals(0x80FF0000, half.texture().argb()[0]);
        Material same = Material.colour(1);
        assertSame(same, same.withOpacity(1));
        assertThrows(IllegalArgumentException.class, () -> same.withOpacity(1.5));
    }

    /** Blue at 50 % farther, red at 50 % nearer, over black: red over (blue over black), in either scene order. */
    @Test
    void blendedObjectsAreDrawnFarthestFirst() {
        for (boolean nearFirst : new boolean[] {true, false}) {
            Scene scene = new Scene();
            SceneObject near = new SceneObject(Primitives.box(2, 2, 0.01), Material.colour(0xFF0000).withOpacity(0.5),
                    Transform.translation(0, 0, 1));
            SceneObject far = new SceneObject(Primitives.box(2, 2, 0.01), Material.colour(0x0000FF).withOpacity(0.5),
                    Transform.translation(0, 0, 0));
            for (SceneObject o : nearFirst ? List.of(near, far) : List.of(far, near)) {
                scene.add(o);
            }
            for (RenderMode mode : RenderMode.values()) {
                for (TextureFilter filter : TextureFilter.values()) {
                    Framebuffer f = new Framebuffer(W, H);
                    try (SceneRenderer r = new SceneRenderer(1)) {
                        r.render(scene, Camera.looking(new Vec3(0, 0, 6), Vec3.ZERO),
                                RenderSettings.defaults().withMode(mode).withFilter(filter), f);
                    }
                    // Blue over black: 128/255 of 255 = 128; then red over that: 128 red, blue 127/255 of 128 = 64.
                    assertEquals(0xFF800040, f.colour()[H / 2 * W + W / 2], mode + ", " + filter
                            + ", near object first: " + nearFirst);
                }
            }
        }
    }
}
