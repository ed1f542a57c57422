package dev.trisect.perf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.render.SplitPolicy;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The budget controller against the frame's piece budget (issue 18, defect 2): on synthetic frames
 * whose pieces grow as the threshold falls and whose cost jumps once the pieces pass the budget (the
 * frame is redone with a lower depth cap), it never chooses a threshold that overflows the budget,
 * and does not oscillate, whether the target is out of reach of the budget or the over-budget frames
 * are cheap enough to tempt it.
 */
class BudgetControllerPieceBudgetTest {
    private static final long BUDGET = 60_000;

    /** A frame's pieces at a threshold: some never split, the rest growing as threshold^-p, scaled by the view. */
    private record Scene(double unsplit, double k, double p) {
        long pieces(double threshold, double view) {
            return Math.round(unsplit + view * k / Math.pow(threshold, p));
        }
    }

    /** Edge policy: pieces grow with the square of 1/threshold; 60k at about 8.5 px. */
    private static final Scene EDGE = new Scene(5_000, 4e6, 2);
    /** Error policy: pieces grow about as 1/threshold; 60k at about 0.55 px. */
    private static final Scene ERROR = new Scene(5_000, 30_000, 1);

    /** What a run did, frame by frame. */
    private record Run(double[] thresholds, long[] pieces, int overflows) {
    }

    /**
     * Drives {@code c} for {@code frames} frames. A frame's cost is 3 ms plus 1 ms per 4,000 pieces; over
     * the budget it is redone with a lower cap: {@code overCost} ms (the capped frame's pieces are the
     * budget's). {@code view} scales the pieces, frame by frame (the camera moving).
     */
    private static Run run(BudgetController c, Scene scene, int frames, double overCost, double noise,
                           java.util.function.IntToDoubleFunction view) {
        Random random = new Random(5);
        double[] thresholds = new double[frames];
        long[] pieces = new long[frames];
        int overflows = 0;
        for (int i = 0; i < frames; i++) {
            double t = c.threshold();
            long made = scene.pieces(t, view.applyAsDouble(i));
            boolean over = made > BUDGET;
            double ms = (over ? overCost : 3 + made / 4000.0) * (1 + noise * (2 * random.nextDouble() - 1));
            thresholds[i] = t;
            pieces[i] = made;
            overflows += over ? 1 : 0;
            c.update(ms, over ? BUDGET : made, BUDGET, over);
        }
        return new Run(thresholds, pieces, overflows);
    }

    private static int reversals(double[] t, int from) {
        return BudgetControllerTest.reversals(t, from);
    }

    @Test
    void aGenerousTargetStopsAtThePieceBudgetInsteadOfPassingIt() {
        // 40 ms is never reached within the budget (at most 3 + 15 = 18 ms); over it frames cost 25 ms, so
        // the time alone would drive the threshold to its floor and every frame over the budget.
        for (Scene scene : new Scene[] {EDGE, ERROR}) {
            SplitPolicy policy = scene == EDGE ? SplitPolicy.EDGE : SplitPolicy.ERROR;
            double ceiling = scene == EDGE ? 32 : 8;
            BudgetController c = new BudgetController(40, ceiling, BudgetController.floorFor(policy, ceiling), ceiling);
            Run r = run(c, scene, 400, 25, 0, i -> 1);
            assertEquals(0, r.overflows(), policy + ": frames over the piece budget");
            long last = r.pieces()[r.pieces().length - 1];
            assertTrue(last >= BudgetController.BUDGET_AIM * 0.9 * BUDGET && last <= BudgetController.BUDGET_HIGH * BUDGET,
                    policy + ": settles with the budget well used, " + last + " pieces");
            assertEquals(BudgetController.Limit.PIECE_BUDGET, c.limit(), policy + ": and says the budget holds it");
            assertEquals(0, reversals(r.thresholds(), 0), policy + ": from the ceiling straight down to it");
        }
    }

    @Test
    void aCostThatJumpsOverTheBudgetNeverMakesItHunt() {
        // Over the budget a frame costs 120 ms: a controller that passed it would bounce back and forth.
        BudgetController c = new BudgetController(40, 32, BudgetController.floorFor(SplitPolicy.EDGE, 32), 32);
        Run r = run(c, EDGE, 600, 120, 0.15, i -> 1);
        assertEquals(0, r.overflows());
        assertTrue(reversals(r.thresholds(), 0) <= 2, "reversals: " + reversals(r.thresholds(), 0));
    }

    @Test
    void aCameraThatBringsMorePiecesIntoViewIsFollowedWithoutOverflow() {
        // The view's pieces swell by up to 60 % and shrink again, twice, over 800 frames (an orbit).
        BudgetController c = new BudgetController(40, 32, BudgetController.floorFor(SplitPolicy.EDGE, 32), 32);
        Run r = run(c, EDGE, 800, 120, 0.1, i -> 1.3 + 0.3 * Math.sin(4 * Math.PI * i / 800));
        assertEquals(0, r.overflows());
        for (long p : r.pieces()) {
            assertTrue(p <= BUDGET, "pieces " + p);
        }
        // It follows the view: coarser as it swells, finer as it shrinks, but never back and forth in between.
        assertTrue(reversals(r.thresholds(), 0) <= 8, "reversals: " + reversals(r.thresholds(), 0));
    }

    @Test
    void piecesGrowingFasterThanPredictedOverflowOnceAtMostAndSettle() {
        // Locally steeper growth than threshold^-2 (the prediction's), as discrete splitting can give.
        Scene steep = new Scene(5_000, 2.5e7, 2.6);
        BudgetController c = new BudgetController(40, 32, BudgetController.floorFor(SplitPolicy.EDGE, 32), 32);
        Run r = run(c, steep, 600, 25, 0, i -> 1);
        assertTrue(r.overflows() <= 1, "overflows: " + r.overflows());
        assertEquals(0, reversals(r.thresholds(), 300), "settled in the second half");
    }

    @Test
    void aFrameOverTheBudgetAnywayIsAnsweredAtOnce() {
        BudgetController c = new BudgetController(40, 32, 2, 4);
        double before = c.threshold();
        c.update(25, BUDGET, BUDGET, true);
        assertTrue(c.threshold() >= before * BudgetController.MAX_STEP, "coarser at once: " + c.threshold());
        assertEquals(BudgetController.Limit.PIECE_BUDGET, c.limit());
    }

    @Test
    void theFloorIsTheFinestTheControlsOffer() {
        assertEquals(2, BudgetController.floorFor(SplitPolicy.EDGE, 32), "not 0.5 px (1/64 of 32)");
        assertEquals(4, BudgetController.floorFor(SplitPolicy.EDGE, 256));
        assertEquals(0.05, BudgetController.floorFor(SplitPolicy.ERROR, 0.5));
        assertEquals(1.5, BudgetController.floorFor(SplitPolicy.EDGE, 1.5), "never above the ceiling");
    }
}
