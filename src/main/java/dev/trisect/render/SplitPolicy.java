package dev.trisect.render;

import java.util.Locale;

/**
 * What decides that an edge is split (see {@code docs/math.md}), and what the stages that tune or
 * report a split policy ask of it: which threshold of {@link TessellationSettings} it reads
 * ({@link #threshold}, {@link #withThreshold}), the finest value the controls offer ({@link #floor}),
 * and the measure compared with it ({@link #measuresError}).
 */
public enum SplitPolicy {
    /** Split while an edge is longer on screen than {@code maxEdge} pixels. */
    EDGE(2),
    /** Split while an edge's worst affine displacement (the Kamen-Shirman bound) exceeds {@code maxError} pixels. */
    ERROR(0.05);

    private final double floor;

    SplitPolicy(double floor) {
        this.floor = floor;
    }

    /**
     * The threshold this policy compares edges with: {@code maxEdge} or {@code maxError}.
     *
     * @param t the split settings
     * @return the threshold, screen pixels
     */
    public double threshold(TessellationSettings t) {
        return this == EDGE ? t.maxEdge() : t.maxError();
    }

    /**
     * A copy of {@code t} with this policy's threshold set to {@code px} (and the other left as it is).
     *
     * @param t  the split settings
     * @param px the threshold, screen pixels, &gt; 0
     * @return the copy
     */
    public TessellationSettings withThreshold(TessellationSettings t, double px) {
        return this == EDGE ? t.withMaxEdge(px) : t.withMaxError(px);
    }

    /**
     * The finest threshold the controls offer (the demo's sliders and the frame budget controller's
     * floor): 2 px for the edge policy — below that a piece holds a pixel or two and costs more to cut
     * than to fill per pixel — and 0.05 px for the error policy, a twentieth of a pixel.
     *
     * @return the finest threshold, screen pixels
     */
    public double floor() {
        return floor;
    }

    /**
     * Whether the measure compared with the threshold is an edge's affine error bound in pixels
     * ({@link #ERROR}); otherwise it is the edge's screen length in pixels ({@link #EDGE}).
     *
     * @return true for {@link #ERROR}
     */
    public boolean measuresError() {
        return this == ERROR;
    }

    /**
     * The name used on the command line and in reports: edge or error.
     *
     * @return the policy's name on the command line
     */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }
}
