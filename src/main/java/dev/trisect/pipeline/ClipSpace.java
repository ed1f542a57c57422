package dev.trisect.pipeline;

import dev.trisect.math.Mat4;
import dev.trisect.mesh.Mesh;

/**
 * The transform stage: every position of a mesh to clip space once, in doubles, with a flag on
 * each position that came out NaN or infinite. The arrays are kept from frame to frame.
 */
final class ClipSpace {
    /** Below this many positions the transform runs on one thread: sharing it out costs more. */
    private static final int PARALLEL_POSITIONS = 65536;

    private double[] clip = new double[0];
    private boolean[] invalid = new boolean[0];

    /** Transforms the positions of {@code mesh} by {@code viewProjection} (world to clip space). */
    void transform(Mesh mesh, Mat4 viewProjection, WorkerPool pool) {
        int n = mesh.positionCount();
        if (clip.length < 4 * n) {
            clip = new double[4 * n];
            invalid = new boolean[n];
        }
        double[] out = clip;
        boolean[] flags = invalid;
        float[] p = mesh.positions();
        int parts = n < PARALLEL_POSITIONS ? 1 : pool.threads();
        int per = (n + parts - 1) / parts;
        pool.run(parts, (thread, part) -> {
            int to = Math.min(n, (part + 1) * per);
            for (int i = part * per; i < to; i++) {
                viewProjection.transformPoint(p[3 * i], p[3 * i + 1], p[3 * i + 2], out, 4 * i);
                flags[i] = !(Double.isFinite(out[4 * i]) && Double.isFinite(out[4 * i + 1])
                        && Double.isFinite(out[4 * i + 2]) && Double.isFinite(out[4 * i + 3]));
            }
        });
    }

    /** Clip-space x, y, z, w of each position of the last mesh transformed, 4 doubles each. */
    double[] positions() {
        return clip;
    }

    /** Per position of the last mesh transformed: whether its clip-space coordinates are not all finite. */
    boolean[] invalid() {
        return invalid;
    }
}
