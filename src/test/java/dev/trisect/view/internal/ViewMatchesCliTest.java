package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.cli.Cli;
import dev.trisect.content.AssetScenes;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.devtools.CliArgs;
import dev.trisect.raster.OverlayColours;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import java.awt.image.BufferedImage;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The view's frame is the command line's: the same scene, camera, size and settings give the same
 * pixels, borders and fallback marks included — with the borders off no outline at all, the fallback
 * pieces' magenta included (issue 18, defect 1: the demo outlined them even without B).
 */
class ViewMatchesCliTest {
    @TempDir
    Path dir;
    /** Renders made so far: each writes a file of its own. */
    private int renders;

    /** Runs the render loop until it has drawn a frame with {@code settings}; returns that frame. */
    private static FrameSlot viewFrame(ViewState state, ViewSettings settings) throws Exception {
        state.settings(settings);
        // Two frames of a still scene: ask for frames, as an animation would.
        state.demand.keepDrawing("test", true);
        TripleBuffer buffers = new TripleBuffer();
        RenderLoop loop = new RenderLoop(state, buffers, () -> { }, 2);
        Thread t = new Thread(loop, "test-render");
        t.start();
        FrameSlot f = null;
        try {
            // Bounded waiting, not timing: up to 1000 polls 10 ms apart.
            for (int poll = 0; poll < 1000 && (f == null || f.serial < 2); poll++) {
                f = buffers.acquire(f);
                Thread.sleep(10);
            }
        } finally {
            loop.stop();
            t.join(5000);
        }
        assertTrue(f != null && f.serial >= 2, "the loop drew frames");
        return f;
    }

    /** Pixels of the view's frame that differ from {@code render} of the same frame on the command line. */
    private int differingPixels(SceneAsset scene, FrameSlot f) throws Exception {
        Path out = dir.resolve("cli-" + renders++ + ".png");
        List<String> args = new ArrayList<>(CliArgs.render(scene, f.camera, f.drawnRender, f.width(), f.height()));
        args.add("--out");
        args.add(out.toString());
        StringWriter err = new StringWriter();
        assertEquals(0, Cli.run(new PrintWriter(new StringWriter(), true), new PrintWriter(err, true),
                args.toArray(String[]::new)), err.toString());
        BufferedImage cli = ImageIO.read(Files.newInputStream(out));
        assertEquals(f.width(), cli.getWidth());
        int[] view = f.frame.colour();
        int differ = 0;
        for (int y = 0; y < f.height(); y++) {
            for (int x = 0; x < f.width(); x++) {
                differ += (view[y * f.width() + x] & 0xFFFFFF) != (cli.getRGB(x, y) & 0xFFFFFF) ? 1 : 0;
            }
        }
        return differ;
    }

    private static int count(int[] argb, int colour) {
        int n = 0;
        for (int p : argb) {
            n += p == colour ? 1 : 0;
        }
        return n;
    }

    @Test
    void theDemoAtStartIsTheCommandLinesImageWithAndWithoutBorders() throws Exception {
        ViewState state = new ViewState(DemoScenes.demo());
        state.viewSize(640, 360);
        SceneAsset scene = AssetScenes.assetOf(state.scene()).orElseThrow();
        FrameSlot plain = viewFrame(state, ViewSettings.defaults());
        assertTrue(plain.stats.piecesFallback() > 0, "the demo at start has slivers filled per pixel");
        assertEquals(0, count(plain.frame.colour(), OverlayColours.FALLBACK), "no fallback marks without B");
        assertEquals(0, differingPixels(scene, plain));
        RenderSettings borders = ViewSettings.defaults().render().withBorders(true).withBorderStyle(BorderStyle.plain());
        FrameSlot outlined = viewFrame(state, ViewSettings.defaults().withRender(borders));
        assertTrue(count(outlined.frame.colour(), OverlayColours.FALLBACK) > 0, "with B the fallback marks show");
        assertEquals(0, differingPixels(scene, outlined));
        FrameSlot faded = viewFrame(state, ViewSettings.defaults().withRender(
                borders.withBorderStyle(new BorderStyle(BorderStyle.Colouring.BOUND, true))));
        assertEquals(0, differingPixels(scene, faded));
    }

    @Test
    void aCappedFramesFallbackMarksComeWithTheBordersAndMatchTheCommandLine() throws Exception {
        ViewState state = new ViewState(DemoScenes.floor());
        state.viewSize(320, 180);
        SceneAsset scene = AssetScenes.assetOf(state.scene()).orElseThrow();
        RenderSettings capped = ViewSettings.defaults().render().withTessellation(ViewSettings.defaults().render()
                .tessellation().withPolicy(SplitPolicy.ERROR).withMaxError(0.05).withMaxDepth(2));
        FrameSlot off = viewFrame(state, ViewSettings.defaults().withRender(capped));
        assertTrue(off.stats.capsReached() > 0 && off.stats.piecesFallback() > 0);
        assertEquals(0, count(off.frame.colour(), OverlayColours.FALLBACK), "no outline without B");
        assertEquals(0, differingPixels(scene, off));
        FrameSlot on = viewFrame(state, ViewSettings.defaults().withRender(capped.withBorders(true)));
        assertTrue(count(on.frame.colour(), OverlayColours.FALLBACK) > 100, "the capped pieces in magenta with B");
        assertEquals(0, differingPixels(scene, on));
    }
}
