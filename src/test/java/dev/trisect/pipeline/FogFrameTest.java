package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.LineShapes;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.TessellationSettings;
import dev.trisect.render.SplitPolicy;
import org.junit.jupiter.api.Test;

/**
 * Fog is per pixel in every path: each pixel of a fogged frame is the unfogged frame's pixel blended
 * towards the fog colour by OpenGL's factor of that pixel's own depth, within 0.15 + 0.5 of a step of
 * 1/255 (the pass's bound, then rounding); the
 * background and the depth buffer stay as they were; and without fog nothing changes. Lines are
 * fogged likewise, each pixel by its own depth (OpenGL fogs every fragment, lines' too).
 */
class FogFrameTest {
    private static final int W = 320;
    private static final int H = 180;

    @Test
    void everyPathFogsEveryCoveredPixelByItsOwnDepth() {
        SceneAsset scene = DemoScenes.byName("demo").orElseThrow();
        Mat4 vp = scene.camera().viewProjection(new Viewport(W, H));
        Colour haze = new Colour(0.6, 0.7, 0.8);
        Fog[] fogs = {Fog.linear(3, 40, haze), Fog.exp(0.08, haze), Fog.exp2(0.05, haze)};
        RenderSettings base = RenderSettings.defaults().withBackground(0x102030);
        RenderSettings[] paths = {base.withMode(RenderMode.PERSPECTIVE), base.withMode(RenderMode.AFFINE),
            base.withMode(RenderMode.SPANS), base.withMode(RenderMode.TESSELLATED).withTessellation(
                TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.5))};
        try (FrameRenderer r = new FrameRenderer(2)) {
            Draws draws = new Draws();
            for (RenderSettings path : paths) {
                draws.clear();
                draws.add(scene.mesh(), scene.textureArray(), vp);
                Framebuffer clear = new Framebuffer(W, H);
                r.render(draws, path, clear);
                for (Fog fog : fogs) {
                    draws.clear();
                    draws.add(scene.mesh(), scene.textureArray(), vp);
                    draws.setFog(fog);
                    Framebuffer fogged = new Framebuffer(W, H);
                    r.render(draws, path, fogged);
                    int changed = checkFogged(clear, fogged, fog, haze, path.mode().toString());
                    assertTrue(changed > W * H / 4, fog + " changed only " + changed + " pixels");
                }
            }
        }
    }

    @Test
    void linesAreFoggedByTheirOwnDepthAsOpenGlFogsThem() {
        SceneAsset scene = DemoScenes.byName("demo").orElseThrow();
        Mat4 vp = scene.camera().viewProjection(new Viewport(W, H));
        // A grid a little above the floor, yellow, two pixels wide: drawn over the triangles in both frames.
        Mat4 lifted = vp.mul(Mat4.ofRows(1, 0, 0, 0, 0, 1, 0, 0.3, 0, 0, 1, 0, 0, 0, 0, 1));
        Colour haze = new Colour(0.6, 0.7, 0.8);
        RenderSettings path = RenderSettings.defaults().withBackground(0x102030).withMode(RenderMode.PERSPECTIVE);
        try (FrameRenderer r = new FrameRenderer(2)) {
            Draws draws = new Draws();
            Framebuffer clear = new Framebuffer(W, H);
            for (Fog fog : new Fog[] {null, Fog.linear(3, 40, haze), Fog.exp(0.08, haze)}) {
                draws.clear();
                draws.add(scene.mesh(), scene.textureArray(), vp);
                draws.addLines(LineShapes.grid(40, 20, 0xFFFF00), lifted, 2);
                draws.setFog(fog);
                Framebuffer frame = fog == null ? clear : new Framebuffer(W, H);
                r.render(draws, path, frame);
                if (fog == null) {
                    int yellow = 0;
                    for (int c : clear.colour()) {
                        yellow += (c & 0xFFFFFF) == 0xFFFF00 ? 1 : 0;
                    }
                    assertTrue(yellow > 500, "line pixels: " + yellow);
                } else {
                    checkFogged(clear, frame, fog, haze, "lines");
                }
            }
        }
    }

    /**
     * A frame of more bands than a thread fogs at once (720 rows: 45 bands of 16 against groups of 16)
     * goes through both ways the fill pass fogs: groups fogged inside the run and the bands left over
     * after it. Every band is fogged exactly once (a second pass would move each fogged pixel again,
     * none would leave a pixel as it was), and one thread and two give the same frame.
     */
    @Test
    void framesOfManyBandsAreFoggedOnceOnOneThreadAndOnTwo() {
        int w = 400;
        int h = 720;
        SceneAsset scene = DemoScenes.byName("demo").orElseThrow();
        Mat4 vp = scene.camera().viewProjection(new Viewport(w, h));
        Colour haze = new Colour(0.6, 0.7, 0.8);
        Fog fog = Fog.linear(3, 40, haze);
        RenderSettings path = RenderSettings.defaults().withBackground(0x102030).withMode(RenderMode.SPANS);
        Draws draws = new Draws();
        Framebuffer clear = new Framebuffer(w, h);
        try (FrameRenderer r = new FrameRenderer(1)) {
            draws.add(scene.mesh(), scene.textureArray(), vp);
            r.render(draws, path, clear);
        }
        Framebuffer[] fogged = new Framebuffer[2];
        for (int threads = 1; threads <= 2; threads++) {
            try (FrameRenderer r = new FrameRenderer(threads)) {
                draws.clear();
                draws.add(scene.mesh(), scene.textureArray(), vp);
                draws.setFog(fog);
                fogged[threads - 1] = new Framebuffer(w, h);
                r.render(draws, path, fogged[threads - 1]);
            }
            int changed = checkFogged(clear, fogged[threads - 1], fog, haze, threads + " threads", w * h);
            assertTrue(changed > w * h / 4, threads + " threads changed only " + changed + " pixels");
        }
        assertTrue(java.util.Arrays.equals(fogged[0].colour(), fogged[1].colour()), "one thread and two differ");
    }

    /**
     * Asserts that every pixel of {@code fogged} is {@code clear}'s blended towards the haze by the fog
     * factor of its own depth (depths unchanged, the background not fogged); returns how many changed.
     */
    private static int checkFogged(Framebuffer clear, Framebuffer fogged, Fog fog, Colour haze, String what) {
        return checkFogged(clear, fogged, fog, haze, what, W * H);
    }

    private static int checkFogged(Framebuffer clear, Framebuffer fogged, Fog fog, Colour haze, String what,
                                   int pixels) {
        int changed = 0;
        for (int i = 0; i < pixels; i++) {
            float q = clear.depth()[i];
            assertEquals(Float.floatToRawIntBits(q), Float.floatToRawIntBits(fogged.depth()[i]));
            int c = clear.colour()[i];
            int f = fogged.colour()[i];
            if (q == 0) {
                assertEquals(c, f, "the background is not fogged");
                continue;
            }
            double k = fog.factor(1.0 / q);
            double[] mix = {((c >> 16) & 0xFF) * k + 255 * haze.r() * (1 - k),
                ((c >> 8) & 0xFF) * k + 255 * haze.g() * (1 - k), (c & 0xFF) * k + 255 * haze.b() * (1 - k)};
            int[] got = {(f >> 16) & 0xFF, (f >> 8) & 0xFF, f & 0xFF};
            for (int ch = 0; ch < 3; ch++) {
                assertTrue(Math.abs(got[ch] - mix[ch]) <= 0.65, what + ", " + fog + ": pixel " + i
                        + " channel " + ch + " is " + got[ch] + ", exact " + mix[ch]);
            }
            changed += c != f ? 1 : 0;
        }
        return changed;
    }
}
