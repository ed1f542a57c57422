package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Lines;
import dev.trisect.mesh.Primitives;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.scene.DrawStyle;
import dev.trisect.scene.Label;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.ScreenText;
import dev.trisect.scene.internal.DrawnFrame;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The pixel inspector names the line or label drawn over a triangle at the inspected pixel, as the fill
 * itself found it (the probe notes the last line or quad command that wrote the pixel), in every path;
 * probing leaves the image as it is.
 */
class InspectorShapesTest {
    private static final int W = 160;
    private static final int H = 120;
    private static final int RED = 0xFFFF0000;
    private static final int WHITE = 0xFFFFFFFF;
    private static final int YELLOW = 0xFFFFFF00;
    private static final int GREY = 0xFF808080;

    private static Scene scene() {
        Scene scene = new Scene();
        SceneObject wall = new SceneObject(Primitives.box(4, 3, 0.1), Material.colour(0x808080));
        wall.setName("wall");
        scene.add(wall);
        Lines.Builder b = Lines.builder();
        b.segment(b.point(-1.5, -0.8, 0.2), b.point(1.5, -0.6, 0.2), 0xFF0000);
        SceneObject rail = SceneObject.lines(b.build(), 3);
        rail.setName("rail");
        scene.add(rail);
        SceneObject post = new SceneObject(Primitives.box(0.5, 0.5, 0.5), Material.colour(0x808080),
                Transform.translation(1.2, 0.9, 0.3));
        post.setName("post");
        post.setDrawStyle(DrawStyle.WIRE);
        post.setWireColour(0xFFFF00);
        scene.add(post);
        SceneObject sign = SceneObject.labels(List.of(Label.of("sign", new Vec3(-0.8, 0.6, 0.2))));
        sign.setName("signs");
        scene.add(sign);
        scene.setScreenText(List.of(ScreenText.of(ScreenText.Corner.TOP_LEFT, "hud").withColour(0x00FF00)));
        return scene;
    }

    /** Draws the scene probing (x, y) (-1: none); returns the frame's colours, and the shape named there. */
    private static Object[] draw(FrameRenderer r, RenderMode mode, int x, int y) {
        Scene scene = scene();
        Camera camera = Camera.looking(new Vec3(0, 0, 4), Vec3.ZERO);
        DrawnFrame drawn = new DrawnFrame(scene.capture(), camera, W, H, new Draws())
                .withScreenText(scene.screenText());
        Framebuffer fb = new Framebuffer(W, H);
        r.probe(x, y);
        r.render(drawn.draws(), RenderSettings.defaults().withMode(mode), fb);
        r.probe(-1, -1);
        return new Object[] {fb.colour().clone(), PixelInspector.shapeOf(r.drawn().probed(), drawn)};
    }

    private static int find(int[] argb, int colour) {
        for (int i = 0; i < argb.length; i++) {
            if (argb[i] == colour) {
                return i;
            }
        }
        throw new AssertionError(String.format("no pixel of #%08X", colour));
    }

    @Test
    void theInspectorNamesTheLineWireLabelOrScreenTextOverThePixelAndNothingElse() {
        for (RenderMode mode : RenderMode.values()) {
            try (FrameRenderer r = new FrameRenderer(2)) {
                int[] plain = (int[]) draw(r, mode, -1, -1)[0];
                String[][] want = {
                    {"line segment 0 of \"rail\", #FF0000, 3 px", Integer.toString(find(plain, RED))},
                    {"wireframe edge", Integer.toString(find(plain, YELLOW))},
                    {"label \"sign\" of \"signs\"", Integer.toString(find(plain, WHITE))},
                    {"the screen text", Integer.toString(find(plain, 0xFF00FF00))}};
                for (String[] w : want) {
                    int i = Integer.parseInt(w[1]);
                    Object[] probed = draw(r, mode, i % W, i / W);
                    assertArrayEquals(plain, (int[]) probed[0], "probing changes no pixel");
                    String shape = (String) probed[1];
                    assertTrue(shape != null && shape.startsWith(w[0]), mode + ": " + shape);
                }
                int wall = find(plain, GREY);
                Object[] bare = draw(r, mode, wall % W, wall / W);
                assertNull(bare[1], mode + ": the wall alone");
                assertArrayEquals(plain, (int[]) bare[0]);
                assertEquals(null, draw(r, mode, -1, -1)[1]);
            }
        }
    }
}
