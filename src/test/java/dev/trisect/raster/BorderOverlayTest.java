package dev.trisect.raster;

import dev.trisect.render.BorderStyle;
import dev.trisect.render.Framebuffer;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.texture.Texture;
import java.util.Random;
import org.junit.jupiter.api.Test;

class BorderOverlayTest {
    private static final int W = 80;
    private static final int H = 60;
    private static final Texture[] GREY = {Texture.solid("grey", 0xFF808080), Texture.solid("blue", 0xFF0000FF)};

    private static int[] all(ScreenTriangles t) {
        int[] order = new int[t.count()];
        for (int i = 0; i < order.length; i++) {
            order[i] = i;
        }
        return order;
    }

    /** The triangles filled per pixel over a black frame. */
    private static Framebuffer filled(ScreenTriangles t) {
        Framebuffer fb = new Framebuffer(W, H);
        fb.clearRows(0, H, 0);
        new Rasterizer().fill(fb, t, all(t), 0, t.count(), GREY, true, 0, 0, W, H);
        return fb;
    }

    private static Framebuffer draw(ScreenTriangles t, int bandRows) {
        Framebuffer fb = filled(t);
        OutlinePlan plan = new OutlinePlan();
        plan.prepare(t, BorderStyle.plain(), 0, 1, H, bandRows);
        BorderOverlay overlay = new BorderOverlay();
        for (int y = 0, band = 0; y < H; y += bandRows, band++) {
            overlay.draw(fb, plan, band, y, Math.min(H, y + bandRows));
        }
        return fb;
    }

