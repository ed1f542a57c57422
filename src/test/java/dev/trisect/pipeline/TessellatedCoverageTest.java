package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The tessellated path covers exactly what the per-pixel path covers, with the same depth, so that
 * every pixel shows the same triangle (docs/conventions.md, "The fill: one pass per input
 * triangle"): on built-in scenes, under both split policies, on one and three threads, the depth
 * buffers are equal bit for bit and so are the triangle numbers of the UV output. When pieces were
 * filled one by one, their snapped cut points decided coverage at the input triangles' edges: 8 to 11
 * pixels of these scenes at 640x360 showed another triangle than the per-pixel path.
 */
class TessellatedCoverageTest {
    private static final int W = 640;
    private static final int H = 360;

    @ParameterizedTest
    @ValueSource(strings = {"demo", "boxes", "floor", "sphere"})
    void everyPixelShowsTheTrianglePerPixelShowsAtTheSameDepth(String name) {
        SceneAsset scene = DemoScenes.byName(name).orElseThrow();
        Mat4 viewProjection = scene.camera().viewProjection(new Viewport(W, H));
        RenderSettings base = RenderSettings.defaults();
        TessellationSettings[] policies = {TessellationSettings.defaults(),
                TessellationSettings.defaults().withPolicy(SplitPolicy.ERROR).withMaxError(0.5)};
        for (int threads : new int[] {1, 3}) {
            try (FrameRenderer r = new FrameRenderer(threads)) {
                Framebuffer perPixel = frame(r, scene, viewProjection, base.withMode(RenderMode.PERSPECTIVE));
                long covered = 0;
                for (float d : perPixel.depth()) {
                    covered += d > 0 ? 1 : 0;
                }
                assertTrue(covered > W * H / 4, name + ": covered " + covered);
                for (TessellationSettings policy : policies) {
                    Framebuffer tessellated = frame(r, scene, viewProjection,
                            base.withMode(RenderMode.TESSELLATED).withTessellation(policy));
                    String what = name + ", " + policy.policy() + ", " + threads + " threads";
                    int depthDiffer = 0;
                    int triangleDiffer = 0;
                    for (int i = 0; i < W * H; i++) {
                        depthDiffer += Float.floatToRawIntBits(perPixel.depth()[i])
                                != Float.floatToRawIntBits(tessellated.depth()[i]) ? 1 : 0;
                        triangleDiffer += perPixel.uv()[3 * i + 2] != tessellated.uv()[3 * i + 2] ? 1 : 0;
                    }
                    assertEquals(0, depthDiffer, what + ": pixels of another depth");
                    assertEquals(0, triangleDiffer, what + ": pixels of another triangle");
                }
            }
        }
    }

    private static Framebuffer frame(FrameRenderer r, SceneAsset scene, Mat4 viewProjection, RenderSettings s) {
        Framebuffer fb = new Framebuffer(W, H);
        fb.recordUv(true);
        r.render(scene.mesh(), scene.textureArray(), viewProjection, s, fb);
        return fb;
    }
}
