package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.SceneAsset;
import dev.trisect.content.SceneLoader;
import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Lines;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The line pass within a frame: clipping, threads, and its place after the fill. */
class LinePassTest {
    private static final int W = 200;
    private static final int H = 150;
    private final Camera camera = new Camera(new Vec3(0, 0, 0), new Vec3(0, 0, -1), new Vec3(0, 1, 0), 60, 0.1, 100);
    private final Mat4 vp = camera.viewProjection(new Viewport(W, H));

    private int[] render(Lines lines, int threads) {
        Draws draws = new Draws();
        draws.addLines(lines, vp, 1);
        Framebuffer fb = new Framebuffer(W, H);
        try (FrameRenderer r = new FrameRenderer(threads)) {
            r.render(draws, RenderSettings.defaults(), fb);
        }
        return fb.colour();
    }

    private static int lit(int[] color) {
        int n = 0;
        for (int c : color) {
            n += c == 0xFFFFFFFF ? 1 : 0;
        }
        return n;
    }

    @Test
    void aSegmentCrossingTheNearPlaneIsCutThereNotDropped() {
        Vec3 behind = new Vec3(0.05, 0.02, 1);
        Vec3 front = new Vec3(0.4, -0.3, -3);
        // Where it crosses the near plane, z = -0.1 in view space (the camera looks down -z from the origin).
        double t = (1 + 0.1) / (1 + 3);
        Vec3 onNear = behind.add(front.sub(behind).scale(t));
        int[] crossing = render(Lines.builder().segment(behind, front, 0xFFFFFF).build(), 1);
        int[] cut = render(Lines.builder().segment(onNear, front, 0xFFFFFF).build(), 1);
        assertTrue(lit(crossing) > 50, "drawn: " + lit(crossing));
        int differ = 0;
        for (int i = 0; i < W * H; i++) {
            differ += crossing[i] != cut[i] ? 1 : 0;
        }
        assertTrue(differ <= 1, differ + " pixels differ from the segment cut at the near plane by hand");
        int[] behindOnly = render(Lines.builder().segment(behind, new Vec3(0.5, 0.5, 2), 0xFFFFFF).build(), 1);
        assertEquals(0, lit(behindOnly), "a segment wholly behind the camera draws nothing");
    }

    @Test
    void theImageDoesNotDependOnTheThreadCount() throws Exception {
        SceneAsset scene = SceneLoader.load(Path.of(LinePassTest.class.getResource("/dev/trisect/lines/lines.obj")
                .toURI()), null, note -> { });
        Camera c = new Camera(new Vec3(-1, 1.6, 4.2), new Vec3(1.3, 0.4, 0), new Vec3(0, 1, 0), 60, 0.1, 100);
        int[][] images = new int[3][];
        for (int threads = 1; threads <= 3; threads++) {
            Framebuffer fb = new Framebuffer(W, H);
            try (FrameRenderer r = new FrameRenderer(threads)) {
                r.render(scene.draws(new Draws(), c.viewProjection(new Viewport(W, H)), 2), RenderSettings.defaults(), fb);
            }
            images[threads - 1] = fb.colour();
        }
        assertArrayEquals(images[0], images[1]);
        assertArrayEquals(images[0], images[2]);
    }
}
