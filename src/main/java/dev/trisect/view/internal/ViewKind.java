package dev.trisect.view.internal;

/** What the view shows. */
public enum ViewKind {
    /** The current path's image. */
    IMAGE,
    /** The displacement heat map of the current path against the per-pixel path. */
    DIFFERENCE,
    /** The current path left of a divider, the per-pixel path right of it. */
    SPLIT
}
