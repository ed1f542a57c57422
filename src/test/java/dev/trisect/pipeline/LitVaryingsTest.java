package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import dev.trisect.light.Lights;
import dev.trisect.light.Surface;
import dev.trisect.math.Mat4;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.raster.ScreenTriangles;
import dev.trisect.render.Colour;
import dev.trisect.render.CullMode;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.Shading;
import dev.trisect.tessellate.VertexLayout;
import dev.trisect.texture.Texture;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A lit frame's geometry carries each corner's lit colour to the pixel stage as varyings 2..4 (r, g,
 * b), values computed here by hand from OpenGL's equation: per corner with smooth shading, the
 * triangle's last corner's in all three with flat shading, white for an unlit material; a frame with
 * no lit material keeps the textured layout.
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

    /** The r, g, b varyings of every corner of every screen triangle of the frame. */
    private static List<double[]> cornerColours(Draws draws) {
        FrameGeometry geometry = new FrameGeometry(1);
        List<double[]> out = new ArrayList<>();
        try (WorkerPool pool = new WorkerPool(1, "lit-varyings-test")) {
            FrameGeometry.Result r = geometry.run(draws, SETTINGS, 64, 64, pool);
            for (int c = 0; c < r.chunkCount(); c++) {
                ScreenTriangles st = geometry.chunks().get(c).out;
                assertSame(FrameGeometry.LIT_LAYOUT, st.layout());
                double[] a = st.attributes();
                for (int k = 0; k < 3 * st.count(); k++) {
                    int o = k * st.cornerStride() + 1 + ChunkGeometry.COLOUR_SLOT;
                    out.add(new double[] {a[o], a[o + 1], a[o + 2]});
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
        for (int i = 0; i < 3; i++) {
            assertEquals(want[i], got[i], 1e-6, "channel " + i);
        }
    }

    @Test
    void smoothCornersCarryTheirOwnColour() {
        List<double[]> got = cornerColours(draws(Shading.SMOOTH, null));
        assertEquals(3, got.size());
        for (int k = 0; k < 3; k++) {
            assertColour(expected(CORNERS[k]), got.get(k));
        }
    }

    @Test
    void flatCornersAllCarryTheLastCornersColour() {
        List<double[]> got = cornerColours(draws(Shading.FLAT, null));
        assertEquals(3, got.size());
        for (double[] c : got) {
            assertColour(expected(CORNERS[2]), c);
        }
    }

    @Test
    void anUnlitMaterialInALitFrameIsWhite() {
        List<double[]> got = cornerColours(draws(Shading.SMOOTH, Surface.UNLIT));
        assertEquals(6, got.size());
        for (int k = 3; k < 6; k++) {
            assertColour(new double[] {1, 1, 1}, got.get(k));
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
