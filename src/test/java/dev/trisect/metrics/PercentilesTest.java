package dev.trisect.metrics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class PercentilesTest {

    @ParameterizedTest
    @ValueSource(ints = {1, 2, 3, 10, 101, 1000})
    void selectAgreesWithSortingForEveryRank(int n) {
        Random random = new Random(n);
        for (int distinct : new int[] {1, 3, n}) {
            float[] values = new float[n];
            for (int i = 0; i < n; i++) {
                values[i] = random.nextInt(distinct) * 0.5f;
            }
            float[] sorted = values.clone();
            Arrays.sort(sorted);
            for (int k = 0; k < n; k++) {
                assertEquals(sorted[k], Percentiles.select(values.clone(), n, k), "n=" + n + " k=" + k);
            }
        }
    }

    @Test
    void sortedAndReversedInputsWork() {
        int n = 100_000;
        float[] ascending = new float[n];
        float[] descending = new float[n];
        for (int i = 0; i < n; i++) {
            ascending[i] = i;
            descending[i] = n - 1 - i;
        }
        assertEquals(98_999, Percentiles.nearestRank(ascending, n, 99));
        assertEquals(98_999, Percentiles.nearestRank(descending, n, 99));
    }

    @Test
    void nearestRankDefinition() {
        // ceil(0.99 * 100) = 99th smallest, ceil(0.99 * 101) = 100th, ceil(0.99 * 1) = 1st.
        assertEquals(99, Percentiles.nearestRank(range(100), 100, 99));
        assertEquals(100, Percentiles.nearestRank(range(101), 101, 99));
        assertEquals(1, Percentiles.nearestRank(range(1), 1, 99));
        assertEquals(50, Percentiles.nearestRank(range(100), 100, 50));
        assertEquals(100, Percentiles.nearestRank(range(100), 100, 100));
        assertTrue(Double.isNaN(Percentiles.nearestRank(new float[4], 0, 99)));
    }

    @Test
    void onlyThePrefixCounts() {
        float[] values = {5, 4, 3, 2, 1, 1000, 1000};
        assertEquals(5, Percentiles.nearestRank(values, 5, 99));
    }

    /** 1..n shuffled. */
    private static float[] range(int n) {
        float[] values = new float[n];
        for (int i = 0; i < n; i++) {
            values[i] = (i * 7919L) % n + 1;
        }
        return values;
    }
}
