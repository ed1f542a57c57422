package dev.trisect.metrics;

import java.util.Arrays;

/**
 * Exact percentiles of a primitive {@code float[]} by selection (quickselect), in expected linear time
 * and without boxing or a full sort. The array is reordered.
 */
final class Percentiles {
    private Percentiles() {
    }

    /**
     * The nearest-rank percentile of the first {@code n} values: the smallest value that at least
     * {@code percent}% of them do not exceed; {@code NaN} when {@code n == 0}. The values must not
     * contain NaN. Reorders {@code values[0..n)}.
     *
     * @param percent in (0, 100]
     */
    static double nearestRank(float[] values, int n, int percent) {
        if (n == 0) {
            return Double.NaN;
        }
        // rank = ceil(percent * n / 100), 1-based, in exact integer arithmetic.
        int rank = (int) ((percent * (long) n + 99) / 100);
        return select(values, n, Math.max(rank, 1) - 1);
    }

    /**
     * The value that would be at index {@code k} if {@code values[0..n)} were sorted ascending.
     * Reorders {@code values[0..n)}.
     */
    static float select(float[] values, int n, int k) {
        int lo = 0;
        int hi = n - 1;
        // Median-of-three quickselect is linear on real data; a bounded number of rounds keeps a
        // pathological input at O(n log n) by finishing with a primitive sort of what is left.
        int rounds = 4 * (32 - Integer.numberOfLeadingZeros(n)) + 8;
        while (lo < hi) {
            if (rounds-- == 0) {
                Arrays.sort(values, lo, hi + 1);
                return values[k];
            }
            float pivot = medianOfThree(values[lo], values[(lo + hi) >>> 1], values[hi]);
            // Hoare partition: afterwards [lo..j] <= pivot, [i..hi] >= pivot, (j..i) == pivot.
            int i = lo;
            int j = hi;
            while (i <= j) {
                while (values[i] < pivot) {
                    i++;
                }
                while (values[j] > pivot) {
                    j--;
                }
                if (i <= j) {
                    float swap = values[i];
                    values[i] = values[j];
                    values[j] = swap;
                    i++;
                    j--;
                }
            }
            if (k <= j) {
                hi = j;
            } else if (k >= i) {
                lo = i;
            } else {
                return values[k];
            }
        }
        return values[k];
    }

    private static float medianOfThree(float a, float b, float c) {
        return Math.max(Math.min(a, b), Math.min(Math.max(a, b), c));
    }
}
