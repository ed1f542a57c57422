package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.light.Lights;
import dev.trisect.light.Surface;
import dev.trisect.math.Mat4;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Colour;
import dev.trisect.render.Shading;
import dev.trisect.texture.Texture;
import org.junit.jupiter.api.Test;

/** The per-vertex stage: which vertex each corner takes, and its colour, on hand-computed cases. */
class VertexColoursTest {
    private static final Texture WHITE = Texture.solid("white", 0xFFFFFFFF);
    private static final double[] NO = {0, 0, 0};

    private static float[] colour(VertexColours v, int d, int corner, boolean flat) {
        int i = v.index(d, corner, flat);
        return new float[] {v.colours()[i], v.colours()[i + 1], v.colours()[i + 2]};
    }

    /** One triangle in the plane z = 0 facing +z, with corners at x = 0, 1, 0 and y = 0, 0, 1. */
    private static Mesh triangle() {
        MeshBuilder b = new MeshBuilder();
        b.triangle(b.position(0, 0, 0), b.position(1, 0, 0), b.position(0, 1, 0), -1, -1, -1);
        return b.build();
    }

    @Test
    void unlitDrawsComputeNothing() {
        Draws draws = new Draws();
        draws.add(triangle(), new Texture[] {WHITE}, Mat4.identity());
        draws.setLights(Lights.builder().ambient(1, 1, 1).build());
        VertexColours v = new VertexColours();
        try (WorkerPool pool = new WorkerPool(1, "vc-test")) {
            v.compute(draws, pool);
        }
        assertFalse(v.lit());
    }

    @Test
    void pointLightPerCornerAndFlatTakesTheLastCorner() {
        // A point light 2 above the origin, attenuation 1, 0.2, 0.05, red diffuse; the triangle faces it.
        Draws draws = new Draws();
        Surface smooth = new Surface(Shading.SMOOTH, Colour.WHITE, new Colour(1, 1, 0.5));
        draws.add(triangle(), new Texture[] {WHITE}, Mat4.identity(), Mat4.identity(), new Surface[] {smooth});
        draws.setLights(Lights.builder().ambient(0.1, 0.1, 0.1)
                .point(0, 0, 2, NO, new double[] {1, 0, 1}, 1, 0.2, 0.05).build());
        VertexColours v = new VertexColours();
        try (WorkerPool pool = new WorkerPool(2, "vc-test")) {
            v.compute(draws, pool);
        }
        assertTrue(v.lit());
        // Corner 0 at the origin: d = 2, N·L = 1, att = 1 / (1 + 0.4 + 0.2).
        float[] c0 = colour(v, 0, 0, false);
        assertEquals(0.1 + 1 / 1.6, c0[0], 1e-6);
        assertEquals(0.1, c0[1], 1e-6);
        assertEquals(0.1 + 0.5 / 1.6, c0[2], 1e-6);
        // Corner 2 at (0, 1, 0): d = √5, N·L = 2 / √5.
        double d = Math.sqrt(5);
        double att = 1 / (1 + 0.2 * d + 0.05 * 5);
        float[] c2 = colour(v, 0, 2, false);
        assertEquals(0.1 + att * 2 / d, c2[0], 1e-6);
        // Flat: every corner takes corner 2's colour.
        for (int k = 0; k < 3; k++) {
            assertEquals(c2[0], colour(v, 0, k, true)[0]);
        }
    }

