package dev.trisect.pipeline;

import dev.trisect.math.Mat4;

/**
 * The transform stage: every position of every draw to clip space once, in doubles, by the draw's
 * own model-view-projection, with a flag on each position that came out NaN or infinite. Draw d's
 * positions land from {@link Draws#firstPosition}(d) on. The arrays are kept from frame to frame.
 */
final class ClipSpace {
    /** Below this many positions the transform runs on one thread: sharing it out costs more. */
    private static final int PARALLEL_POSITIONS = 65536;

    /** Positions below which the arrays are never given back: 2 MiB of them. */
    private static final int TRIM_FLOOR = 65536;

    private double[] clip = new double[0];
    private boolean[] invalid = new boolean[0];
    private final Retention retention = new Retention(TRIM_FLOOR);

    /** Transforms the positions of every draw by its model-view-projection (object to clip space). */
    void transform(Draws draws, WorkerPool pool) {
        int total = draws.positionCount();
        long keep = retention.keep(total, invalid.length);
        if (invalid.length < total || keep >= 0) {
            // Grown to the need, or given back to twice the recent need (see Retention).
            int size = Math.max(total, (int) keep);
            clip = new double[4 * size];
            invalid = new boolean[size];
        }
        double[] out = clip;
        boolean[] flags = invalid;
        for (int d = 0; d < draws.size(); d++) {
            Mat4 mvp = draws.transform(d);
            float[] p = draws.mesh(d).positions();
            int n = draws.mesh(d).positionCount();
            int base = draws.firstPosition(d);
            int parts = n < PARALLEL_POSITIONS ? 1 : pool.threads();
            int per = (n + parts - 1) / parts;
            pool.run(parts, (thread, part) -> {
                int to = Math.min(n, (part + 1) * per);
                for (int i = part * per; i < to; i++) {
                    int o = 4 * (base + i);
                    mvp.transformPoint(p[3 * i], p[3 * i + 1], p[3 * i + 2], out, o);
                    flags[base + i] = !(Double.isFinite(out[o]) && Double.isFinite(out[o + 1])
                            && Double.isFinite(out[o + 2]) && Double.isFinite(out[o + 3]));
                }
            });
        }
    }

    /** Gives the arrays back; the next {@link #transform} makes them anew. */
    void release() {
        clip = new double[0];
        invalid = new boolean[0];
    }

    /** Positions the arrays hold room for. */
    int capacity() {
        return invalid.length;
    }

    /** Clip-space x, y, z, w of each frame position last transformed, 4 doubles each. */
    double[] positions() {
        return clip;
    }

    /** Per frame position last transformed: whether its clip-space coordinates are not all finite. */
    boolean[] invalid() {
        return invalid;
    }
}
