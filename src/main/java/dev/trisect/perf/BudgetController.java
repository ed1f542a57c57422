package dev.trisect.perf;

import dev.trisect.render.SplitPolicy;

/**
 * Holds a frame-time target by adjusting the split threshold (the edge policy's longest edge or the
 * error policy's largest displacement, pixels) from frame to frame: a larger threshold means fewer
 * pieces and a faster frame. The better version of Sixth 3D's polygon-budget controller.
 *
 * <p>How it works, and why it does not oscillate:
 * <ul>
 * <li>It controls the logarithm of the threshold, multiplicatively: frame cost is roughly
 *     {@code a + b * threshold^-p} (pieces fall with the square of the edge, p = 2, or with the
 *     error, p of about 1), so equal ratios of time call for equal ratios of threshold at any scale.</li>
 * <li>It measures a window of {@link #WINDOW} frames at one threshold and acts on their median, so
 *     one slow frame from a busy machine does not move it, and every step is judged on frames
 *     rendered after the previous step (a running average would lag behind its own steps and make
 *     it overshoot).</li>
 * <li>Each step is {@code log threshold += GAIN * log(median / target)}. With the gain at 1/2 it is
 *     at most a Newton step for p &lt;= 2 (less where part of the frame does not depend on the
 *     threshold), so it approaches the target from one side without overshooting, and each step is
 *     also limited to a factor of {@link #MAX_STEP}.</li>
 * <li>Hysteresis: once a window's median comes within {@link #DEAD_BAND} of the target it holds
 *     still, and moves again only when a median strays beyond {@link #HOLD_BAND}, so noise at the
 *     target does not make it hunt.</li>
 * <li>The threshold stays within [floor, ceiling]: never looser than the user's ceiling, never finer
 *     than the floor ({@link #floorFor}: the finest the split-policy controls offer, and 1/64 of the
 *     ceiling); a target it cannot reach parks it at a bound.</li>
 * <li>The frame's piece budget is a floor too ({@link #update(double, long, long, boolean)}): a frame
 *     over its budget is redone with a lower depth cap and its pieces beyond it are filled per pixel,
 *     so its time says nothing of the threshold, and below some threshold a generous target would
 *     drive the threshold into that regime for good. Pieces grow at most as {@code threshold^-2}
 *     (with the edge policy they do, for pieces much larger than the threshold; with the error policy
 *     about as {@code threshold^-1}; pieces left unsplit do not grow), so from a frame's pieces P at
 *     threshold T the threshold {@code T sqrt(P / (AIM b))} keeps a budget b at least AIM full: the
 *     controller never steps below it. Should the pieces still pass {@link #BUDGET_HIGH} of the budget
 *     (the camera moved), it raises the threshold at once, by {@code P / (AIM b)} (at least a pieces'
 *     worth, and {@link #MAX_STEP} when the budget was reached), not waiting for the window. The gap
 *     between the two shares is the budget's hysteresis.</li>
 * </ul>
 * Not thread-safe: one frame loop drives it.
 */
public final class BudgetController {
    /** Frames measured at one threshold before each decision. */
    public static final int WINDOW = 5;
    /** Proportional gain on log(time / target) applied to log(threshold). */
    public static final double GAIN = 0.5;
    /** Relative distance of the window median from the target within which the controller settles. */
    public static final double DEAD_BAND = 0.05;
    /** Relative distance of the window median from the target beyond which a settled controller moves again. */
    public static final double HOLD_BAND = 0.15;
    /** Largest factor one frame may change the threshold by. */
    public static final double MAX_STEP = 1.5;
    /** Share of the frame's piece budget the controller aims at, at most, when it refines. */
    public static final double BUDGET_AIM = 0.6;
    /** Share of the frame's piece budget beyond which it coarsens at once. */
    public static final double BUDGET_HIGH = 0.75;

    /** What holds the threshold where it is, as the last frame left it. */
    public enum Limit {
        /** Nothing: it follows the frame time toward the target (or has settled there). */
        TARGET,
        /** The ceiling, the user's threshold, with frames still slower than the target: out of reach. */
        CEILING,
        /** The floor, the finest threshold allowed, with frames still faster than the target. */
        FLOOR,
        /** The frame's piece budget: finer would be predicted to fill more than {@link #BUDGET_AIM} of it. */
        PIECE_BUDGET
    }

    private final double targetMs;
    private final double ceiling;
    private final double floor;
    private double threshold;
    private final double[] window = new double[WINDOW];
    private int filled;
    private double lastMedianMs = Double.NaN;
    private boolean settled;
    private Limit limit = Limit.TARGET;
    /** The finest threshold the last frame's pieces allow (see the class comment); 0 before any. */
    private double pieceFloor;

