package dev.trisect.pipeline;

/**
 * When working storage that grew for a large frame is given back: the one retention policy of the
 * renderer's buffers (chunks, their screen triangles, split trees and bands, clip-space positions,
 * outline plans). Each buffer keeps one {@code Retention} and tells it, once per frame, what that
 * frame needed and what the buffer holds; the policy answers how much to keep.
 *
 * <p>The rule: storage more than {@link #FACTOR} times the largest need of the last {@link #FRAMES}
 * frames (and above the buffer's floor, below which it never matters) shrinks to twice that need.
 * So one huge frame's memory goes back after {@link #FRAMES} ordinary frames — a tenth of a second
 * in a view — while frames whose needs vary within a factor of {@value #FACTOR} (and a view that
 * draws several paths per frame, each in its own render call, fewer than {@link #FRAMES} of them)
 * never reallocate. Needs and capacities are in the buffer's own units (triangles, positions,
 * chunks); the policy only compares them.
 *
 * <p>Not thread-safe: each instance belongs to one buffer, updated by one thread at a time.
 */
final class Retention {
    /** Frames (render calls) a need is remembered for. */
    static final int FRAMES = 5;
    /** Storage more than this many times the recent need is oversized. */
    static final int FACTOR = 4;

    private final long floor;
    private final long[] needs = new long[FRAMES];
    private int next;
    /** Frames recorded, up to {@link #FRAMES}: a new buffer is not judged on fewer. */
    private int seen;

    /** @param floor storage at or below this (in the buffer's units) is never given back */
    Retention(long floor) {
        this.floor = floor;
    }

    /**
     * Records one frame's need and says how much of {@code capacity} to keep.
     *
     * @param need     what this frame used (triangles, positions, chunks...)
     * @param capacity what the buffer holds now, in the same units
     * @return the capacity to shrink to (at least the floor, at least twice the recent need), or -1 to
     *         keep the storage as it is
     */
    long keep(long need, long capacity) {
        needs[next] = Math.max(0, need);
        next = (next + 1) % FRAMES;
        seen = Math.min(FRAMES, seen + 1);
        if (seen < FRAMES || capacity <= floor) {
            return -1;
        }
        long recent = recentNeed();
        if (capacity <= FACTOR * recent) {
            return -1;
        }
        return Math.max(floor, 2 * recent);
    }

    /** The largest need of the last {@link #FRAMES} frames recorded. */
    long recentNeed() {
        long recent = 0;
        for (long n : needs) {
            recent = Math.max(recent, n);
        }
        return recent;
    }
}