    @Test
    void outlineFollowsTheEdgesAndStaysInsideTheFrame() {
        ScreenTriangles t = new ScreenTriangles();
        // Corners far outside the frame: the lines must be clipped, not wrapped or thrown.
        t.add(5.3, 5.7, 1, 0, 0, 300, 40.2, 1, 0, 0, 40.6, -200, 1, 0, 0, 0, 0);
        Framebuffer fb = draw(t, H);
        int yellow = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                if (fb.colour()[y * W + x] == BorderOverlay.YELLOW) {
                    yellow++;
                    assertTrue(distanceToEdges(t, x + 0.5, y + 0.5) <= 0.75, "pixel " + x + "," + y + " is off the edges");
                }
            }
        }
        assertTrue(yellow > 40, "the visible parts of two edges are drawn: " + yellow);
    }

    private static double distanceToEdges(ScreenTriangles t, double px, double py) {
        double[] s = t.screen();
        double best = Double.POSITIVE_INFINITY;
        for (int e = 0; e < 3; e++) {
            double ax = s[2 * e];
            double ay = s[2 * e + 1];
            double bx = s[2 * ((e + 1) % 3)];
            double by = s[2 * ((e + 1) % 3) + 1];
            double len = Math.hypot(bx - ax, by - ay);
            best = Math.min(best, Math.abs((bx - ax) * (py - ay) - (by - ay) * (px - ax)) / len);
        }
        return best;
    }

    /** 40 triangles scattered over the frame and beyond it; with {@code fallbacks}, one in three a fallback piece. */
    private static ScreenTriangles scattered(long seed, boolean fallbacks) {
        Random rnd = new Random(seed);
        ScreenTriangles t = new ScreenTriangles();
        for (int k = 0; k < 40; k++) {
            double x = rnd.nextDouble() * W;
            double y = rnd.nextDouble() * H;
            t.add(x, y, 0.5, 0, 0, x + rnd.nextGaussian() * 25, y + rnd.nextGaussian() * 25, 0.4, 0, 0,
                    x + rnd.nextGaussian() * 25, y + rnd.nextGaussian() * 25, 0.6, 0, 0, k, 0, fallbacks && k % 3 == 0);
        }
        return t;
    }

    @Test
    void drawingInBandsGivesTheSamePixels() {
        ScreenTriangles t = scattered(11, false);
        assertArrayEquals(draw(t, H).colour(), draw(t, 7).colour());
        assertArrayEquals(draw(t, H).colour(), draw(t, 1).colour());
    }

    /**
     * The plan's edges are segments of the line rasterizer's crossing rule: drawn band by band, with
     * faded and fallback outlines, every pixel they change is one the rule's one-pixel test
     * ({@link OutlineProbe}, {@link LineCrossing#lights}) says an outline lights; the loop of OpenGL's
     * lines refuses them.
     */
    @Test
    void thePlansEdgesAreCrossingLinesOfTheLineRasterizer() {
        ScreenTriangles t = scattered(5, true);
        BorderStyle style = new BorderStyle(BorderStyle.Colouring.YELLOW, true);
        int bandRows = 8;
        OutlinePlan plan = new OutlinePlan();
        plan.prepare(t, style, 0, 1, H, bandRows);
        assertEquals(Segments.CROSSING, plan.segments().rule());
        Framebuffer fb = filled(t);
        BorderOverlay overlay = new BorderOverlay();
        long drawn = 0;
        for (int y = 0, band = 0; y < H; y += bandRows, band++) {
            drawn += overlay.draw(fb, plan, band, y, Math.min(H, y + bandRows));
        }
        assertTrue(drawn > 100, "outlines drawn: " + drawn);
        Framebuffer plain = filled(t);
        for (int i = 0; i < W * H; i++) {
            if (fb.colour()[i] != plain.colour()[i]) {
                int x = i % W;
                int y = i / W;
                boolean lit = false;
                for (int tri = 0; tri < t.count() && !lit; tri++) {
                    lit = OutlineProbe.lights(t, tri, x, y, H, plain.depth()[i]);
                }
                assertTrue(lit, "pixel " + x + "," + y + " drawn by no outline the probe knows");
            }
        }
        assertThrows(IllegalArgumentException.class,
                () -> LineRaster.rows(plan.segments(), 0, fb.colour(), fb.depth(), 0, H));
    }

    @Test
    void outlinesOfHiddenPiecesStayHidden() {
        ScreenTriangles t = new ScreenTriangles();
        // A small far triangle (1/w = 0.1) wholly behind a big near one (1/w = 1).
        t.add(30, 20, 0.1, 0, 0, 50, 20, 0.1, 0, 0, 40, 40, 0.1, 0, 0, 0, 1);
        t.add(0, 0, 1, 0, 0, 80, 0, 1, 0, 0, 0, 120, 1, 0, 0, 1, 0);
        Framebuffer fb = draw(t, H);
        for (int y = 22; y < 38; y++) {
            for (int x = 32; x < 48; x++) {
                assertEquals(0xFF808080, fb.colour()[y * W + x], "hidden outline shows at " + x + "," + y);
            }
        }
        // The near triangle's own hypotenuse still shows.
        int yellow = 0;
        for (int c : fb.colour()) {
            yellow += c == BorderOverlay.YELLOW ? 1 : 0;
        }
        assertTrue(yellow > 40);
    }

    @Test
    void theOutlineOfASliverSeenEdgeOnStaysBehindANearerSurface() {
        ScreenTriangles t = new ScreenTriangles();
        // A far sliver 0.03 px wide seen edge-on (1/w from 0.05 to 0.2 across it, as the side of a box far
        // off), filled per pixel as slivers are, wholly behind a near triangle (1/w = 1). Its plane, half a
        // pixel off it at the pixel centres its outline lights, reads 1/w = 2.5: nearer than the near one.
        t.add(40, 5, 0.05, 0, 0, 40.03, 30, 0.2, 0, 0, 40, 55, 0.05, 0, 0, 0, 0, true);
        t.add(0, 0, 1, 0, 0, 80, 0, 1, 0, 0, 0, 120, 1, 0, 0, 1, 1);
        Framebuffer fb = draw(t, H);
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < 60; x++) {
                assertTrue(fb.colour()[y * W + x] != OverlayColours.FALLBACK, "the hidden sliver's outline at " + x
                        + "," + y);
            }
        }
        // Alone, it is outlined.
        ScreenTriangles alone = new ScreenTriangles();
        alone.add(40, 5, 0.05, 0, 0, 40.03, 30, 0.2, 0, 0, 40, 55, 0.05, 0, 0, 0, 0, true);
        int magenta = 0;
        for (int c : draw(alone, H).colour()) {
            magenta += c == OverlayColours.FALLBACK ? 1 : 0;
        }
        assertTrue(magenta > 40, "a sliver in view is outlined: " + magenta);
    }

    @Test
    void fallbackPiecesAreOutlinedInTheirOwnColour() {
        ScreenTriangles t = new ScreenTriangles();
        // Two triangles side by side, the right one a per-pixel fallback piece.
        t.add(2, 2, 1, 0, 0, 38, 2, 1, 0, 0, 2, 50, 1, 0, 0, 0, 0, false);
        t.add(42, 2, 1, 0, 0, 78, 2, 1, 0, 0, 42, 50, 1, 0, 0, 1, 0, true);
        Framebuffer fb = draw(t, H);
        int yellowLeft = 0;
        int magentaRight = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int c = fb.colour()[y * W + x];
                assertTrue(c != OverlayColours.FALLBACK || x >= 40, "magenta only on the fallback piece");
                assertTrue(c != OverlayColours.PIECE || x < 40, "yellow only on the ordinary piece");
                yellowLeft += c == OverlayColours.PIECE ? 1 : 0;
                magentaRight += c == OverlayColours.FALLBACK ? 1 : 0;
            }
        }
        assertTrue(yellowLeft > 60 && magentaRight > 60, yellowLeft + " yellow, " + magentaRight + " magenta");
    }

    private static Framebuffer drawEachAlone(ScreenTriangles t, BorderStyle style) {
        Framebuffer fb = filled(t);
        BorderOverlay overlay = new BorderOverlay();
        for (int i = 0; i < t.count(); i++) {
            // A list of one triangle: nothing to share.
            ScreenTriangles one = new ScreenTriangles();
            double[] s = t.screen();
            double[] a = t.attributes();
            one.add(s[6 * i], s[6 * i + 1], a[9 * i], 0, 0, s[6 * i + 2], s[6 * i + 3], a[9 * i + 3], 0, 0,
                    s[6 * i + 4], s[6 * i + 5], a[9 * i + 6], 0, 0, i, 0, t.perPixel()[i]);
            OutlinePlan plan = new OutlinePlan();
            plan.prepare(one, style, 0, 1, H, H);
            overlay.draw(fb, plan, 0, 0, H);
        }
        return fb;
    }

    private static Framebuffer drawTogether(ScreenTriangles t, BorderStyle style) {
        Framebuffer fb = filled(t);
        OutlinePlan plan = new OutlinePlan();
        plan.prepare(t, style, 0, 1, H, H);
        new BorderOverlay().draw(fb, plan, 0, 0, H);
        return fb;
    }

    @Test
    void aSharedEdgeWalkedOnceLooksAsIfDrawnTwice() {
        // A quad split along its diagonal, both halves on one plane, the second a fallback piece:
        // the diagonal is walked once, applying the first half's outline and then the second's.
        ScreenTriangles t = new ScreenTriangles();
        t.add(10, 10, 0.5, 0, 0, 70, 12, 0.5, 0, 0, 12, 50, 0.5, 0, 0, 0, 0, false);
        t.add(70, 12, 0.5, 0, 0, 68, 52, 0.5, 0, 0, 12, 50, 0.5, 0, 0, 1, 0, true);
        for (BorderStyle style : new BorderStyle[] {BorderStyle.plain(),
                new BorderStyle(BorderStyle.Colouring.YELLOW, true), BorderStyle.fallbackOnly()}) {
            assertArrayEquals(drawEachAlone(t, style).colour(), drawTogether(t, style).colour(), style.toString());
        }
        // The diagonal is magenta where the later (fallback) piece draws over the earlier's yellow.
        Framebuffer fb = drawTogether(t, BorderStyle.plain());
        assertEquals(OverlayColours.FALLBACK, fb.colour()[31 * W + 40]);
    }

    @Test
    void aSharedEdgeHiddenForTheLaterPieceTakesTheEarlierPiecesColour() {
        // Two ordinary pieces folded along their shared top edge (10,10)-(70,10), coloured by split
        // depth: the earlier (level 0, cyan) faces the viewer at 1/w = 1; the later (level 4, red) lies
        // under it, its third corner farther off (1/w = 0.2). Both outlines are opaque and unheld, so
        // the edge, walked once in the later piece's turn, takes BorderOverlay's simple per-pixel step.
        // Its pixels (row 10, centres at y = 10.5, inside the earlier piece) hold 1/w = 1, where the
        // later piece's plane reads 0.98: beyond the tolerance, so only the earlier outline shows.
        ScreenTriangles t = new ScreenTriangles();
        t.add(10, 10, 1, 0, 0, 70, 10, 1, 0, 0, 40, 50, 1, 0, 0, 0, 0, false, 0);
        t.add(10, 10, 1, 0, 0, 70, 10, 1, 0, 0, 40, 30, 0.2, 0, 0, 1, 0, false, 4);
        BorderStyle style = new BorderStyle(BorderStyle.Colouring.DEPTH, false);
        int earlier = OverlayColours.depth(0, 4);
        int later = OverlayColours.depth(4, 4);
        assertTrue(earlier != later);
        // One band (the edge walked without per-pixel bounds) and bands of one row (with them).
        for (int bandRows : new int[] {H, 1}) {
            Framebuffer fb = filled(t);
            OutlinePlan plan = new OutlinePlan();
            plan.prepare(t, style, 4, 1, H, bandRows);
            int shared = sharedEdge(plan);
            assertEquals(1, plan.owner(shared), "the later piece walks the shared edge");
            assertEquals(0, plan.earlier(shared), "the earlier piece shares it");
            BorderOverlay overlay = new BorderOverlay();
            for (int y = 0, band = 0; y < H; y += bandRows, band++) {
                overlay.draw(fb, plan, band, y, Math.min(H, y + bandRows));
            }
            for (int x = 10; x < 70; x++) {
                assertEquals(earlier, fb.colour()[10 * W + x], "shared edge at " + x + ",10, bands of " + bandRows);
            }
            for (int c : fb.colour()) {
                assertTrue(c != later, "the hidden piece's outline shows, bands of " + bandRows);
            }
        }
    }

    /** The one edge of {@code plan} that an earlier triangle shares. */
    private static int sharedEdge(OutlinePlan plan) {
        int found = -1;
        for (int k = 0; k < plan.edgeCount(); k++) {
            if (plan.earlier(k) != OutlinePlan.ALONE) {
                assertEquals(-1, found, "one shared edge");
                found = k;
            }
        }
        assertTrue(found >= 0, "the edge is shared");
        return found;
    }
}
