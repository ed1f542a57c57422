package dev.trisect.devtools;

import java.util.Arrays;

/**
 * The last {@link #CAPACITY} timings of each path (one per comparison, about every 0.4 s), so that the
 * per-path bars show a median and its spread rather than one sample: a single frame of the span path
 * once read 116 ms against its usual 5-16 ms. Event thread only.
 */
final class PathSamples {
    /** Samples kept per path: about 4 s of comparisons. */
    static final int CAPACITY = 9;

    private final double[][] rows = new double[CAPACITY][];
    private int count;
    private int next;
    /** The last sample taken, so that the same one read again (between comparisons) is not counted twice. */
    private double[] last;

    /**
     * Takes the newest timings ({@code ms} by path ordinal, or null when another scene cleared them, which
     * clears the samples too).
     */
    void offer(double[] ms) {
        if (ms == null) {
            Arrays.fill(rows, null);
            count = 0;
            next = 0;
            last = null;
            return;
        }
        if (ms == last) {
            return;
        }
        last = ms;
        rows[next] = ms.clone();
        next = (next + 1) % CAPACITY;
        count = Math.min(CAPACITY, count + 1);
    }

    /** How many samples there are (0 to {@link #CAPACITY}). */
    int count() {
        return count;
    }

    /** The sorted samples of path {@code path}. */
    private double[] sorted(int path) {
        double[] v = new double[count];
        for (int i = 0; i < count; i++) {
            v[i] = rows[i][path];
        }
        Arrays.sort(v);
        return v;
    }

    /** The median of path {@code path}'s samples, milliseconds (the mean of the middle two for an even count). */
    double median(int path) {
        double[] v = sorted(path);
        return v.length % 2 == 1 ? v[v.length / 2] : (v[v.length / 2 - 1] + v[v.length / 2]) / 2;
    }

    /** The least of path {@code path}'s samples, milliseconds. */
    double min(int path) {
        return sorted(path)[0];
    }

    /** The greatest of path {@code path}'s samples, milliseconds. */
    double max(int path) {
        return sorted(path)[count - 1];
    }
}