    /**
     * @param targetMs frame time to hold, milliseconds, &gt; 0
     * @param ceiling  the loosest threshold allowed (the user's setting), pixels, &gt; 0
     * @param floor    the finest threshold allowed, pixels, in (0, ceiling]
     * @param initial  the threshold to start from, clamped to [floor, ceiling]
     */
    public BudgetController(double targetMs, double ceiling, double floor, double initial) {
        if (!(targetMs > 0) || !Double.isFinite(targetMs)) {
            throw new IllegalArgumentException("target must be a positive number of milliseconds, got " + targetMs);
        }
        if (!(floor > 0) || !(ceiling >= floor) || !Double.isFinite(ceiling)) {
            throw new IllegalArgumentException("need 0 < floor <= ceiling, got " + floor + " and " + ceiling);
        }
        this.targetMs = targetMs;
        this.ceiling = ceiling;
        this.floor = floor;
        this.threshold = clamp(Double.isFinite(initial) ? initial : ceiling);
    }

    /** The finest threshold a controller allows by default: 1/64 of the ceiling. */
    public static double defaultFloor(double ceiling) {
        return ceiling / 64;
    }

    /**
     * The finest threshold a controller of {@code policy} allows under {@code ceiling}: 1/64 of it, but
     * never finer than the split-policy section offers ({@link SplitPolicy#floor()}),
     * nor looser than the ceiling itself.
     */
    public static double floorFor(SplitPolicy policy, double ceiling) {
        return Math.min(ceiling, Math.max(defaultFloor(ceiling), policy.floor()));
    }

    /** What held the threshold at the last frame. */
    public Limit limit() {
        return limit;
    }

    /** The threshold to render the next frame with, pixels. */
    public double threshold() {
        return threshold;
    }

    /** The frame time held, milliseconds. */
    public double targetMs() {
        return targetMs;
    }

    /** The loosest threshold allowed, pixels. */
    public double ceiling() {
        return ceiling;
    }

    /**
     * The finest threshold the last frame's pieces allow: finer would be predicted to fill more than
     * {@link #BUDGET_AIM} of the piece budget (see the class comment); 0 before a frame with a budget.
     */
    public double pieceFloor() {
        return pieceFloor;
    }

    /** Whether the last window's median was close enough to the target to hold still. */
    public boolean settled() {
        return settled;
    }

    /** The median frame time of the last full window, milliseconds (NaN before the first). */
    public double lastMedianMs() {
        return lastMedianMs;
    }

    /**
     * Takes the time of the frame just rendered with {@link #threshold()} and returns the threshold for
     * the next one (changed only at the end of a window). A non-finite or non-positive time is ignored.
     */
    public double update(double frameMs) {
        return step(frameMs);
    }

    /**
     * As {@link #update(double)}, for a frame of the tessellated path that also says how many pieces
     * it made ({@code pieces}: filled and dropped off screen, what the budget counts) against its
     * budget {@code pieceBudget}, and whether it went over (so was redone with a lower depth cap and
     * its pieces are those of the capped frame). The piece budget is then a floor on the threshold
     * (see the class comment). A budget of 0 or less means none.
     */
    public double update(double frameMs, long pieces, long pieceBudget, boolean budgetReached) {
        if (pieceBudget <= 0 || pieces < 0) {
            return step(frameMs);
        }
        // A frame over its budget made at least the budget's pieces: its own count is the capped frame's.
        double made = budgetReached ? Math.max(pieces, pieceBudget) : pieces;
        double ratio = made / (BUDGET_AIM * pieceBudget);
        pieceFloor = threshold * Math.sqrt(ratio);
        if (budgetReached || made > BUDGET_HIGH * pieceBudget) {
            // Coarsen now, and start a new window: the frames so far were timed at a threshold left behind.
            double raised = threshold * Math.max(ratio, budgetReached ? MAX_STEP : 1);
            threshold = clamp(raised);
            pieceFloor = threshold;
            filled = 0;
            settled = false;
            limit = Limit.PIECE_BUDGET;
            return threshold;
        }
        return step(frameMs);
    }

    private double step(double frameMs) {
        if (!(frameMs > 0) || !Double.isFinite(frameMs)) {
            return threshold;
        }
        window[filled++] = frameMs;
        if (filled < WINDOW) {
            return threshold;
        }
        filled = 0;
        double[] sorted = window.clone();
        java.util.Arrays.sort(sorted);
        lastMedianMs = sorted[WINDOW / 2];
        double error = Math.log(lastMedianMs / targetMs);
        double distance = Math.abs(error);
        if (distance <= Math.log1p(DEAD_BAND) || (settled && distance <= Math.log1p(HOLD_BAND))) {
            settled = true;
            limit = Limit.TARGET;
            return threshold;
        }
        settled = false;
        double maxLog = Math.log(MAX_STEP);
        double step = Math.max(-maxLog, Math.min(maxLog, GAIN * error));
        double wanted = clamp(threshold * Math.exp(step));
        // Never finer than the piece budget allows (nor coarser than the ceiling).
        threshold = clamp(Math.max(wanted, Math.min(threshold, pieceFloor)));
        limit = threshold > wanted ? Limit.PIECE_BUDGET
                : error > 0 && threshold >= ceiling ? Limit.CEILING
                : error < 0 && threshold <= floor ? Limit.FLOOR : Limit.TARGET;
        return threshold;
    }

    private double clamp(double t) {
        return Math.max(floor, Math.min(ceiling, t));
    }
}
