package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.render.Framebuffer;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Objects added, moved and removed from other threads while a renderer draws the scene: no
 * exception, no frame showing half of a change made in one {@link Scene#update}, no object lost.
 */
class SceneThreadsTest {
    private static final int RED = 0xFF0000;
    private static final int GREEN = 0x00FF00;

    /** Leftmost column holding {@code rgb}, or -1. */
    private static int left(Framebuffer f, int rgb) {
        for (int x = 0; x < f.width(); x++) {
            for (int y = 0; y < f.height(); y++) {
                if ((f.colour()[y * f.width() + x] & 0xFFFFFF) == rgb) {
                    return x;
                }
            }
        }
        return -1;
    }

    @Test
    @Timeout(60)
    void changesWhileRenderingAreNeverTornNorLost() throws Exception {
        Scene scene = new Scene();
        SceneObject top = new SceneObject(SceneRendererTest.square(), Material.colour(RED));
        SceneObject bottom = new SceneObject(SceneRendererTest.square(), Material.colour(GREEN));
        top.setTransform(SceneRendererTest.FACING.withTranslation(-3, 1.5, -5));
        bottom.setTransform(SceneRendererTest.FACING.withTranslation(-3, -1.5, -5));
        Group extras = new Group("extras");
        scene.add(top, bottom, extras);

        AtomicBoolean done = new AtomicBoolean();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        List<String> torn = new ArrayList<>();
        int[] frames = new int[1];
        Thread render = new Thread(() -> {
            Framebuffer f = new Framebuffer(64, 64);
            try (SceneRenderer r = new SceneRenderer(2)) {
                while (!done.get()) {
                    r.render(scene, SceneRendererTest.CAMERA, SceneRendererTest.PERSPECTIVE, f);
                    frames[0]++;
                    int a = left(f, RED);
                    int b = left(f, GREEN);
                    if (a != b) {
                        torn.add("frame " + frames[0] + ": red at " + a + ", green at " + b);
                    }
                }
            } catch (Throwable t) {
                failure.set(t);
            }
        }, "render");
        render.start();

        // Two writers: one moves the pair together; one adds and removes small objects far behind.
        Set<SceneObject> kept = new HashSet<>();
        Thread adder = new Thread(() -> {
            try {
                for (int i = 0; i < 400; i++) {
                    SceneObject o = new SceneObject(SceneRendererTest.square(), Material.colour(0x000080),
                            SceneRendererTest.FACING.withTranslation(0, 0, -90));
                    extras.add(o);
                    if (i % 3 == 0) {
                        extras.remove(o);
                    } else {
                        synchronized (kept) {
                            kept.add(o);
                        }
                    }
                }
            } catch (Throwable t) {
                failure.set(t);
            }
        }, "adder");
        adder.start();
        for (int step = 0; step < 2000; step++) {
            double x = -3 + (step % 60) * 0.1;
            scene.update(() -> {
                top.setTransform(top.transform().withTranslation(x, 1.5, -5));
                // Widen the gap between the two changes, so that a frame taken in it would be likely
                // (a fixed number of spins: no clock is read).
                for (int spin = 0; spin < 20_000; spin++) {
                    Thread.onSpinWait();
                }
                bottom.setTransform(bottom.transform().withTranslation(x, -1.5, -5));
            });
            if (step % 200 == 0) {
                Thread.sleep(1);
            }
        }
        adder.join();
        while (frames[0] < 20 && failure.get() == null) {
            Thread.sleep(5);
        }
        done.set(true);
        render.join();

        assertNull(failure.get(), () -> "a thread failed: " + failure.get());
        assertTrue(frames[0] >= 20, "frames drawn: " + frames[0]);
        assertEquals(List.of(), torn, "frames showing the pair apart");
        assertEquals(kept, new HashSet<>(scene.objects().subList(2, scene.objects().size())),
                "every object added and not removed is in the scene");
        assertEquals(2 + kept.size(), scene.snapshot().size());
    }
}
