package dev.trisect.pipeline;

import dev.trisect.tessellate.PieceBudget;

/**
 * The frame piece budget's search for a depth cap: runs the geometry at the configured cap and, if
 * the frame's pieces exceed its budget, searches for the deepest cap at which they fit, leaving that
 * attempt's geometry in place.
 */
final class DepthCapSearch {
    /** One try at the frame's geometry with edge levels capped at {@code depth}; true if within {@code pieces}. */
    @FunctionalInterface
    interface Attempt {
        boolean run(int depth, long pieces);
    }

    private DepthCapSearch() {
    }

    /**
     * First the configured cap, then the cap one below (a frame just over its budget costs two
     * attempts), then bisection between 0 and that. Lowering the level cap is crack-free (it is per
     * edge) and the pieces it stops short of the policy are filled per pixel, so the bound holds.
     * Each attempt is cut off at about the budget, and there are at most log2(maxDepth) + 3 of them;
     * each verdict is thread-count-independent (see {@link PieceBudget}), so the chosen cap is too.
     * Depth 0 (no splitting) is accepted whatever its count. The last attempt run is always the one
     * at the returned cap (or the configured one), complete.
     *
     * @return the depth cap the budget forced, or -1 if the configured one fit
     */
    static int fit(Attempt attempt, int maxDepth, long limit) {
        if (attempt.run(maxDepth, limit)) {
            return -1;
        }
        if (maxDepth > 0 && attempt.run(maxDepth - 1, limit)) {
            return maxDepth - 1;
        }
        // Depth 0 counts as fitting even when it does not: the triangles are the least a frame can be.
        int fits = 0;
        int fails = Math.max(0, maxDepth - 1);
        boolean lastRunFits = false;
        while (fails - fits > 1) {
            int mid = (fits + fails) >>> 1;
            lastRunFits = attempt.run(mid, limit);
            if (lastRunFits) {
                fits = mid;
            } else {
                fails = mid;
            }
        }
        if (!lastRunFits) {
            // The last attempt was over budget: redo the deepest cap that fit.
            attempt.run(fits, Long.MAX_VALUE);
        }
        return fits;
    }
}
