package dev.trisect.perf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.function.DoubleUnaryOperator;
import org.junit.jupiter.api.Test;

/** The budget controller on synthetic cost models: it converges, does not hunt, and keeps its bounds. */
class BudgetControllerTest {
    /** Edge policy: a fixed fill cost plus pieces falling with the square of the edge. */
    private static final DoubleUnaryOperator EDGE_COST = edge -> 3 + 4000 / (edge * edge);
    /** Error policy: pieces fall roughly with the error itself. */
    private static final DoubleUnaryOperator ERROR_COST = error -> 2 + 6 / error;

    /** Thresholds chosen over {@code frames} frames, each frame costing model(threshold) * noise. */
    private static double[] run(BudgetController c, DoubleUnaryOperator model, int frames, double noise, long seed) {
        Random random = new Random(seed);
        double[] thresholds = new double[frames];
        for (int i = 0; i < frames; i++) {
            thresholds[i] = c.threshold();
            double ms = model.applyAsDouble(c.threshold()) * (1 + noise * (2 * random.nextDouble() - 1));
            c.update(ms);
        }
        return thresholds;
    }

    static int reversals(double[] t, int from) {
        int n = 0;
        int last = 0;
        for (int i = from + 1; i < t.length; i++) {
            int d = Double.compare(t[i], t[i - 1]);
            if (d != 0) {
                n += last != 0 && d != last ? 1 : 0;
                last = d;
            }
        }
        return n;
    }

    @Test
    void convergesToTheTargetFromTheCeilingWithoutOvershoot() {
        BudgetController c = new BudgetController(8, 128, 2, 128);
        double[] t = run(c, EDGE_COST, 200, 0, 1);
        double frame = EDGE_COST.applyAsDouble(c.threshold());
        assertTrue(Math.abs(frame / 8 - 1) <= BudgetController.DEAD_BAND + 1e-9, "settled at " + frame + " ms");
        int settled = -1;
        for (int i = 0; i < t.length; i++) {
            if (t[i] == t[t.length - 1] && settled < 0) {
                settled = i;
            }
            assertTrue(i == 0 || t[i] <= t[i - 1], "approaches from one side, frame " + i);
        }
        assertTrue(settled >= 0 && settled <= 60, "settled within 60 frames, at " + settled);
        assertEquals(0, reversals(t, 0));
    }

    @Test
    void convergesUnderTheErrorPolicyModelFromBelow() {
        BudgetController c = new BudgetController(8, 4, 4.0 / 64, 4.0 / 64);
        double[] t = run(c, ERROR_COST, 300, 0, 1);
        assertTrue(Math.abs(ERROR_COST.applyAsDouble(c.threshold()) / 8 - 1) <= BudgetController.DEAD_BAND + 1e-9);
        assertEquals(0, reversals(t, 0));
    }

    @Test
    void holdsStillUnderNoiseOnceSettled() {
        BudgetController c = new BudgetController(8, 128, 2, 128);
        double[] t = run(c, EDGE_COST, 600, 0.15, 42);
        double ideal = Math.sqrt(4000 / 5.0);
        int changes = 0;
        for (int i = 100; i < t.length; i++) {
            assertTrue(Math.abs(t[i] / ideal - 1) < 0.2, "stays near " + ideal + ", frame " + i + ": " + t[i]);
            changes += t[i] != t[i - 1] ? 1 : 0;
        }
        assertTrue(changes <= 20, "changed " + changes + " times in 500 noisy frames");
        assertTrue(reversals(t, 100) <= 10, "reversals " + reversals(t, 100));
    }

    @Test
    void neverLooserThanTheCeiling() {
        BudgetController c = new BudgetController(1, 32, 0.5, 1000);
        assertEquals(32, c.threshold(), "the start is clamped to the ceiling");
        for (double t : run(c, EDGE_COST, 100, 0.3, 7)) {
            assertTrue(t <= 32, "above the ceiling: " + t);
        }
        assertEquals(32, c.threshold(), "an unreachable target parks it at the ceiling");
    }

    @Test
    void neverFinerThanTheFloor() {
        BudgetController c = new BudgetController(500, 32, 4, 32);
        for (double t : run(c, EDGE_COST, 200, 0, 7)) {
            assertTrue(t >= 4, "below the floor: " + t);
        }
        assertEquals(4, c.threshold());
    }

    @Test
    void ignoresMeaninglessTimesAndRejectsBadSettings() {
        BudgetController c = new BudgetController(8, 32, 1, 32);
        for (int i = 0; i < 20; i++) {
            c.update(Double.NaN);
            c.update(-1);
            c.update(Double.POSITIVE_INFINITY);
        }
        assertEquals(32, c.threshold());
        assertThrows(IllegalArgumentException.class, () -> new BudgetController(0, 32, 1, 32));
        assertThrows(IllegalArgumentException.class, () -> new BudgetController(8, 1, 2, 1));
        assertThrows(IllegalArgumentException.class, () -> new BudgetController(8, 32, 0, 1));
    }
}
