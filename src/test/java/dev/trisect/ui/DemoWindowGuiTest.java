package dev.trisect.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.AssetScenes;
import dev.trisect.cli.Cli;
import dev.trisect.devtools.CliArgs;
import dev.trisect.devtools.CompareSection;
import dev.trisect.metrics.Comparison;
import dev.trisect.render.RenderMode;
import dev.trisect.texture.TextureFilter;
import dev.trisect.view.ViewAction;
import dev.trisect.view.internal.ViewKind;
import dev.trisect.view.internal.ViewSettings;
import dev.trisect.view.internal.ViewState;
import java.awt.Window;
import java.awt.event.KeyEvent;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.Action;
import javax.swing.JDialog;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;

/** The demo window's keys for paths, filter and overlay, its comparison numbers, resizing and the difference view (the tools and the rest: DemoToolsGuiTest). */
@Tag("gui")
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class DemoWindowGuiTest extends DemoWindowFixture {
    @Test
    @Order(1)
    void theWindowOpensWithTrisectInItsTitle() throws Exception {
        assertTrue(onEdt(() -> window.frame().getTitle()).startsWith("Trisect"));
        assertTrue(onEdt(() -> window.frame().isShowing()));
        int[] px = freshFrame();
        assertTrue(Arrays.stream(px).distinct().count() > 100, "the scene is drawn, not a blank frame");
    }

    @Test
    @Order(2)
    void f12ShowsTheDeveloperToolsAndTheViewKeepsTheKeyboard() throws Exception {
        press(KeyEvent.VK_F12);
        waitFor("the developer tools", () -> onEdt(() -> devToolsWindow() != null && devToolsWindow().isShowing()));
        assertTrue(onEdt(() -> window.frame().isFocused()), "the view keeps the keyboard");
        press(KeyEvent.VK_F12);
        waitFor("the developer tools to close", () -> onEdt(() -> !devToolsWindow().isShowing()));
        press(KeyEvent.VK_F12);
        waitFor("the developer tools again", () -> onEdt(() -> devToolsWindow().isShowing()));
    }

    @Test
    @Order(3)
    void bAddsTheYellowOverlayAndTakesItAway() throws Exception {
        int before = yellow(freshFrame());
        press(KeyEvent.VK_B);
        waitFor("borders on", () -> state().settings().render().borders());
        int with = yellow(freshFrame());
        press(KeyEvent.VK_B);
        waitFor("borders off", () -> !state().settings().render().borders());
        int after = yellow(freshFrame());
        assertEquals(0, before);
        assertTrue(with > 2000, "yellow piece outlines: " + with);
        assertEquals(0, after);
        assertTrue(onEdt(() -> !cmd(ViewAction.BORDERS).selected()), "the menu and the dev tools show it off");
    }

    @Test
    @Order(4)
    void oneToFourSwitchThePathAndChangeTheFrame() throws Exception {
        int[][] frames = new int[4][];
        int[] keys = {KeyEvent.VK_1, KeyEvent.VK_2, KeyEvent.VK_3, KeyEvent.VK_4};
        for (RenderMode m : RenderMode.values()) {
            press(keys[m.ordinal()]);
            waitFor(m.id(), () -> state().settings().render().mode() == m);
            frames[m.ordinal()] = freshFrame();
            assertTrue(onEdt(() -> c().commands().modes.get(m.ordinal()).selected()), "the Render menu follows");
        }
        assertFalse(Arrays.equals(frames[0], frames[1]), "affine differs from perspective");
        assertFalse(Arrays.equals(frames[1], frames[2]), "tessellated differs from affine");
        assertFalse(Arrays.equals(frames[0], frames[2]), "tessellated differs from perspective, slightly");
        long differ = 0;
        for (int i = 0; i < frames[0].length; i++) {
            differ += frames[0][i] != frames[2][i] ? 1 : 0;
        }
        long affineDiffer = 0;
        for (int i = 0; i < frames[0].length; i++) {
            affineDiffer += frames[0][i] != frames[1][i] ? 1 : 0;
        }
        assertTrue(differ < affineDiffer, "tessellated is closer to perspective than affine is");
        long spansDiffer = 0;
        for (int i = 0; i < frames[0].length; i++) {
            spansDiffer += frames[0][i] != frames[3][i] ? 1 : 0;
        }
        assertTrue(spansDiffer > 0 && spansDiffer < affineDiffer, "spans differ from perspective, less than affine: "
                + spansDiffer + " pixels against " + affineDiffer);
    }

    @Test
    @Order(4)
    void fStepsTheTextureFilterFromTrilinear() throws Exception {
        assertEquals(TextureFilter.TRILINEAR, state().settings().render().filter(), "the demo opens trilinear");
        TextureFilter[] order = {TextureFilter.NEAREST, TextureFilter.BILINEAR, TextureFilter.TRILINEAR};
        int[][] frames = new int[3][];
        for (int i = 0; i < 3; i++) {
            TextureFilter f = order[i];
            press(KeyEvent.VK_F);
            waitFor(f.id(), () -> state().settings().render().filter() == f);
            frames[i] = freshFrame();
            assertEquals("Texture filter: " + f.id(), onEdt(() -> cmd(ViewAction.TEXTURE_FILTER).getValue(Action.NAME)),
                    "the View menu entry names the filter");
        }
        assertFalse(Arrays.equals(frames[0], frames[1]), "bilinear differs from nearest");
        assertFalse(Arrays.equals(frames[1], frames[2]), "trilinear differs from bilinear");
    }


    @Test
    @Order(5)
    void comparisonNumbersAppearAndAgreeWithTheCommandLine() throws Exception {
        press(KeyEvent.VK_3);
        // The key reaches the event thread some time after the robot returns (longer under load): read
        // the settings only once it has, or they are the spans path's, whose numbers the tools replace.
        waitFor("the tessellated path", () -> state().settings().render().mode() == RenderMode.TESSELLATED);
        ViewSettings now = state().settings();
        waitFor("a measurement of the current settings", () -> {
            ViewState.Measurement m = state().measurement();
            return m != null && m.settings().equals(now);
        });
        ViewState.Measurement m = state().measurement();
        Comparison c = m.comparison();
        waitFor("the readouts", () -> onEdt(() -> String.format(Locale.ROOT, "%.3f px", c.maxDisplacement())
                .equals(tools().readout("Max displacement"))));
        String p99 = onEdt(() -> tools().readout("p99 displacement"));
        assertEquals(String.format(Locale.ROOT, "%.3f px", c.p99Displacement()), p99);
        assertEquals(String.format(Locale.ROOT, "%.3f px", c.meanDisplacement()),
                onEdt(() -> tools().readout("Mean displacement")));
        assertNotNull(onEdt(() -> tools().readout("PSNR")));
        List<String> args = CliArgs.compare(AssetScenes.assetOf(state().scene()).orElseThrow(), m);
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        assertEquals(0, Cli.run(new PrintWriter(out, true), new PrintWriter(err, true), args.toArray(String[]::new)),
                err.toString());
        String json = out.toString();
        assertEquals(c.maxDisplacement(), number(json, "max_displacement"), 0.0, "same frame, same numbers");
        assertEquals(c.p99Displacement(), number(json, "p99_displacement"), 0.0);
        assertEquals(c.meanDisplacement(), number(json, "mean_displacement"), 0.0);
        assertEquals(c.texelDifferShare(), number(json, "texel_differ_share"), 0.0);
        assertEquals(c.psnrDb(), number(json, "psnr_db"), 0.0);
    }

    @Test
    @Order(6)
    void resizingTinyAndHugeAndMinimizingNeverThrows() throws Exception {
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread.UncaughtExceptionHandler previous = Thread.getDefaultUncaughtExceptionHandler();
        Thread.setDefaultUncaughtExceptionHandler((t, e) -> failure.set(e));
        try {
            for (int[] size : new int[][] {{20, 20}, {1, 1}, {2600, 1800}, {700, 500}}) {
                SwingUtilities.invokeAndWait(() -> window.frame().setSize(size[0], size[1]));
                Thread.sleep(300);
            }
            SwingUtilities.invokeAndWait(() -> window.frame().setExtendedState(java.awt.Frame.ICONIFIED));
            Thread.sleep(300);
            SwingUtilities.invokeAndWait(() -> window.frame().setExtendedState(java.awt.Frame.NORMAL));
            long before = state().progress().frames();
            waitFor("frames after restoring", () -> state().progress().frames() > before + 3);
            SwingUtilities.invokeAndWait(() -> {
                JDialog d = devToolsWindow();
                if (d != null) {
                    d.dispatchEvent(new java.awt.event.WindowEvent(d, java.awt.event.WindowEvent.WINDOW_CLOSING));
                }
            });
            waitFor("frames after closing the tools", () -> state().progress().frames() > before + 6);
            assertFalse(onEdt(() -> cmd(ViewAction.DEV_TOOLS).selected()), "F12's state follows the closed window");
        } finally {
            Thread.setDefaultUncaughtExceptionHandler(previous);
        }
        assertEquals(null, failure.get());
    }

    @Test
    @Order(7)
    void f6ShowsTheDifferenceWithTheToolsAndClosingThemGoesBackToTheImage() throws Exception {
        press(KeyEvent.VK_F6);
        waitFor("the difference view", () -> state().settings().view() == ViewKind.DIFFERENCE);
        waitFor("the developer tools", () -> onEdt(() -> devToolsWindow() != null && devToolsWindow().isShowing()));
        freshFrame();
        assertEquals(ViewKind.DIFFERENCE, onEdt(() -> front().view));
        press(KeyEvent.VK_F12);
        waitFor("the tools to close", () -> onEdt(() -> !devToolsWindow().isShowing()));
        assertEquals(ViewKind.IMAGE, state().settings().view(), "no heat map left behind");
        freshFrame();
        assertEquals(ViewKind.IMAGE, onEdt(() -> front().view));
        assertTrue(onEdt(() -> c().commands().views.get(ViewKind.IMAGE.ordinal()).selected()), "the View menu follows");
        press(KeyEvent.VK_F7);
        waitFor("the split view", () -> state().settings().view() == ViewKind.SPLIT);
        press(KeyEvent.VK_F5);
        waitFor("the image", () -> state().settings().view() == ViewKind.IMAGE);
    }

    @Test
    @Order(8)
    void untickingTheMeasurementGreysTheNumbersAndStopsTheHeatMap() throws Exception {
        press(KeyEvent.VK_F6);
        waitFor("the difference view with the tools", () -> state().settings().view() == ViewKind.DIFFERENCE
                && onEdt(() -> devToolsWindow() != null && devToolsWindow().isShowing()));
        CompareSection compare = onEdt(() -> tools().section(CompareSection.class));
        waitFor("live numbers", () -> onEdt(() -> compare.live("PSNR")));
        SwingUtilities.invokeAndWait(() -> compare.measureBox().doClick());
        assertFalse(state().settings().compare());
        assertEquals(ViewKind.IMAGE, state().settings().view(), "the heat map stops with the measurement");
        waitFor("greyed numbers", () -> onEdt(() -> !compare.live("PSNR") && !compare.live("Max displacement")));
        assertTrue(onEdt(() -> tools().readout("PSNR")).matches("[0-9.]+ dB|identical"),
                "greyed, not hidden (docs/demo.md): " + onEdt(() -> tools().readout("PSNR")));
        assertTrue(onEdt(() -> tools().readout("Max displacement")).endsWith(" px"));
        SwingUtilities.invokeAndWait(() -> compare.measureBox().doClick());
        waitFor("live numbers again", () -> onEdt(() -> compare.live("PSNR")));
    }

}
