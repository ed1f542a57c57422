package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.light.Lights;
import dev.trisect.light.Surface;
import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Colour;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.Shading;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureFilter;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * A flat-shaded triangle's pixels do not depend on how its colour travels: a frame whose lit materials
 * are all flat carries each triangle's colour once ({@link FrameGeometry#FLAT_LIT_LAYOUT}), and the same
 * frame with a smooth material beside it (drawn out of view, so it adds no pixel) carries it in every
 * corner ({@link FrameGeometry#LIT_LAYOUT}); the two are the same bit for bit — colour, depth, UV
 * output and ids — on every path and filter, with and without lit copies of textures. The paths,
 * textures and view are {@link LitTexturesFrameTest}'s.
 */
class FlatColourFrameTest {
    private static final int W = LitTexturesFrameTest.W;
    private static final int H = LitTexturesFrameTest.H;
    private static final RenderSettings[] PATHS = LitTexturesFrameTest.PATHS;
    private static final Texture[] TEXTURES = LitTexturesFrameTest.TEXTURES;
    private static final Mat4 VIEW_PROJECTION = LitTexturesFrameTest.VIEW_PROJECTION;
    /** {@link LitTexturesFrameTest}'s floor, crates and globe. */
    private static final Mesh MESH = LitTexturesFrameTest.MESH;
    private static final Mesh MORE = more();

    /** A crate around the eye (clipped by the near plane) and a lit globe of smaller triangles. */
    private static Mesh more() {
        MeshBuilder b = new MeshBuilder();
        b.material("crate");
        Primitives.box(b, new Vec3(0.5, 1.8, 5.95), new Vec3(1, 1, 1));
        b.material("globe");
        Primitives.sphere(b, new Vec3(3, 2.2, -12), 1.6, 32, 16);
        return b.build();
    }

    /** One triangle behind the camera: culled, it adds nothing to the frame but its material. */
    private static Mesh behind() {
        MeshBuilder b = new MeshBuilder();
        b.triangle(b.position(0, 0, 20), b.position(1, 0, 20), b.position(0, 1, 20), -1, -1, -1);
        return b.build();
    }

    private static Draws draws(boolean smoothBeside) {
        Draws draws = new Draws();
        Surface[] surfaces = new Surface[3];
        Arrays.fill(surfaces, new Surface(Shading.FLAT, new Colour(0.9, 0.8, 0.7), Colour.WHITE));
        surfaces[2] = Surface.UNLIT; // an unlit material in a lit frame: white
        draws.add(MESH, TEXTURES, VIEW_PROJECTION, Mat4.identity(), surfaces);
        draws.add(MORE, new Texture[] {TEXTURES[1], TEXTURES[2]}, VIEW_PROJECTION, Mat4.identity(),
                new Surface[] {surfaces[0], surfaces[0]});
        if (smoothBeside) {
            draws.add(behind(), new Texture[] {TEXTURES[0]}, VIEW_PROJECTION, Mat4.identity(),
                    new Surface[] {new Surface(Shading.SMOOTH, Colour.WHITE, Colour.WHITE)});
        }
        draws.setLights(Lights.builder().ambient(0.2, 0.2, 0.2)
                .directional(0.3, -1, -0.5, new double[3], new double[] {1, 0.9, 0.7})
                .point(1, 3, -2, new double[3], new double[] {0.6, 0.7, 1}, 1, 0.2, 0.05).build());
        return draws;
    }

    private static Framebuffer frame(FrameRenderer r, RenderSettings s, boolean smoothBeside) {
        Framebuffer fb = new Framebuffer(W, H);
        fb.recordUv(true);
        // The third frame draws from the lit copies built after the second (when the renderer keeps them).
        for (int f = 0; f < 3; f++) {
            r.render(draws(smoothBeside), s, fb);
        }
        return fb;
    }

    @Test
    void aFlatTrianglesPixelsAreTheSameWhetherItsColourTravelsOnceOrPerCorner() {
        assertFalse(draws(false).anySmooth(), "all flat: the colour once per triangle");
        assertTrue(draws(true).anySmooth(), "a smooth material beside: the colour per corner");
        try (FrameRenderer once = new FrameRenderer(2); FrameRenderer corners = new FrameRenderer(2)) {
            for (boolean copies : new boolean[] {true, false}) {
                once.cacheLitTextures(copies);
                corners.cacheLitTextures(copies);
                for (RenderSettings path : PATHS) {
                    for (TextureFilter filter : TextureFilter.values()) {
                        RenderSettings s = path.withFilter(filter);
                        String what = path.mode() + " " + filter + (copies ? " with lit copies" : "");
                        Framebuffer a = frame(once, s, false);
                        Framebuffer b = frame(corners, s, true);
                        assertArrayEquals(b.colour(), a.colour(), what + ": colour");
                        assertArrayEquals(b.depth(), a.depth(), what + ": depth");
                        assertArrayEquals(b.uv(), a.uv(), what + ": UV output");
                        assertArrayEquals(b.ids(), a.ids(), what + ": ids");
                    }
                }
            }
        }
    }
}
