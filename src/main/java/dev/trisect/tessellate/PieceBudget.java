package dev.trisect.tessellate;

import java.util.concurrent.atomic.AtomicLong;

/**
 * A frame-wide limit on the pieces the tessellators of all threads produce, with a verdict that does
 * not depend on how the triangles are shared out between threads.
 *
 * <p>Each triangle charges the pieces it produced (filled or dropped off screen: one plus its
 * splits) once it is done, and a triangle stops early when its own pieces alone would take the total
 * past the limit. Either way the budget is marked exceeded only if the frame's total — a sum over
 * triangles, each a function of the triangle alone — is above the limit, and it always is then: when
 * all triangles finish, the charge that crosses the limit marks it; when one stops early, its own
 * pieces already cross what the others left. So the verdict is the same for any number of threads
 * and any order, while the work stays within about the limit. What the tessellators emitted in a
 * frame whose budget was exceeded is incomplete and must be thrown away.
 */
public final class PieceBudget {
    private final AtomicLong used = new AtomicLong();
    private volatile boolean exceeded;
    private long limit = Long.MAX_VALUE;

    /** Starts a frame (or another attempt at one) with room for {@code pieces} pieces, &gt;= 1. */
    public void reset(long pieces) {
        if (pieces < 1) {
            throw new IllegalArgumentException("piece budget must be at least 1, got " + pieces);
        }
        used.set(0);
        exceeded = false;
        limit = pieces;
    }

    /** Whether the frame's pieces are more than the limit (so far, or as a triangle found out alone). */
    public boolean exceeded() {
        return exceeded;
    }

    /** The limit set by the last {@link #reset}. */
    public long limit() {
        return limit;
    }

    /** Pieces the triangle starting now may produce before the total is certainly over the limit. */
    long allowance() {
        return limit - used.get();
    }

    /** Charges a finished triangle's pieces. */
    void charge(long pieces) {
        if (used.addAndGet(pieces) > limit) {
            exceeded = true;
        }
    }

    /** Marks the budget exceeded: a triangle's own pieces would pass what is left. */
    void exceed() {
        exceeded = true;
    }
}
