package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Framebuffer;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Pick;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.SceneRenderer;
import dev.trisect.texture.ProceduralTextures;
import java.util.Optional;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * A view's frames carry their triangle ids, whatever listens: picking the frame on screen reads them
 * and draws nothing, and answers as {@code SceneRenderer.pick} does on the same frame.
 */
class FrameIdsTest {
    @Test
    void aFrameOfAViewNobodyListensToIsPickedFromItsIdsAsTheRendererPicksIt() throws Exception {
        Scene scene = new Scene();
        scene.add(new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.crate(64)),
                Transform.translation(-0.8, 0, 0)));
        scene.add(new SceneObject(Primitives.sphere(0.6, 16, 8), Material.of(ProceduralTextures.uvGrid(64)),
                Transform.translation(0.9, 0, -0.5)));
        ViewState state = new ViewState(scene, Camera.looking(new Vec3(0.2, 0.8, 2.2), Vec3.ZERO));
        state.viewSize(240, 160);
        TripleBuffer buffers = new TripleBuffer();
        RenderLoop loop = new RenderLoop(state, buffers, () -> { }, 2);
        Thread t = new Thread(loop, "test-render");
        t.start();
        try {
            for (int poll = 0; poll < 1500 && state.progress().frames() < 1; poll++) {
                Thread.sleep(20);
            }
            FrameSlot shown = buffers.acquire(null);
            assertNotNull(shown, "a frame");
            assertNotNull(shown.frame.ids(), "a frame records its ids with nothing listening");
            assertNull(shown.frame.uv(), "and not the UV output (a quarter more time a frame)");
            Framebuffer fb = new Framebuffer(shown.width(), shown.height());
            Random random = new Random(29);
            int objects = 0;
            try (SceneRenderer r = new SceneRenderer(1)) {
                r.render(scene, shown.camera, shown.drawnRender, fb);
                for (int i = 0; i < 1000; i++) {
                    int x = random.nextInt(shown.width());
                    int y = random.nextInt(shown.height());
                    Optional<Pick> mine = Optional.ofNullable(FrameIds.pick(shown, x, y));
                    assertEquals(r.pick(x, y), mine, "pixel " + x + "," + y);
                    objects += mine.isPresent() ? 1 : 0;
                }
            }
            assertTrue(objects > 200, objects + " of the points on an object");
        } finally {
            loop.stop();
            t.join(5000);
        }
    }
}
