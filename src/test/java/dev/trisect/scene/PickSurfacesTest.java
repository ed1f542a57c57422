package dev.trisect.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.LineShapes;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.texture.Texture;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Which surfaces a pick finds, as {@link SceneRenderer#pick}'s Javadoc says: opaque and alpha-tested
 * triangles; a blended pane is seen through, a cut-out's holes too, and lines, billboards and labels are
 * not picked. Every pixel asked is one that shows the surface in question (its colour is checked first).
 */
class PickSurfacesTest {
    private static final Camera CAMERA = Camera.looking(new Vec3(0, 0, 5), Vec3.ZERO);

    private static String picked(SceneRenderer r, int x, int y) {
        return r.pick(x, y).map(p -> p.object().name()).orElse("nothing");
    }

    @Test
    void glassAndHolesAreSeenThroughAndSpritesAndLinesAreNotPicked() {
        Scene scene = new Scene();
        SceneObject back = new SceneObject(Primitives.box(8, 3, 0.1), Material.colour(0xFF0000),
                Transform.translation(0, -1.5, -1));
        back.setName("back");
        SceneObject glass = new SceneObject(Primitives.box(1, 1, 0.05), Material.colour(0x0000FF).withOpacity(0.5),
                Transform.translation(-1, -1, 0));
        glass.setName("glass");
        // Left half of the texture opaque green, right half a hole.
        int[] half = {0xFF00FF00, 0, 0xFF00FF00, 0};
        SceneObject fence = new SceneObject(Primitives.box(1, 1, 0.05), Material.of(new Texture("half", 2, 2, half)),
                Transform.translation(1, -1, 0));
        fence.setName("fence");
        SceneObject lines = SceneObject.lines(LineShapes.box(1, 1, 1, 0xFFFFFF), 5);
        lines.setTransform(Transform.translation(-1.5, 1.2, 0));
        lines.setName("lines");
        SceneObject sprites = SceneObject.billboards(List.of(Billboard.pixels(Texture.solid("w", 0xFFFFFFFF),
                new Vec3(1.5, 1.2, 0), 20, 20)));
        sprites.setName("billboard");
        sprites.setLabels(List.of(Label.of("MMMM", new Vec3(0, 1.2, 0)).withBackground(0xFFFFFFFF)));
        scene.add(back, glass, fence, lines, sprites);
        try (SceneRenderer r = new SceneRenderer(1)) {
            Framebuffer fb = new Framebuffer(200, 200);
            r.render(scene, CAMERA, RenderSettings.defaults(), fb);
            int[] c = fb.colour();
            // The glass's centre (-1, -1, 0): blended blue over red, picked as the back.
            int gx = 100 - 35;
            int gy = 100 + 35;
            assertEquals(0x7F0080, c[gy * 200 + gx] & 0xFFFFFF, "blue glass over red at " + gx + "," + gy);
            assertEquals("back", picked(r, gx, gy));
            // The fence: its opaque left half picked, its hole shows the back and picks it.
            int fx = 100 + 35;
            assertEquals(0x00FF00, c[gy * 200 + fx - 8] & 0xFFFFFF);
            assertEquals("fence", picked(r, fx - 8, gy));
            assertEquals(0xFF0000, c[gy * 200 + fx + 8] & 0xFFFFFF);
            assertEquals("back", picked(r, fx + 8, gy));
            // Lines, a billboard and a label over the background: drawn, not picked.
            int row = 100 - 42;
            int drawnOnRow = 0;
            for (int x = 0; x < 200; x++) {
                if ((c[row * 200 + x] & 0xFFFFFF) != 0) {
                    drawnOnRow++;
                    assertEquals("nothing", picked(r, x, row), "pixel " + x + "," + row);
                }
            }
            assertNotEquals(0, drawnOnRow, "the row crosses the lines, the label and the billboard");
            assertEquals(0xFFFFFF, c[row * 200 + 152] & 0xFFFFFF, "the billboard's centre");
            assertEquals(0xFFFFFF, c[row * 200 + 100] & 0xFFFFFF, "the label's backdrop");
        }
    }
}
