package dev.trisect.view.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.Primitives;
import dev.trisect.metrics.TexelToScreen;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.pipeline.PieceInfo;
import dev.trisect.raster.RowKnots;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Pick;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.SceneRenderer;
import dev.trisect.scene.internal.DrawnFrame;
import dev.trisect.texture.ProceduralTextures;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The pixel inspector's numbers against the renderer's own buffers of the same frame. */
class PixelInspectorTest {
    private static final int W = 160;
    private static final int H = 90;

    /** Runs the loop on {@code scene} until a frame carries an inspection of (x, y); returns that frame. */
    private static FrameSlot inspected(ViewState state, int x, int y) throws Exception {
        state.viewSize(W, H);
        state.inspect(x, y);
        // Two frames of a still scene: ask for frames, as an animation would.
        state.demand.keepDrawing("test", true);
        TripleBuffer buffers = new TripleBuffer();
        RenderLoop loop = new RenderLoop(state, buffers, () -> { }, 1);
        Thread t = new Thread(loop, "test-render");
        t.start();
        try {
            FrameSlot f = null;
            for (int poll = 0; poll < 1500; poll++) {
                f = buffers.acquire(f);
                if (f != null && f.inspection != null && f.serial >= 2) {
                    return f;
                }
                Thread.sleep(20);
            }
            throw new AssertionError("no inspected frame");
        } finally {
            loop.stop();
            t.join(5000);
        }
    }

    @Test
    void everyNumberIsTheRenderersOwn() throws Exception {
        SceneAsset floor = DemoScenes.floor();
        ViewState state = new ViewState(floor);
        ViewSettings v = ViewSettings.defaults().withRender(ViewSettings.defaults().render()
                .withTessellation(ViewSettings.defaults().render().tessellation().withPolicy(SplitPolicy.ERROR)
                        .withMaxError(0.5)));
        state.settings(v);
        int x = 70;
        int y = 52;
        FrameSlot f = inspected(state, x, y);
        PixelInspector.Inspection in = f.inspection;
        Framebuffer fb = f.frame;
        int i = y * W + x;
        assertEquals((int) fb.uv()[3 * i + 2] - 1, in.triangle(), "the UV output's triangle");
        assertTrue(in.triangle() >= 0, "the floor is under the pixel");
        assertEquals(fb.uv()[3 * i], in.s(), 0.0);
        assertEquals(fb.uv()[3 * i + 1], in.t(), 0.0);
        assertEquals(1 / fb.depth()[i], in.w(), 1e-6 * in.w());
        // The per-pixel path, rendered here from the frame's own camera, agrees with the inspector's reference.
        var vp = f.camera.viewProjection(new Viewport(W, H));
        Framebuffer ref = new Framebuffer(W, H);
        ref.recordUv(true);
        try (FrameRenderer r = new FrameRenderer(1)) {
            r.render(floor.mesh(), floor.textureArray(), vp, v.render().withMode(RenderMode.PERSPECTIVE), ref);
        }
        assertEquals(ref.uv()[3 * i], in.refS(), 0.0);
        assertEquals(ref.colour()[i], in.refArgb(), "the per-pixel path's colour beside this path's");
        double[] c = in.triangle2d();
        assertTrue(c != null && c.length >= 6, "the input triangle (its part before the near plane) on screen");
        boolean covers = false;
        for (int k = 2; k + 3 < c.length; k += 2) {
            // A fan of the convex outline: one of its triangles covers the pixel.
            covers |= inside(new double[] {c[0], c[1], c[k], c[k + 1], c[k + 2], c[k + 3]}, x + 0.5, y + 0.5);
        }
        assertTrue(covers, "and covers the pixel: " + java.util.Arrays.toString(c));
        assertEquals(ref.uv()[3 * i + 1], in.refT(), 0.0);
        double exact = new TexelToScreen(floor.mesh(), floor.textureArray(), vp, new Viewport(W, H))
                .displacement(in.triangle(), in.s(), in.t(), x, y);
        assertEquals(exact, in.displacement(), 0.0, "the exact displacement of the metrics package");
        assertTrue(in.displacement() <= 0.5, "within the error policy's bound");
        PieceInfo p = in.piece();
        assertNotNull(p, "the piece filled there");
        assertEquals(in.triangle(), p.triangle());
        assertTrue(p.level() >= 0 && p.level() <= f.stats.deepestSplit(), "level " + p.level());
        assertTrue(inside(p.screen(), x + 0.5, y + 0.5), "the piece holds the pixel centre");
        assertEquals(Math.max(0, (int) Math.floor(in.lambda())), in.mipLevel(), "trilinear's lower level");
        assertTrue(InspectorPainter.lines(in, false).stream().anyMatch(l -> l.contains("split level " + p.level())));
    }

