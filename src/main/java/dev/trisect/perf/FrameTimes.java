package dev.trisect.perf;

import java.util.Arrays;

/**
 * Summary of the wall-clock times of a run of frames, in milliseconds. The median is the figure to
 * compare (a shared machine adds outliers to the mean); the minimum is the least disturbed frame.
 *
 * @param frames   frames measured
 * @param medianMs median frame time (for an even count, the upper of the two middle values)
 * @param minMs    fastest frame
 * @param meanMs   mean frame time
 * @param p95Ms    95th percentile, nearest rank
 */
public record FrameTimes(int frames, double medianMs, double minMs, double meanMs, double p95Ms) {

    /** Summarizes frame times given in milliseconds; at least one. */
    public static FrameTimes of(double[] ms) {
        if (ms.length == 0) {
            throw new IllegalArgumentException("no frame times");
        }
        double[] sorted = ms.clone();
        Arrays.sort(sorted);
        double mean = Arrays.stream(ms).average().orElseThrow();
        int p95 = Math.min(sorted.length - 1, (int) Math.ceil(sorted.length * 0.95) - 1);
        return new FrameTimes(ms.length, sorted[sorted.length / 2], sorted[0], mean, sorted[p95]);
    }
}
