package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.tessellate.VertexLayout;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The clipper interpolates every varying of a vertex layout: with copies of s and t in slots 2 and 3
 * and a constant in slot 4, each clipped vertex holds the very bits of its s and t in the copies, and
 * the constant unchanged up to rounding of an interpolation between equal values (exactly).
 */
class ClipperVaryingsTest {
    @Test
    void everySlotOfAClippedVertexIsInterpolated() {
        VertexLayout layout = VertexLayout.of(5);
        int cs = layout.clipStride();
        Clipper clipper = new Clipper();
        clipper.layout(layout);
        clipper.guardBand(1.5, 1.5);
        Random random = new Random(28);
        int clipped = 0;
        for (int n = 0; n < 2000; n++) {
            double[] v = new double[3 * cs];
            for (int k = 0; k < 3; k++) {
                int o = k * cs;
                v[o + VertexLayout.X] = 6 * random.nextDouble() - 3;
                v[o + VertexLayout.Y] = 6 * random.nextDouble() - 3;
                v[o + VertexLayout.Z] = 4 * random.nextDouble() - 2;
                v[o + VertexLayout.W] = 2 * random.nextDouble() - 0.5;
                v[o + VertexLayout.S] = 100 * random.nextGaussian();
                v[o + VertexLayout.T] = 100 * random.nextGaussian();
                v[o + VertexLayout.varying(2)] = v[o + VertexLayout.S];
                v[o + VertexLayout.varying(3)] = v[o + VertexLayout.T];
                v[o + VertexLayout.varying(4)] = -3.5;
            }
            int planes = clipper.clipCode(v[0], v[1], v[2], v[3])
                    | clipper.clipCode(v[cs], v[cs + 1], v[cs + 2], v[cs + 3])
                    | clipper.clipCode(v[2 * cs], v[2 * cs + 1], v[2 * cs + 2], v[2 * cs + 3]);
            int m = clipper.clip(v, 0, cs, 2 * cs, planes);
            double[] out = clipper.vertices();
            for (int k = 0; k < m; k++) {
                int o = k * cs;
                assertEquals(out[o + VertexLayout.S], out[o + VertexLayout.varying(2)], "s copy");
                assertEquals(out[o + VertexLayout.T], out[o + VertexLayout.varying(3)], "t copy");
                assertEquals(-3.5, out[o + VertexLayout.varying(4)], "constant");
            }
            clipped += planes != 0 && m > 0 ? 1 : 0;
        }
        assertTrue(clipped > 300, "triangles clipped: " + clipped);
    }
}