    @Test
    void normalsGoThroughTheNormalMatrixUnderNonUniformScale() {
        // The plane x + y = 0 tilted 45°, its normal (1, 1, 0)/√2; scaled by 2 in x it becomes the plane
        // x/2 + y = 0, whose normal is (1, 2, 0)/√5 — not the normal scaled like a point, (2, 1, 0)/√5.
        MeshBuilder b = new MeshBuilder();
        int n = b.normal(1, 1, 0);
        b.triangle(b.position(1, -1, 0), b.position(0, 0, 1), b.position(-1, 1, 0), -1, -1, -1, n, n, n);
        Mesh mesh = b.build();
        Draws draws = new Draws();
        Surface lit = new Surface(Shading.SMOOTH, Colour.WHITE, Colour.WHITE);
        draws.add(mesh, new Texture[] {WHITE}, Mat4.identity(), Mat4.ofRows(2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1),
                new Surface[] {lit});
        draws.setLights(Lights.builder().directional(0, 1, 0, NO, new double[] {1, 1, 1}).build());
        VertexColours v = new VertexColours();
        try (WorkerPool pool = new WorkerPool(1, "vc-test")) {
            v.compute(draws, pool);
        }
        assertEquals(2 / Math.sqrt(5), colour(v, 0, 1, false)[0], 1e-6);
    }

    @Test
    void cornersSharingPositionNormalAndMaterialShareAVertex() {
        Mesh sphere = Primitives.sphere(1, 8, 6);
        Draws draws = new Draws();
        Surface lit = new Surface(Shading.SMOOTH, Colour.WHITE, Colour.WHITE);
        draws.add(sphere, new Texture[] {WHITE}, Mat4.identity(), Mat4.identity(), new Surface[] {lit});
        draws.add(sphere, new Texture[] {WHITE}, Mat4.identity(), Mat4.identity(), new Surface[] {lit});
        draws.setLights(Lights.builder().directional(0, 1, 0, NO, new double[] {1, 1, 1}).build());
        VertexColours v = new VertexColours();
        try (WorkerPool pool = new WorkerPool(1, "vc-test")) {
            v.compute(draws, pool);
        }
        int[] cp = sphere.cornerPositions();
        int[] cn = sphere.cornerNormals();
        for (int a = 0; a < cp.length; a++) {
            for (int b = 0; b < cp.length; b++) {
                boolean same = cp[a] == cp[b] && cn[a] == cn[b] && cn[a] >= 0;
                if (same) {
                    assertEquals(v.index(0, a, false), v.index(0, b, false));
                }
            }
            // The second draw has vertices of its own, with the same colours.
            assertEquals(colour(v, 0, a, false)[0], colour(v, 1, a, false)[0]);
        }
    }

    @Test
    void coloursAreKeptWhileLightsWorldsAndMaterialsStayAndFollowAnyChange() {
        Mesh mesh = triangle();
        Lights front = Lights.builder().directional(0, 0, 1, NO, new double[] {1, 1, 1}).build();
        Lights above = Lights.builder().directional(0, 1, 1, NO, new double[] {1, 1, 1}).build();
        Mat4 still = Mat4.identity();
        Mat4 turned = Mat4.ofRows(1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1); // the normal +z becomes -y
        Colour grey = new Colour(0.5, 0.5, 0.5);
        // Each frame's lights, world and diffuse colour, and corner 0's red: Lambert's N·L times the diffuse.
        Object[][] frames = {
            {front, still, Colour.WHITE, 1.0},
            {front, still, Colour.WHITE, 1.0},
            {above, still, Colour.WHITE, 1 / Math.sqrt(2)},
            {above, turned, Colour.WHITE, 0.0},
            {front, still, Colour.WHITE, 1.0},
            {front, still, grey, 0.5},
        };
        VertexColours v = new VertexColours();
        Draws draws = new Draws();
        try (WorkerPool pool = new WorkerPool(1, "vc-test")) {
            for (int i = 0; i < frames.length; i++) {
                Object[] f = frames[i];
                draws.clear();
                draws.add(mesh, new Texture[] {WHITE}, Mat4.identity(), (Mat4) f[1],
                        new Surface[] {new Surface(Shading.SMOOTH, Colour.WHITE, (Colour) f[2])});
                draws.setLights((Lights) f[0]);
                v.compute(draws, pool);
                assertEquals((double) f[3], colour(v, 0, 0, false)[0], 1e-6, "frame " + i);
            }
        }
    }
}