    @Test
    void theSpanPathShowsTheKnotsOfTheRowAndTheSegmentOfThePixel() throws Exception {
        SceneAsset demo = DemoScenes.byName("demo").orElseThrow();
        ViewState state = new ViewState(demo);
        ViewSettings v = ViewSettings.defaults().withRender(ViewSettings.defaults().render().withMode(RenderMode.SPANS)
                .withKnotError(0.5));
        state.settings(v);
        // A pixel of the brick wall, whose depth changes along the rows.
        int x = 130;
        int y = 40;
        FrameSlot f = inspected(state, x, y);
        PixelInspector.Inspection in = f.inspection;
        assertTrue(in.triangle() >= 0, "a triangle under the pixel");
        RowKnots knots = in.knots();
        assertNotNull(knots, "the span path's knots");
        assertEquals(y, knots.y());
        int k = in.segment();
        assertTrue(k >= 0 && knots.columns()[k] <= x && x <= knots.columns()[k + 1], "the segment holds the pixel: "
                + java.util.Arrays.toString(knots.columns()));
        for (double b : knots.bounds()) {
            assertTrue(b <= 0.5 * (1 + 1e-12), "every segment within Max error: " + b);
        }
        assertTrue(in.displacement() <= knots.bounds()[k] + 1e-6, "the pixel within its segment's bound: "
                + in.displacement() + " > " + knots.bounds()[k]);
        assertTrue(InspectorPainter.lines(in, false).stream().anyMatch(l -> l.startsWith("span segment " + (k + 1))),
                InspectorPainter.lines(in, false).toString());
    }

    @Test
    void theSkyHasNothingToInspect() throws Exception {
        ViewState state = new ViewState(DemoScenes.floor());
        FrameSlot f = inspected(state, 5, 2);
        assertEquals(-1, f.inspection.triangle());
        assertTrue(InspectorPainter.lines(f.inspection, true).get(1).contains("nothing drawn"));
    }

    private static boolean inside(double[] s, double x, double y) {
        double d0 = (s[2] - s[0]) * (y - s[1]) - (s[3] - s[1]) * (x - s[0]);
        double d1 = (s[4] - s[2]) * (y - s[3]) - (s[5] - s[3]) * (x - s[2]);
        double d2 = (s[0] - s[4]) * (y - s[5]) - (s[1] - s[5]) * (x - s[4]);
        return (d0 >= 0 && d1 >= 0 && d2 >= 0) || (d0 <= 0 && d1 <= 0 && d2 <= 0);
    }

    @Test
    void theReadoutNamesAFallbackPieceAndWhy() {
        // A sliver 0.03 px thick and a fat piece, both filled per pixel.
        PieceInfo sliver = new PieceInfo(7, 3, 1, true, new double[] {10, 10, 60, 10, 35, 10.03}, new double[9]);
        PieceInfo capped = new PieceInfo(8, 3, 2, true, new double[] {10, 10, 60, 10, 35, 40}, new double[9]);
        assertTrue(sliver.sliver());
        PixelInspector.Inspection on = new PixelInspector.Inspection(35, 10, 0xFFFF00FF, 3, null, 2, 0, 0, 0, 0, 0, capped,
                0, 0, 0, 0, null, sliver, null, 0, null, null, null);
        var lines = InspectorPainter.lines(on, false);
        assertTrue(lines.contains("magenta outline: piece 7 of triangle 3, filled per pixel: a sliver (thinner than 1/16 px)"),
                lines.toString());
        assertTrue(lines.stream().anyMatch(l -> l.endsWith("piece 8, split level 2, filled per pixel: a cap stopped its "
                + "splitting")), lines.toString());
    }

    /**
     * In a scene of several objects the readout names the object under the pixel and the triangle's index
     * in that object's own mesh (the frame numbers triangles across all objects), as picking does.
     */
    @Test
    void aMultiObjectSceneNamesTheObjectAndItsOwnTriangle() throws Exception {
        Scene scene = new Scene();
        Mesh ground = Primitives.plane(20, 20, 8, 8);
        SceneObject floor = new SceneObject(ground, Material.of(ProceduralTextures.uvGrid(64)));
        floor.setName("floor");
        SceneObject crate = new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.crate(64)),
                Transform.translation(0, 0.5, 0));
        crate.setName("crate");
        scene.add(floor, crate);
        Camera camera = Camera.looking(new Vec3(0, 1.2, 3), new Vec3(0, 0.5, 0));
        int x = W / 2;
        int y = H / 2;
        FrameSlot f = inspected(new ViewState(scene, camera), x, y);
        PixelInspector.Inspection in = f.inspection;
        assertNotNull(in.owner(), "an object under the pixel");
        assertEquals("crate", in.owner().name());
        assertEquals(1, in.owner().draw());
        assertEquals(in.triangle() - ground.triangleCount(), in.owner().triangle(), "counted in the crate's own mesh");
        try (SceneRenderer r = new SceneRenderer(1)) {
            r.render(scene, f.camera, RenderSettings.defaults(), new Framebuffer(W, H));
            Pick pick = r.pick(x, y).orElseThrow();
            assertEquals(crate, pick.object());
            assertEquals(pick.triangle(), in.owner().triangle(), "the triangle picking names");
        }
        List<String> lines = InspectorPainter.lines(in, false);
        assertTrue(lines.stream().anyMatch(l -> l.startsWith("\"crate\" triangle " + in.owner().triangle())),
                lines.toString());
        assertEquals("object 2 triangle 7", InspectorPainter.triangleOf(new DrawnFrame.Owner(null, 1, 7), 99));
    }
}
