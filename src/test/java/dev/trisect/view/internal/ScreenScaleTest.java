package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trisect.math.Vec3;
import dev.trisect.mesh.Lines;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Billboard;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Label;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.ScreenText;
import dev.trisect.texture.Texture;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * On a high-density screen a view's sizes in pixels are Swing's (logical) pixels: a pixel-sized
 * billboard, a line's width, a label's backdrop and the screen text's margin take the screen's scale
 * times as many frame pixels, as Swing's own text beside the view does; on a normal screen, and when
 * the render scale brings the frame down to one pixel per logical pixel, they keep their size in frame
 * pixels. Each is measured by its colour in the frame the render loop hands on.
 */
class ScreenScaleTest {
    private static final int W = 240;
    private static final int H = 160;

    /** What one frame shows, in frame pixels. */
    private record Sizes(int frameWidth, int billboard, int line, int backdrop, int margin) {
    }

    private static Sizes drawn(double screenScale, double renderScale) throws Exception {
        Scene scene = new Scene();
        // A red 10x10 billboard on the left, a green horizontal line of width 2 across the middle, a
        // label with a blue backdrop on the right, and screen text over a white backdrop top-left.
        SceneObject o = SceneObject.billboards(List.of(Billboard.pixels(Texture.solid("red", 0xFFFF0000),
                new Vec3(-1.5, 0.5, 0), 10, 10)));
        o.setLines(Lines.builder().segment(new Vec3(-1, -0.5, 0), new Vec3(1, -0.5, 0), 0x00FF00).build());
        o.setLineWidth(2);
        o.setLabels(List.of(Label.of(" ", new Vec3(1.5, 0.5, 0)).withBackground(0xFF0000FF)));
        scene.add(o);
        scene.setScreenText(List.of(ScreenText.of(ScreenText.Corner.TOP_LEFT, " ").withBackground(0xFFFFFFFF)
                .withMargin(6)));
        ViewState state = new ViewState(scene, Camera.looking(new Vec3(0, 0, 4), Vec3.ZERO));
        state.settings(ViewSettings.defaults().withRender(RenderSettings.defaults()).withRenderScale(renderScale));
        state.screenScale(screenScale);
        state.viewSize(W, H);
        TripleBuffer buffers = new TripleBuffer();
        FrameSlot slot = LoopRun.until(state, buffers, 1, "a frame", () -> {
            FrameSlot s = buffers.acquire(null);
            return s != null && s.serial >= 1 ? s : null;
        });
        int fw = slot.frame.width();
        int[] c = slot.frame.colour();
        int red = 0;
        int blueRows = 0;
        int greenRows = 0;
        int firstWhite = -1;
        for (int y = 0; y < slot.frame.height(); y++) {
            boolean blue = false;
            boolean green = false;
            for (int x = 0; x < fw; x++) {
                int rgb = c[y * fw + x] & 0xFFFFFF;
                red += rgb == 0xFF0000 ? 1 : 0;
                blue |= rgb == 0x0000FF;
                green |= rgb == 0x00FF00;
                if (rgb == 0xFFFFFF && firstWhite < 0) {
                    firstWhite = x;
                }
            }
            blueRows += blue ? 1 : 0;
            greenRows += green ? 1 : 0;
        }
        return new Sizes(fw, (int) Math.round(Math.sqrt(red)), greenRows, blueRows, firstWhite);
    }

    @Test
    void sizesInPixelsAreLogicalPixelsOnAHighDensityScreen() throws Exception {
        Sizes one = drawn(1, 1);
        assertEquals(W, one.frameWidth());
        assertEquals(10, one.billboard(), "a 10-pixel billboard on a normal screen");
        assertEquals(2, one.line(), "a 2-pixel line");
        // The screen text's backdrop starts 2 pixels before its margin of 6.
        assertEquals(4, one.margin(), "the screen text's margin");

        Sizes two = drawn(2, 1);
        assertEquals(20, two.billboard(), "at 200 % the billboard is 10 logical pixels: 20 frame pixels");
        assertEquals(4, two.line(), "the line 2 logical pixels wide");
        assertEquals(2 * one.backdrop(), two.backdrop(), "the label's backdrop twice as tall");
        assertEquals(8, two.margin(), "the margin and the backdrop's reach twice as wide");

        Sizes half = drawn(2, 0.5);
        assertEquals(W / 2, half.frameWidth());
        assertEquals(one, new Sizes(W, half.billboard(), half.line(), half.backdrop(), half.margin()),
                "at 200 % with render scale 0.5 a frame pixel is a logical pixel again");

        Sizes small = drawn(1, 0.5);
        assertEquals(10, small.billboard(), "below one frame pixel per logical pixel, sizes are not shrunk");
    }
}
