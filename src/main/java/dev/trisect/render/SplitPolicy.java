package dev.trisect.render;

/** What decides that an edge is split (see {@code docs/math.md}). */
public enum SplitPolicy {
    /** Split while an edge is longer on screen than {@code maxEdge} pixels. */
    EDGE,
    /** Split while an edge's worst affine displacement (the Kamen-Shirman bound) exceeds {@code maxError} pixels. */
    ERROR
}
