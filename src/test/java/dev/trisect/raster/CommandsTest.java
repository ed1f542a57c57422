package dev.trisect.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.render.Framebuffer;
import dev.trisect.texture.Texture;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The command lists of the band fill: every band draws its commands in the order they were added,
 * whatever their kinds (PIXEL_CONTRACT's order of drawing, which blended objects drawn last rely on),
 * and a spike's storage is given back.
 */
class CommandsTest {
    private static final int W = 40;
    private static final int H = 40;
    private static final int BAND_ROWS = 4;
    private static final int RED = 0xFFFF0000;
    private static final int BLUE = 0xFF0000FF;

    @Test
    void everyBandListsItsCommandsInTheOrderAddedWhateverTheirKinds() {
        Random random = new Random(26);
        ScreenTriangles triangles = new ScreenTriangles();
        Segments segments = new Segments();
        segments.begin(W, H);
        LineSetup setup = new LineSetup();
        Commands list = new Commands().triangles(triangles).segments(segments);
        for (int i = 0; i < 300; i++) {
            if (random.nextBoolean()) {
                double x = W * random.nextDouble();
                double y = H * random.nextDouble();
                triangles.add(x, y, 1, 0, 0, x + 9 * random.nextDouble(), y + 9, 1, 1, 0, x - 5, y + 7, 1, 0, 1, i, 0);
                int t = triangles.count() - 1;
                list.add(Commands.TRIANGLE, t, triangles.firstRow(t), triangles.endRow(t));
            } else if (setup.add(segments, W * random.nextDouble(), H * random.nextDouble(), 1, W * random.nextDouble(),
                    H * random.nextDouble(), 1, 1, 0xFFFFFF)) {
                int l = segments.count() - 1;
                list.add(Commands.LINE, l, segments.firstRow(l), segments.lastRow(l) + 1);
            }
        }
        list.bin(H, BAND_ROWS);
        int[] items = list.bins().items();
        int listed = 0;
        for (int b = 0; b < H / BAND_ROWS; b++) {
            for (int k = list.bins().start(b) + 1; k < list.bins().start(b + 1); k++) {
                assertTrue(items[k - 1] < items[k], "band " + b + " lists command " + items[k] + " after "
                        + items[k - 1]);
            }
            listed += list.bins().start(b + 1) - list.bins().start(b);
        }
        assertTrue(listed > list.count(), "commands span several bands: " + listed);
    }

    /**
     * Ties of depth show the order: a triangle is drawn where its 1/w is larger than the frame's (the
     * first of two at one depth stays), a line where it is at least the frame's (the last stays). Mixed
     * with each other's kind, both keep the order of submission in every band.
     */
    @Test
    void theBandFillDrawsEachBandsCommandsInSubmissionOrder() {
        ScreenTriangles triangles = new ScreenTriangles();
        Segments segments = new Segments();
        segments.begin(W, H);
        LineSetup setup = new LineSetup();
        Commands list = new Commands().triangles(triangles).segments(segments);
        triangles.add(2, 2, 0.5, 0, 0, 38, 3, 0.5, 1, 0, 3, 38, 0.5, 0, 1, 0, 0);
        list.add(Commands.TRIANGLE, 0, triangles.firstRow(0), triangles.endRow(0));
        setup.add(segments, 4.5, 20.5, 0.5, 35.5, 20.5, 0.5, 1, 0x00FF00);
        list.add(Commands.LINE, 0, segments.firstRow(0), segments.lastRow(0) + 1);
        triangles.add(2, 2, 0.5, 0, 0, 38, 3, 0.5, 1, 0, 3, 38, 0.5, 0, 1, 1, 1);
        list.add(Commands.TRIANGLE, 1, triangles.firstRow(1), triangles.endRow(1));
        setup.add(segments, 4.5, 20.5, 0.5, 35.5, 20.5, 0.5, 1, 0xFFFFFF);
        list.add(Commands.LINE, 1, segments.firstRow(1), segments.lastRow(1) + 1);
        list.bin(H, BAND_ROWS);
        Framebuffer frame = new Framebuffer(W, H);
        BandFill fill = new BandFill();
        Texture[] textures = {Texture.solid("red", RED), Texture.solid("blue", BLUE)};
        for (int b = 0; b < H / BAND_ROWS; b++) {
            frame.clearRows(b * BAND_ROWS, (b + 1) * BAND_ROWS, 0);
            fill.fill(frame, list, b, textures, false, 0, b * BAND_ROWS, W, (b + 1) * BAND_ROWS);
        }
        int red = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int c = frame.colour()[y * W + x];
                if (y == 20 && x >= 4 && x < 35) {
                    assertEquals(0xFFFFFFFF, c, "the last line stays at (" + x + ", " + y + ")");
                } else if (c != 0xFF000000) {
                    assertEquals(RED, c, "the first triangle stays at (" + x + ", " + y + ")");
                    red++;
                }
            }
        }
        assertTrue(red > 500, red + " red pixels");
    }

    @Test
    void aSpikeOfCommandsGivesItsStorageBack() {
        Commands list = new Commands();
        for (int i = 0; i < 1_000_000; i++) {
            list.add(Commands.TRIANGLE, i, 0, 1);
        }
        list.clear();
        list.add(Commands.TRIANGLE, 7, 0, 1);
        list.add(Commands.TREE, 9, 0, 1);
        list.shrink(8192, 16384);
        assertTrue(list.capacity() <= 8192, "room kept for " + list.capacity() + " commands");
        assertEquals(2, list.count());
        assertEquals(Commands.TRIANGLE, Commands.kind(list.command(0)));
        assertEquals(7, Commands.ref(list.command(0)));
        assertEquals(Commands.TREE, Commands.kind(list.command(1)));
        assertEquals(9, Commands.ref(list.command(1)));
    }
}
