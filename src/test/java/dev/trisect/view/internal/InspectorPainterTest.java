package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.pipeline.PieceInfo;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** Where the pixel inspector draws: never over its own crosshair (issue 18, defect 5). */
class InspectorPainterTest {
    private static BufferedImage painted(int w, int h, int x, int y) {
        FrameSlot f = new FrameSlot(w, h);
        Arrays.fill(f.frame.colour(), 0xFF808080);
        // A full readout: a triangle, its piece, both paths' texel coordinates, the displacement, the mip level.
        PieceInfo piece = new PieceInfo(8, 3, 2, false, new double[] {10, 10, 60, 10, 35, 40}, new double[9]);
        f.inspection = new PixelInspector.Inspection(x, y, 0xFF808080, 3, null, 2.5, 10.25, 3.5, 10.25, 3.5, 0.125,
                piece, 1.5, 1, 12, 4, null, null, null, 0xFF404040, new double[] {5, 5, 90, 5, 5, 90}, null, null);
        BufferedImage view = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = view.createGraphics();
        g.drawImage(f.image, 0, 0, null);
        InspectorPainter.paint(g, f, w, h, true);
        g.dispose();
        return view;
    }

    @Test
    void theCrosshairShowsWhereTheReadoutUsedToBe() {
        // The issue's case: at (1200,250) the readout, fixed top right, covered the crosshair.
        BufferedImage v = painted(1280, 720, 1200, 250);
        // The crosshair's centre: the pixel's centre (1200.5, 250.5), rounded.
        int cx = 1201;
        int cy = 251;
        for (int arm = 8; arm <= 20; arm += 4) {
            assertEquals(0xFFFFFF, v.getRGB(cx + arm, cy) & 0xFFFFFF, "right arm at +" + arm);
            assertEquals(0xFFFFFF, v.getRGB(cx - arm, cy) & 0xFFFFFF, "left arm at -" + arm);
            assertEquals(0xFFFFFF, v.getRGB(cx, cy - arm) & 0xFFFFFF, "upper arm at -" + arm);
            assertEquals(0xFFFFFF, v.getRGB(cx, cy + arm) & 0xFFFFFF, "lower arm at +" + arm);
        }
    }

    @Test
    void thePanelKeepsClearOfTheCrosshairAnywhereInAHdView() {
        int w = 380;
        int h = 340;
        for (int py = 0; py < 720; py += 7) {
            for (int px = 0; px < 1280; px += 7) {
                Rectangle r = InspectorPainter.place(w, h, px, py, 1280, 720);
                Rectangle cross = new Rectangle(px - InspectorPainter.REACH, py - InspectorPainter.REACH,
                        2 * InspectorPainter.REACH + 1, 2 * InspectorPainter.REACH + 1);
                assertFalse(r.intersects(cross), "panel " + r + " over the crosshair at " + px + "," + py);
                assertTrue(new Rectangle(0, 0, 1280, 720).contains(r), "inside the view: " + r);
            }
        }
        assertEquals(new Rectangle(1280 - w - InspectorPainter.MARGIN, InspectorPainter.MARGIN, w, h),
                InspectorPainter.place(w, h, 300, 600, 1280, 720), "top right while the pixel is elsewhere");
    }

    @Test
    void inAViewTooSmallForAnyCornerThePanelGoesToTheFarthest() {
        Rectangle r = InspectorPainter.place(300, 300, 40, 40, 320, 320);
        assertTrue(r.x > 0 && r.y > 0, "the bottom right, away from a pixel at the top left: " + r);
    }

    @Test
    void theInspectedPieceAndItsTriangleAreDrawnAndBothColoursNamed() {
        BufferedImage v = painted(1280, 720, 600, 400);
        assertEquals(0x00FFFF, v.getRGB(35, 10) & 0xFFFFFF, "the piece's top edge in cyan");
        assertEquals(0xFFFFFF, v.getRGB(7, 5) & 0xFFFFFF, "the input triangle's top edge, dashed white");
        FrameSlot f = new FrameSlot(8, 8);
        PieceInfo piece = new PieceInfo(8, 3, 2, false, new double[] {10, 10, 60, 10, 35, 40}, new double[9]);
        var in = new PixelInspector.Inspection(1, 2, 0xFF808080, 3, null, 2.5, 10.25, 3.5, 10.25, 3.5, 0.125, piece,
                1.5, 1, 12, 4, null, null, null, 0xFF404040, new double[] {5, 5, 90, 5, 5, 90}, null, null);
        String text = InspectorPainter.text(in);
        assertTrue(text.startsWith("pixel 1,2 #808080, per-pixel #404040" + System.lineSeparator()), text);
        assertTrue(text.contains("in the view: piece outlined cyan, input triangle dashed"), text);
        assertTrue(f.width() == 8);
    }

    /** The magnifier shows the frame with its outlines; the numbers are read before them: it says so. */
    @Test
    void theMagnifierSaysWhenItShowsMarksTheNumbersExclude() {
        FrameSlot f = new FrameSlot(64, 48);
        Arrays.fill(f.frame.colour(), 0xFF808080);
        f.inspection = new PixelInspector.Inspection(10, 10, 0xFF808080, 3, null, 2.5, 10.25, 3.5, 10.25, 3.5, 0.125,
                null, 1.5, 1, 12, 4, null, null, null, 0, null, null, null);
        f.underMarks = InspectorPainter.patch(f.frame.colour(), 64, 48, 10, 10);
        assertEquals(null, InspectorPainter.marksNote(f), "nothing drawn over the image");
        for (int x = 8; x <= 10; x++) {
            f.frame.colour()[10 * 64 + x] = 0xFFFFFF00;
        }
        f.frame.colour()[40 * 64 + 60] = 0xFFFFFF00;
        String note = InspectorPainter.marksNote(f);
        assertTrue(note != null && note.startsWith("magnifier: 3 px marked over the image, this one too"), note);
    }

