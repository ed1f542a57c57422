package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.light.Lights;
import dev.trisect.light.Surface;
import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.mesh.Primitives;
import dev.trisect.raster.PixelState;
import dev.trisect.render.Colour;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.Shading;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.scene.Camera;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * Frames drawn from lit copies of textures ({@code LitTextures}) are the frames drawn without them, bit
 * for bit — colour, depth, UV output and ids — on every path, opaque, alpha-tested and blended, flat
 * and smooth; and the copies were drawn from (the frames would be equal, and prove nothing, if not).
 */
class LitTexturesFrameTest {
    static final int W = 160;
    static final int H = 120;
    private static final RenderSettings BASE = RenderSettings.defaults();
    static final RenderSettings[] PATHS = {BASE.withMode(RenderMode.PERSPECTIVE),
        BASE.withMode(RenderMode.AFFINE), BASE.withMode(RenderMode.SPANS).withKnotError(0.5),
        BASE.withMode(RenderMode.TESSELLATED).withTessellation(TessellationSettings.defaults()
                .withPolicy(SplitPolicy.ERROR).withMaxError(0.5))};

    /** A texture of distinct texels whose alpha runs through 0..255, {@code w x h}. */
    private static Texture texture(String name, int w, int h, int seed) {
        int[] px = new int[w * h];
        for (int i = 0; i < px.length; i++) {
            px[i] = (i * 37 + seed) % 256 << 24 | (i + seed) * 0x9E3779B1 >>> 8;
        }
        return new Texture(name, w, h, px);
    }

    /** A floor (64x64 texture), three crates (48x40: not powers of two) and a smooth-shaded globe. */
    static final Texture[] TEXTURES = {texture("floor", 64, 64, 1), texture("crate", 48, 40, 2),
        texture("globe", 32, 32, 3)};
    static final Mesh MESH = mesh();

    private static Mesh mesh() {
        MeshBuilder b = new MeshBuilder();
        b.material("floor");
        Primitives.floor(b, -20, 20, -60, 5, 0, 8, 8, 4);
        b.material("crate");
        Primitives.box(b, new Vec3(0, 1, -6), new Vec3(2, 2, 2));
        Primitives.box(b, new Vec3(2.6, 0.6, -4), new Vec3(1.2, 1.2, 1.2));
        Primitives.box(b, new Vec3(-2.2, 0.75, -3.5), new Vec3(1.5, 1.5, 1.5));
        b.material("globe");
        Primitives.sphere(b, new Vec3(-3, 1.6, -9), 1.6, 16, 8);
        return b.build();
    }

    static final Mat4 VIEW_PROJECTION = new Camera(new Vec3(0.5, 1.8, 6), new Vec3(0, 1, -10), Vec3.UP,
            60, 0.1, 1000).viewProjection(new Viewport(W, H));

    private static Framebuffer frame(FrameRenderer r, RenderSettings s, Shading shading, int write) {
        return frame(r, s, shading, write, true);
    }

    /** The frame, with the UV output (and ids) recorded or not: the loops differ by it. */
    private static Framebuffer frame(FrameRenderer r, RenderSettings s, Shading shading, int write, boolean uv) {
        Draws draws = new Draws();
        Surface[] surfaces = new Surface[3];
        Arrays.fill(surfaces, new Surface(shading, Colour.WHITE, Colour.WHITE));
        int[] states = new int[3];
        Arrays.fill(states, write);
        draws.add(MESH, TEXTURES, states, VIEW_PROJECTION, Mat4.identity(), surfaces);
        draws.setLights(Lights.builder().ambient(0.2, 0.2, 0.2)
                .directional(0.3, -1, -0.5, new double[3], new double[] {1, 0.9, 0.7}).build());
        Framebuffer fb = new Framebuffer(W, H);
        fb.recordUv(uv);
        r.render(draws, s, fb);
        return fb;
    }

    private static void assertSameFrame(Framebuffer expected, Framebuffer actual, String what) {
        assertArrayEquals(expected.colour(), actual.colour(), what + ": colour");
        assertArrayEquals(expected.depth(), actual.depth(), what + ": depth");
        assertArrayEquals(expected.uv(), actual.uv(), what + ": UV output");
        assertArrayEquals(expected.ids(), actual.ids(), what + ": ids");
    }

    @Test
    void framesFromTheCopiesAreTheFramesWithout() {
        int[] writes = {PixelState.OPAQUE, PixelState.ALPHA_TEST, PixelState.BLEND};
        try (FrameRenderer cached = new FrameRenderer(2); FrameRenderer plain = new FrameRenderer(2)) {
            plain.cacheLitTextures(false);
            for (RenderSettings path : PATHS) {
                for (Shading shading : new Shading[] {Shading.FLAT, Shading.SMOOTH}) {
                    for (int write : writes) {
                        for (boolean uv : new boolean[] {true, false}) {
                            String what = path.mode() + " " + shading + " write " + write + (uv ? " uv" : "");
                            // The third frame draws from the copies built after the second.
                            for (int f = 0; f < 2; f++) {
                                frame(cached, path, shading, write, uv);
                            }
                            Framebuffer lit = frame(cached, path, shading, write, uv);
                            assertTrue(cached.litTextures().hits() > 0, what + ": drawn from the copies");
                            assertSameFrame(frame(plain, path, shading, write, uv), lit, what);
                            assertEquals(0, plain.litTextures().size(),
                                    "the renderer without the cache builds nothing");
                        }
                    }
                }
            }
        }
    }

    @Test
    void filteredFramesKeepTheModulatingLoops() {
        try (FrameRenderer cached = new FrameRenderer(2); FrameRenderer plain = new FrameRenderer(1)) {
            plain.cacheLitTextures(false);
            for (TextureFilter filter : new TextureFilter[] {TextureFilter.BILINEAR, TextureFilter.TRILINEAR}) {
                for (RenderSettings path : PATHS) {
                    RenderSettings s = path.withFilter(filter);
                    for (int f = 0; f < 3; f++) {
                        frame(cached, s, Shading.FLAT, PixelState.OPAQUE);
                    }
                    assertEquals(0, cached.litTextures().hits(), filter + " " + path.mode());
                    assertSameFrame(frame(plain, s, Shading.FLAT, PixelState.OPAQUE),
                            frame(cached, s, Shading.FLAT, PixelState.OPAQUE), filter + " " + path.mode());
                }
            }
        }
    }
}
