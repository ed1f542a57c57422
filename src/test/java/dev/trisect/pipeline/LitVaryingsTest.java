package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.light.Lights;
import dev.trisect.light.Surface;
import dev.trisect.math.Mat4;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.raster.PixelState;
import dev.trisect.raster.ScreenTriangles;
import dev.trisect.render.Colour;
import dev.trisect.render.CullMode;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.Shading;
import dev.trisect.render.SplitPolicy;
import dev.trisect.render.TessellationSettings;
import dev.trisect.tessellate.VertexLayout;
import dev.trisect.texture.Texture;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A lit frame's geometry carries each corner's lit colour to the pixel stage, values computed here by
 * hand from OpenGL's equation: as varyings 2..4 (r, g, b) per corner when a material is smooth; once
 * per triangle, as flat values 0..2, when none is (the triangle's last corner's); white for an unlit
 * material; a frame with no lit material keeps the textured layout.
 */
class LitVaryingsTest {
    private static final Texture WHITE = Texture.solid("white", 0xFFFFFFFF);
    private static final RenderSettings SETTINGS = RenderSettings.defaults().withMode(RenderMode.PERSPECTIVE)
            .withCull(CullMode.NONE);
    /** Corners (0, 0, 0), (0.5, 0, 0), (0, 0.5, 0) facing +z, drawn with an identity model-view-projection. */
    private static final double[][] CORNERS = {{0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}};

    private static Mesh triangle() {
        MeshBuilder b = new MeshBuilder();
        b.triangle(b.position(0, 0, 0), b.position(0.5f, 0, 0), b.position(0, 0.5f, 0), -1, -1, -1);
        return b.build();
    }

    /**
     * Ambient 0.1 grey, a point light at (0, 0, 2), diffuse (1, 0, 1), attenuation 1, 0.2, 0.05; the
     * material's diffuse colour (1, 1, 0.5): the expected r, g, b at a corner on the plane z = 0.
     */
    private static double[] expected(double[] p) {
        double lx = -p[0];
        double ly = -p[1];
        double lz = 2 - p[2];
        double d = Math.sqrt(lx * lx + ly * ly + lz * lz);
        double att = 1 / (1 + 0.2 * d + 0.05 * d * d);
        double lambert = lz / d;
        return new double[] {0.1 + att * lambert, 0.1, 0.1 + att * lambert * 0.5};
    }

    /** The r, g, b varyings of every corner of every screen triangle of the frame, in {@code layout}. */
    private static List<double[]> cornerColours(Draws draws, VertexLayout layout) {
        return cornerColours(draws, layout, SETTINGS);
    }

    /**
     * The colour of every corner of every screen triangle (tessellated: every piece, then every split
     * input triangle) of the frame, in {@code layout}: its r, g, b varyings, or its triangle's flat ones.
     */
    private static List<double[]> cornerColours(Draws draws, VertexLayout layout, RenderSettings settings) {
        return cornerColours(new FrameGeometry(1), draws, layout, settings);
    }

    private static List<double[]> cornerColours(FrameGeometry geometry, Draws draws, VertexLayout layout,
                                                RenderSettings settings) {
        List<double[]> out = new ArrayList<>();
        try (WorkerPool pool = new WorkerPool(1, "lit-varyings-test")) {
            FrameGeometry.Result r = geometry.run(draws, settings, 64, 64, pool);
            for (int c = 0; c < r.chunkCount(); c++) {
                for (ScreenTriangles st : List.of(geometry.chunks().get(c).out, geometry.chunks().get(c).trees.inputs())) {
                    assertSame(layout, st.layout());
                    double[] a = st.attributes();
                    for (int k = 0; k < 3 * st.count(); k++) {
                        if (layout.flats() > 0) {
                            double flat = a[k / 3 * st.attributeStride() + st.flatOffset() + PixelState.FLAT_COLOUR];
                            out.add(new double[] {PixelState.flatChannel(flat, 0), PixelState.flatChannel(flat, 1),
                                    PixelState.flatChannel(flat, 2)});
                        } else {
                            int o = k * st.cornerStride() + 1 + PixelState.COLOUR_SLOT;
                            out.add(new double[] {a[o], a[o + 1], a[o + 2]});
                        }
                    }
                }
            }
        }
        return out;
    }

    private static Draws draws(Shading shading, Surface second) {
        Draws draws = new Draws();
        Surface s = new Surface(shading, Colour.WHITE, new Colour(1, 1, 0.5));
        draws.add(triangle(), new Texture[] {WHITE}, Mat4.identity(), Mat4.identity(), new Surface[] {s});
        if (second != null) {
            draws.add(triangle(), new Texture[] {WHITE}, Mat4.identity(), Mat4.identity(), new Surface[] {second});
        }
        draws.setLights(Lights.builder().ambient(0.1, 0.1, 0.1)
                .point(0, 0, 2, new double[3], new double[] {1, 0, 1}, 1, 0.2, 0.05).build());
        return draws;
    }

    private static void assertColour(double[] want, double[] got) {
        assertColour(want, got, 1e-6);
    }

    /**
     * A colour carried once per triangle, packed in 16 fractional bits a channel (PixelState.flatColour):
     * within half a step of them, 2^-17, of the lit colour (plus its float's rounding).
     */
    private static void assertFlatColour(double[] want, double[] got) {
        assertColour(want, got, 0x1p-17 + 1e-6);
    }