    @Test
    void theLoopKeepsTheImageUnderTheOutlinesForTheMagnifier() throws Exception {
        ViewState state = new ViewState(dev.trisect.content.DemoScenes.demo());
        state.viewSize(320, 180);
        ViewSettings d = ViewSettings.defaults();
        state.settings(d.withRender(d.render().withMode(dev.trisect.render.RenderMode.TESSELLATED).withBorders(true)
                .withTessellation(d.render().tessellation().withMaxEdge(4))));
        state.inspect(160, 120);
        TripleBuffer buffers = new TripleBuffer();
        FrameSlot[] shown = new FrameSlot[1];
        FrameSlot f = LoopRun.until(state, buffers, 1, "an inspected frame", () -> {
            shown[0] = buffers.acquire(shown[0]);
            return shown[0] != null && shown[0].inspection != null ? shown[0] : null;
        });
        assertTrue(f.underMarks != null, "the image under the marks is kept");
        String note = InspectorPainter.marksNote(f);
        assertTrue(note != null && note.contains("px marked over the image"), "4 px pieces' outlines: " + note);
    }

    @Test
    void pinsAreAShortListTheSecondClickUnpins() {
        ViewState state = new ViewState(dev.trisect.content.DemoScenes.floor());
        for (int k = 1; k <= 5; k++) {
            state.togglePin(k, 2 * k);
        }
        assertEquals(ViewState.MAX_PINS, state.pins().length, "at most four");
        assertEquals((2L << 32) | 4, state.pins()[0], "the oldest went");
        state.togglePin(3, 6);
        assertEquals(3, state.pins().length, "pinned again: unpinned");
        state.clearPins();
        assertEquals(0, state.pins().length);
    }

    @Test
    void pinnedPixelsAreReadAfreshEachFrame() throws Exception {
        ViewState state = new ViewState(dev.trisect.content.DemoScenes.demo());
        state.viewSize(320, 180);
        state.inspect(160, 120);
        state.togglePin(100, 150);
        state.togglePin(250, 160);
        TripleBuffer buffers = new TripleBuffer();
        FrameSlot[] shown = new FrameSlot[1];
        FrameSlot first = LoopRun.until(state, buffers, 1, "a frame with pins", () -> {
            shown[0] = buffers.acquire(shown[0]);
            return shown[0] != null && shown[0].pins.length == 2 ? shown[0] : null;
        });
        assertEquals(100, first.pins[0].x());
        assertEquals(160, first.pins[1].y());
        PixelInspector.Inspection firstPin = first.pins[0];
        String line = InspectorPainter.pinLine(1, firstPin);
        assertTrue(line.startsWith("#1 100,150 #"), line);
        // The camera moves: the same pixel's readout follows the new frame.
        state.camera(dev.trisect.scene.Camera.looking(new dev.trisect.math.Vec3(3, 1, 5), dev.trisect.math.Vec3.ZERO));
        dev.trisect.scene.Camera before = first.camera;
        FrameSlot[] again = new FrameSlot[1];
        FrameSlot next = LoopRun.until(state, buffers, 1, "a frame from the new camera", () -> {
            again[0] = buffers.acquire(again[0]);
            return again[0] != null && !before.equals(again[0].camera) && again[0].pins.length == 2 ? again[0] : null;
        });
        assertTrue(next.pins[0].argb() != firstPin.argb() || next.pins[0].w() != firstPin.w(),
                "read from the new frame");
    }

    @Test
    void aLitPixelShowsItsLightColourBesideItsTexel() {
        // Corners lit 0.2, 0.6 and 1.0 in red at 1/w 1, 1 and 0.5: at the centroid (35.5, 20.5) of a piece
        // with corners (10.5, 10.5), (60.5, 10.5), (35.5, 40.5), pixel 35,20's centre, the screen weights
        // are 1/3 each.
        double[] corners = {10.5, 10.5, 60.5, 10.5, 35.5, 40.5};
        PieceInfo piece = new PieceInfo(8, 3, 0, false, corners, new double[] {1, 0, 0, 1, 0, 0, 0.5, 0, 0},
                new double[] {0.2, 0, 0, 0.6, 0, 0, 1.0, 0, 0});
        assertEquals(0.6, piece.colourAt(35.5, 20.5, false)[0], 1e-12, "screen-linear: the mean");
        assertEquals((0.2 + 0.6 + 0.5) / 2.5, piece.colourAt(35.5, 20.5, true)[0], 1e-12, "weighted by 1/w");
        double[] light = PixelInspector.lightAt(piece, false, null, 35, 20);
        var in = new PixelInspector.Inspection(35, 20, 0xFF808080, 3, null, 2.5, 10.25, 3.5, 10.25, 3.5, 0.125, piece,
                1.5, 1, 12, 4, null, null, null, 0xFF404040, null, light, null);
        String texel = InspectorPainter.lines(in, false).stream().filter(l -> l.contains("texel 12,4")).findFirst()
                .orElseThrow();
        assertTrue(texel.endsWith(", light 0.600 0.000 0.000"), texel);
    }
}
