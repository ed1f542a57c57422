package dev.trisect.pipeline;

import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Framebuffer;
import dev.trisect.scene.Camera;
import dev.trisect.render.SplitPoint;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.Texture;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Tessellated tiled and closed meshes: no background pixel inside the silhouette, no pixel covered
 * twice.
 */
class NoCracksTest {
    private static final int W = 256;
    private static final int H = 192;
    private static final FrameRenderer RENDERER = new FrameRenderer(2);
    private static final Texture[] TEX = {TestScenes.distinctTexels()};

    @AfterAll
    static void close() {
        RENDERER.close();
    }

    static Stream<Arguments> cases() {
        MeshBuilder closed = new MeshBuilder();
        Primitives.sphere(closed, new Vec3(-1.2, 1, -5), 1.3, 17, 9);
        Primitives.box(closed, new Vec3(1.6, 0.8, -6), new Vec3(1.5, 1.6, 2.5));
        Mesh shapes = closed.build();
        Camera shapesCam = new Camera(new Vec3(0.4, 2.2, 0.5), new Vec3(0, 0.8, -5.5), Vec3.UP, 60, 0.1, 100);
        Mesh grid = TestScenes.floor(13);
        Camera gridCam = TestScenes.floorCamera();
        TessellationSettings base = TessellationSettings.defaults();
        return Stream.of(
                Arguments.of("tiled floor, edge 8", grid, gridCam, base.withMaxEdge(8)),
                Arguments.of("tiled floor, edge 3", grid, gridCam, base.withMaxEdge(3)),
                Arguments.of("tiled floor, error 0.2", grid, gridCam,
                        base.withPolicy(SplitPolicy.ERROR).withMaxError(0.2)),
                Arguments.of("tiled floor, depth cap 3", grid, gridCam, base.withMaxEdge(1).withMaxDepth(3)),
                Arguments.of("sphere and box, edge 5", shapes, shapesCam, base.withMaxEdge(5)),
                Arguments.of("sphere and box, error 0.05", shapes, shapesCam,
                        base.withPolicy(SplitPolicy.ERROR).withMaxError(0.05)),
                // The default cuts at the screen midpoint; the other split points must tile as well.
                Arguments.of("tiled floor, edge 3, 3D midpoint", grid, gridCam,
                        base.withMaxEdge(3).withSplitPoint(SplitPoint.MIDPOINT)),
                Arguments.of("tiled floor, error 0.2, geometric mean depth", grid, gridCam,
                        base.withPolicy(SplitPolicy.ERROR).withMaxError(0.2).withSplitPoint(SplitPoint.GEOMETRIC)),
                Arguments.of("sphere and box, error 0.05, geometric mean depth", shapes, shapesCam,
                        base.withPolicy(SplitPolicy.ERROR).withMaxError(0.05).withSplitPoint(SplitPoint.GEOMETRIC)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void tessellatedSurfaceHasNoGapsAndNoOverlaps(String name, Mesh mesh, Camera camera, TessellationSettings t) {
        var vp = camera.viewProjection(new Viewport(W, H));
        RenderSettings whole = RenderSettings.defaults().withMode(RenderMode.PERSPECTIVE);
        int[] silhouette = RENDERER.coverage(mesh, TEX, vp, whole, W, H);
        int[] pieces = RENDERER.coverage(mesh, TEX, vp, whole.withMode(RenderMode.TESSELLATED).withTessellation(t), W, H);
        int inside = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int i = y * W + x;
                assertTrue(silhouette[i] <= 1, name + ": the unsplit mesh covers " + x + "," + y + " twice");
                assertTrue(pieces[i] <= 1, name + ": pixel " + x + "," + y + " covered " + pieces[i] + " times");
                // Split vertices snap to the 1/256 grid, so the outline may move by that much; a pixel
                // whose 8 neighbours are all inside the unsplit silhouette must be covered.
                if (deepInside(silhouette, x, y)) {
                    inside++;
                    assertEquals(1, pieces[i], name + ": crack at " + x + "," + y);
                }
            }
        }
        assertTrue(inside > W * H / 10, name + ": the surface fills enough of the frame to mean something");
    }

    private static boolean deepInside(int[] c, int x, int y) {
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) {
                int nx = x + dx;
                int ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= W || ny >= H || c[ny * W + nx] == 0) {
                    return false;
                }
            }
        }
        return true;
    }

    @Test
    void imagesDoNotDependOnTheNumberOfThreads() {
        Mesh mesh = TestScenes.floor(13);
        Camera cam = TestScenes.floorCamera();
        for (RenderMode mode : RenderMode.values()) {
            RenderSettings s = RenderSettings.defaults().withMode(mode).withBorders(true)
                    .withTessellation(TessellationSettings.defaults().withMaxEdge(6));
            Framebuffer one;
            try (FrameRenderer single = new FrameRenderer(1)) {
                one = TestScenes.render(single, mesh, cam, s, W, H);
            }
            Framebuffer many;
            try (FrameRenderer three = new FrameRenderer(3)) {
                many = TestScenes.render(three, mesh, cam, s, W, H);
            }
            assertArrayEquals(one.colour(), many.colour(), mode.id());
            assertArrayEquals(one.uv(), many.uv(), mode.id());
        }
    }
}
