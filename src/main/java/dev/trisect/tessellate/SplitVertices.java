package dev.trisect.tessellate;

import static dev.trisect.tessellate.VertexLayout.W;
import static dev.trisect.tessellate.VertexLayout.X;
import static dev.trisect.tessellate.VertexLayout.Y;

import dev.trisect.math.Viewport;
import dev.trisect.render.SplitPoint;
import java.util.Arrays;

/**
 * The {@link Tessellator}'s vertex pool for one input triangle: its corners and the cut points of its
 * splits, each in the {@link VertexLayout}'s projected form (clip position, varyings, screen
 * position), addressed by offset into {@link #array()}; and what the split policy asks of them — an
 * edge's measure, whether a piece is a sliver or off screen. Cut points are made symmetric in the
 * edge's two ends bit for bit (see {@link #cut}), which is what keeps shared edges free of cracks.
 * Storage grows to its working size and is kept; one instance per tessellator.
 */
final class SplitVertices {
    /** Vertices in the layout last set, {@link VertexLayout#projectedStride()} doubles each. */
    private double[] vertices = new double[VertexLayout.PROJECTED_STRIDE * 256];
    /** The layout's clip stride, projected stride and screen offsets. */
    private int clipStride = VertexLayout.CLIP_STRIDE;
    private int stride = VertexLayout.PROJECTED_STRIDE;
    private int screenX = VertexLayout.SCREEN_X;
    private int screenY = VertexLayout.SCREEN_Y;
    private int count;
    private Viewport viewport = new Viewport(1, 1);
    private double width = 1;
    private double height = 1;
    private SplitPoint splitPoint = SplitPoint.SCREEN;

    /** Sets the frame's viewport and where edges are cut, for the triangles that follow. */
    void configure(Viewport frame, SplitPoint point) {
        viewport = frame;
        width = frame.width();
        height = frame.height();
        splitPoint = point;
    }

    /** Sets the layout of the vertices that follow. */
    void layout(VertexLayout layout) {
        clipStride = layout.clipStride();
        stride = layout.projectedStride();
        screenX = layout.screenX();
        screenY = layout.screenY();
    }

    /** The offset of a vertex's screen x from its own offset (screen y follows it). */
    int screenX() {
        return screenX;
    }

    /** The vertices; a {@link #load} or {@link #cut} may replace the array. */
    double[] array() {
        return vertices;
    }

    /** Forgets every vertex, for a new input triangle. */
    void clear() {
        count = 0;
    }

    /** Copies the clip-space vertex at {@code offset} of {@code input} in and projects it; returns its offset. */
    int load(double[] input, int offset) {
        int o = reserve();
        VertexLayout.copy(input, offset, vertices, o, clipStride);
        project(o);
        return o;
    }

    /**
     * The cut point of edge a-b as a new vertex: {@code (a * ka + b * kb) / (ka + kb)} in clip space
     * and every varying, a point of the 3D edge, with weights from the view depths (see
     * {@link SplitPoint}). Symmetric in a and b bit for bit.
     */
    int cut(int a, int b) {
        int o = reserve();
        double[] v = vertices;
        double ka;
        double kb;
        switch (splitPoint) {
            case SCREEN -> {
                ka = v[b + W];
                kb = v[a + W];
            }
            case GEOMETRIC -> {
                ka = Math.sqrt(v[b + W]);
                kb = Math.sqrt(v[a + W]);
            }
            default -> {
                ka = 1;
                kb = 1;
            }
        }
        double sum = ka + kb;
        for (int k = 0; k < clipStride; k++) {
            v[o + k] = (v[a + k] * ka + v[b + k] * kb) / sum;
        }
        project(o);
        return o;
    }

    /** Edge a-b's measure: its squared screen length, or with {@code error} the affine error bound in pixels. */
    double measure(int a, int b, boolean error) {
        double[] v = vertices;
        double dx = v[a + screenX] - v[b + screenX];
        double dy = v[a + screenY] - v[b + screenY];
        double lengthSquared = dx * dx + dy * dy;
        if (!error) {
            return lengthSquared;
        }
        return EdgeBound.affineError(Math.sqrt(lengthSquared), v[a + W], v[b + W]);
    }

    /** Whether the piece a, b, c is a sliver ({@link Slivers#sliver}), by its corners' screen positions. */
    boolean thin(int a, int b, int c) {
        double[] v = vertices;
        return Slivers.sliver(v[a + screenX], v[a + screenY], v[b + screenX], v[b + screenY], v[c + screenX],
                v[c + screenY]);
    }

    /** Whether the screen bounding box of the piece a, b, c misses the viewport entirely. */
    boolean offScreen(int a, int b, int c) {
        double[] v = vertices;
        double xa = v[a + screenX];
        double xb = v[b + screenX];
        double xc = v[c + screenX];
        double ya = v[a + screenY];
        double yb = v[b + screenY];
        double yc = v[c + screenY];
        return (xa < 0 && xb < 0 && xc < 0) || (ya < 0 && yb < 0 && yc < 0)
                || (xa > width && xb > width && xc > width) || (ya > height && yb > height && yc > height);
    }

    private void project(int o) {
        double[] v = vertices;
        v[o + screenX] = viewport.screenX(v[o + X], v[o + W]);
        v[o + screenY] = viewport.screenY(v[o + Y], v[o + W]);
    }

    private int reserve() {
        int o = count * stride;
        if (o + stride > vertices.length) {
            vertices = Arrays.copyOf(vertices, vertices.length * 2);
        }
        count++;
        return o;
    }
}