    private static void assertColour(double[] want, double[] got, double tolerance) {
        for (int i = 0; i < 3; i++) {
            assertEquals(want[i], got[i], tolerance, "channel " + i);
        }
    }

    @Test
    void smoothCornersCarryTheirOwnColour() {
        List<double[]> got = cornerColours(draws(Shading.SMOOTH, null), FrameGeometry.LIT_LAYOUT);
        assertEquals(3, got.size());
        for (int k = 0; k < 3; k++) {
            assertColour(expected(CORNERS[k]), got.get(k));
        }
    }

    @Test
    void aFlatFrameCarriesTheLastCornersColourOncePerTriangle() {
        List<double[]> got = cornerColours(draws(Shading.FLAT, null), FrameGeometry.FLAT_LIT_LAYOUT);
        assertEquals(3, got.size());
        for (double[] c : got) {
            assertFlatColour(expected(CORNERS[2]), c);
        }
    }

    @Test
    void flatCornersBesideASmoothMaterialAllCarryTheLastCornersColour() {
        Surface smooth = new Surface(Shading.SMOOTH, Colour.WHITE, new Colour(1, 1, 0.5));
        List<double[]> got = cornerColours(draws(Shading.FLAT, smooth), FrameGeometry.LIT_LAYOUT);
        assertEquals(6, got.size());
        for (int k = 0; k < 3; k++) {
            assertColour(expected(CORNERS[2]), got.get(k));
            assertColour(expected(CORNERS[k]), got.get(3 + k));
        }
    }

    @Test
    void aFlatFrameAfterASmoothOneUnderTheSameLightsCarriesItsColour() {
        // The vertex colours are kept between the two frames (same lights, meshes and factors); only
        // the flat frame needs them packed.
        FrameGeometry geometry = new FrameGeometry(1);
        cornerColours(geometry, draws(Shading.SMOOTH, null), FrameGeometry.LIT_LAYOUT, SETTINGS);
        List<double[]> got = cornerColours(geometry, draws(Shading.FLAT, null), FrameGeometry.FLAT_LIT_LAYOUT,
                SETTINGS);
        assertEquals(3, got.size());
        for (double[] c : got) {
            assertFlatColour(expected(CORNERS[2]), c);
        }
    }

    @Test
    void aFlatFramesPiecesAndSplitTrianglesKeepTheirTrianglesColour() {
        // Split into many pieces: edges of at most 2 pixels over a triangle 16 pixels wide.
        RenderSettings split = SETTINGS.withMode(RenderMode.TESSELLATED).withTessellation(
                TessellationSettings.defaults().withPolicy(SplitPolicy.EDGE).withMaxEdge(2));
        Draws draws = draws(Shading.FLAT, null);
        List<double[]> got = cornerColours(draws, FrameGeometry.FLAT_LIT_LAYOUT, split);
        assertTrue(got.size() > 6, "pieces and a split input triangle");
        for (double[] c : got) {
            assertFlatColour(expected(CORNERS[2]), c);
        }
    }

    @Test
    void theInspectorFindsAFlatFramesColourAtEveryCorner() {
        Framebuffer frame = new Framebuffer(64, 64);
        frame.recordUv(true);
        try (FrameRenderer r = new FrameRenderer(1)) {
            r.render(draws(Shading.FLAT, null), SETTINGS, frame);
            // NDC (0.1, 0.1) lies inside the triangle: pixel (35, 28) of 64 x 64, y down.
            int x = 35;
            int y = 28;
            int id = frame.ids()[y * 64 + x] - 1;
            assertEquals(0, id, "the triangle covers the pixel");
            PieceInfo piece = r.drawn().pieceAt(x, y, id, frame.depth()[y * 64 + x]);
            for (int k = 0; k < 3; k++) {
                assertFlatColour(expected(CORNERS[2]), java.util.Arrays.copyOfRange(piece.colours(), 3 * k, 3 * k + 3));
            }
        }
    }

    @Test
    void anUnlitMaterialInALitFrameIsWhite() {
        List<double[]> got = cornerColours(draws(Shading.SMOOTH, Surface.UNLIT), FrameGeometry.LIT_LAYOUT);
        assertEquals(6, got.size());
        for (int k = 3; k < 6; k++) {
            assertColour(new double[] {1, 1, 1}, got.get(k));
        }
        got = cornerColours(draws(Shading.FLAT, Surface.UNLIT), FrameGeometry.FLAT_LIT_LAYOUT);
        assertEquals(6, got.size());
        for (int k = 3; k < 6; k++) {
            assertFlatColour(new double[] {1, 1, 1}, got.get(k));
        }
    }

    @Test
    void aFrameWithoutLitMaterialsKeepsTheTexturedLayout() {
        Draws draws = new Draws();
        draws.add(triangle(), new Texture[] {WHITE}, Mat4.identity());
        draws.setLights(Lights.builder().ambient(1, 1, 1).build());
        FrameGeometry geometry = new FrameGeometry(1);
        try (WorkerPool pool = new WorkerPool(1, "lit-varyings-test")) {
            geometry.run(draws, SETTINGS, 64, 64, pool);
        }
        assertSame(VertexLayout.TEXTURED, geometry.chunks().get(0).out.layout());
    }
}
