package dev.trisect.perf;

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
 *     than the floor; a target it cannot reach parks it at a bound.</li>
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

    private final double targetMs;
    private final double ceiling;
    private final double floor;
    private double threshold;
    private final double[] window = new double[WINDOW];
    private int filled;
    private double lastMedianMs = Double.NaN;
    private boolean settled;

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
            return threshold;
        }
        settled = false;
        double maxLog = Math.log(MAX_STEP);
        double step = Math.max(-maxLog, Math.min(maxLog, GAIN * error));
        threshold = clamp(threshold * Math.exp(step));
        return threshold;
    }

    private double clamp(double t) {
        return Math.max(floor, Math.min(ceiling, t));
    }
}
