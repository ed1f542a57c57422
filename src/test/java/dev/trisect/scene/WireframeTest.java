package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.LineShapes;
import dev.trisect.mesh.Lines;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** Objects drawn filled, as wire or both; the ready-made line objects; the statistics of lines. */
class WireframeTest {
    private static final int W = 160;
    private static final int H = 120;
    private final Camera camera = Camera.looking(new Vec3(2, 1.6, 3), new Vec3(0, 0, 0));

    private int[] render(Scene scene, FrameStats[] stats) {
        Framebuffer fb = new Framebuffer(W, H);
        try (SceneRenderer r = new SceneRenderer(1)) {
            stats[0] = r.render(scene, camera, RenderSettings.defaults(), fb);
        }
        return fb.colour();
    }

    private static int count(int[] color, int argb) {
        int n = 0;
        for (int c : color) {
            n += c == argb ? 1 : 0;
        }
        return n;
    }

    @Test
    void eachEdgeTwoTrianglesShareIsOneSegment() {
        Mesh box = Primitives.plane(2, 2, 3, 2);
        Lines edges = LineShapes.edges(box, 0x123456);
        Set<Long> seen = new HashSet<>();
        for (int s = 0; s < edges.segmentCount(); s++) {
            int a = edges.segments()[2 * s];
            int b = edges.segments()[2 * s + 1];
            assertTrue(seen.add((long) Math.min(a, b) << 32 | Math.max(a, b)), "edge " + a + "-" + b + " twice");
            assertEquals(0x123456, edges.colours()[s]);
        }
        // A grid of 3 x 2 quads, each cut by a diagonal: 3 * 3 + 4 * 2 sides and 6 diagonals.
        assertEquals(3 * 3 + 4 * 2 + 6, edges.segmentCount());
    }

    @Test
    void wireDrawsTheEdgesAndNothingFilledFilledAndWireDrawsBoth() {
        Material red = Material.colour(0xFF0000);
        FrameStats[] st = new FrameStats[1];
        Scene scene = new Scene();
        SceneObject box = new SceneObject(Primitives.box(1, 1, 1), red);
        scene.add(box);
        int[] filled = render(scene, st);
        assertEquals(0, st[0].segmentsIn());
        int redFilled = count(filled, 0xFFFF0000);
        assertTrue(redFilled > 500, "filled: " + redFilled);
        assertEquals(0, count(filled, 0xFFFFFFFF));

        box.setDrawStyle(DrawStyle.WIRE);
        int[] wire = render(scene, st);
        assertEquals(0, count(wire, 0xFFFF0000), "nothing filled");
        int white = count(wire, 0xFFFFFFFF);
        assertTrue(white > 100, "edges drawn: " + white);
        assertEquals(LineShapes.edges(box.mesh(), 0xFFFFFF).segmentCount(), st[0].segmentsIn());
        assertTrue(st[0].linePixels() >= white, "every pixel lit was written (some more than once)");

        box.setDrawStyle(DrawStyle.FILLED_AND_WIRE);
        box.setWireColour(0x00FF00);
        int[] both = render(scene, st);
        int green = count(both, 0xFF00FF00);
        // The visible edges (9 sides, 3 diagonals of the 12 sides and 6 diagonals) show whole, over
        // their own faces; the hidden ones not at all.
        assertTrue(green > 0.5 * white && green < 0.8 * white, "edges over the faces: " + green + " of " + white);
        int faces = count(both, 0xFFFF0000);
        assertTrue(Math.abs(faces + green - redFilled) < 0.1 * redFilled, "the faces are filled: " + faces + " + " + green
                + " against " + redFilled);
    }

    @Test
    void readyObjectsDrawTheirLinesWhereverTheObjectIs() {
        Scene scene = new Scene();
        // The grid first: the x and z axes lie on its middle lines, and of lines at equal depth the later wins.
        scene.add(SceneObject.lines(LineShapes.grid(4, 8, 0x808080), 1));
        SceneObject axes = SceneObject.lines(LineShapes.axes(1), 2);
        scene.add(axes);
        SceneObject box = SceneObject.lines(LineShapes.box(1, 1, 1, 0xFFFF00), 1);
        box.setTransform(Transform.translation(0, 0.5, 0));
        scene.add(box);
        FrameStats[] st = new FrameStats[1];
        int[] img = render(scene, st);
        assertEquals(3 + 18 + 12, st[0].segmentsIn());
        for (int argb : new int[] {0xFFFF0000, 0xFF00FF00, 0xFF0000FF, 0xFF808080, 0xFFFFFF00}) {
            assertTrue(count(img, argb) > 10, Integer.toHexString(argb) + ": " + count(img, argb));
        }
        assertThrows(IllegalArgumentException.class, () -> axes.setLineWidth(0));
        assertTrue(st[0].toJson().contains("\"segments_in\":33"), st[0].toJson());
    }
}
