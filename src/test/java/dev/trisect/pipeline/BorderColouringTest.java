package dev.trisect.pipeline;

import dev.trisect.render.FrameStats;
import dev.trisect.render.RenderSettings;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Viewport;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.Framebuffer;
import dev.trisect.raster.OverlayColours;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The overlay's colourings on real frames: by split depth, by error bound, fallback, and fading. */
class BorderColouringTest {
    private static final int W = 480;
    private static final int H = 270;

    private record Frame(int[] colour, FrameStats stats) {
    }

    private static Frame render(SceneAsset scene, TessellationSettings t, BorderStyle style) {
        Framebuffer fb = new Framebuffer(W, H);
        RenderSettings r = RenderSettings.defaults().withTessellation(t).withBorders(true).withBorderStyle(style);
        try (FrameRenderer renderer = new FrameRenderer(2)) {
            FrameStats s = renderer.render(scene.mesh(), scene.textureArray(),
                    scene.camera().viewProjection(new Viewport(W, H)), r, fb);
            return new Frame(fb.colour().clone(), s);
        }
    }

    private static int count(int[] px, int argb) {
        int n = 0;
        for (int p : px) {
            n += p == argb ? 1 : 0;
        }
        return n;
    }

    @Test
    void theRampsRunFromCyanOrGreenToRedAndFallbackIsMagenta() {
        assertEquals(0xFF00FFFF, OverlayColours.depth(0, 16), "unsplit: cyan");
        assertEquals(0xFFFF0000, OverlayColours.depth(16, 16), "at the cap: red");
        assertEquals(0xFF00FF00, OverlayColours.bound(0), "no error: green");
        assertEquals(0xFFFFFF00, OverlayColours.bound(1), "at the threshold: yellow");
        assertEquals(OverlayColours.OVER_BOUND, OverlayColours.bound(1.001), "above it: red");
        assertEquals(0xFFFF00FF, OverlayColours.FALLBACK);
    }

    @Test
    void depthColouringShowsTheLevelsTheFrameReached() {
        TessellationSettings t = TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.5);
        Frame f = render(DemoScenes.floor(), t, new BorderStyle(BorderStyle.Colouring.DEPTH, false));
        int deepest = f.stats().deepestSplit();
        assertTrue(deepest >= 3, "the floor splits: " + deepest);
        Map<Integer, Integer> byLevel = new HashMap<>();
        for (int level = 0; level <= t.maxDepth(); level++) {
            int n = count(f.colour(), OverlayColours.depth(level, t.maxDepth()));
            if (n > 0) {
                byLevel.put(level, n);
            }
        }
        assertTrue(byLevel.size() >= 3, "several levels in their own colours: " + byLevel);
        assertTrue(byLevel.keySet().stream().allMatch(l -> l <= deepest), "no level beyond the deepest split: "
                + byLevel + " deepest " + deepest);
        assertTrue(byLevel.containsKey(deepest), "the deepest level shows: " + byLevel);
        assertEquals(0, count(f.colour(), OverlayColours.PIECE), "no plain yellow outlines");
    }

    @Test
    void boundColouringIsNeverRedUnderTheErrorPolicyAndIsUnderTheEdgePolicy() {
        SceneAsset floor = DemoScenes.floor();
        BorderStyle bound = new BorderStyle(BorderStyle.Colouring.BOUND, false);
        Frame error = render(floor, TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.5), bound);
        assertEquals(0, count(error.colour(), OverlayColours.OVER_BOUND), "every piece meets the bound");
        Frame edge = render(floor, TessellationSettings.defaults().withPolicy(SplitPolicy.EDGE).withMaxEdge(128)
                .withMaxError(0.5), bound);
        assertTrue(count(edge.colour(), OverlayColours.OVER_BOUND) > 100,
                "long edges near the camera exceed 0.5 px of error and show red");
    }

    @Test
    void cappedPiecesAreMagentaInEveryColouring() {
        TessellationSettings capped = TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.05)
                .withMaxDepth(2);
        for (BorderStyle.Colouring c : BorderStyle.Colouring.values()) {
            Frame f = render(DemoScenes.floor(), capped, new BorderStyle(c, false));
            assertTrue(f.stats().piecesFallback() > 0, "the cap leaves fallback pieces");
            assertTrue(count(f.colour(), OverlayColours.FALLBACK) > 100, c + ": fallback outlines are magenta");
        }
    }

    @Test
    void fadingThinsTheBandAtTheHorizonAndKeepsNearOutlinesWhole() {
        TessellationSettings t = TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.5);
        Frame plain = render(DemoScenes.floor(), t, new BorderStyle(BorderStyle.Colouring.YELLOW, false));
        Frame faded = render(DemoScenes.floor(), t, new BorderStyle(BorderStyle.Colouring.YELLOW, true));
        // The band just below the horizon: pieces a few pixels across.
        int horizonPlain = 0;
        int horizonFaded = 0;
        int nearPlain = 0;
        int nearFaded = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int i = y * W + x;
                boolean near = y > H * 3 / 4;
                int p = plain.colour()[i] == OverlayColours.PIECE ? 1 : 0;
                int q = faded.colour()[i] == OverlayColours.PIECE ? 1 : 0;
                if (near) {
                    nearPlain += p;
                    nearFaded += q;
                } else {
                    horizonPlain += p;
                    horizonFaded += q;
                }
            }
        }
        assertTrue(horizonFaded < horizonPlain / 2, "far pieces fade: " + horizonFaded + " of " + horizonPlain);
        assertTrue(nearFaded > nearPlain * 0.6, "most near outlines stay solid: " + nearFaded + " of " + nearPlain);
    }

    @Test
    void fadingLeavesTheFallbackOutlinesWhole() {
        // The demo counted "666 pieces filled per pixel" in its legend with Fade on while no magenta showed:
        // the slivers, thinnest of all, faded away. Their outlines are what the legend counts: never faded.
        SceneAsset demo = DemoScenes.demo();
        TessellationSettings t = TessellationSettings.defaults();
        Frame plain = render(demo, t, new BorderStyle(BorderStyle.Colouring.YELLOW, false));
        Frame faded = render(demo, t, new BorderStyle(BorderStyle.Colouring.YELLOW, true));
        assertTrue(plain.stats().piecesFallback() > 0, "the demo has fallback pieces");
        int solid = count(plain.colour(), OverlayColours.FALLBACK);
        assertTrue(solid > 0, "magenta outlines without fading");
        assertEquals(solid, count(faded.colour(), OverlayColours.FALLBACK), "the same magenta pixels with fading");
    }
}
