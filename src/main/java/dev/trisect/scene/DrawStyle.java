package dev.trisect.scene;

/**
 * How an object's mesh is drawn: its triangles filled, its edges as lines (a wireframe: each edge two
 * triangles share once), or both. An object's own lines ({@link SceneObject#lines()}) are drawn in
 * every style.
 */
public enum DrawStyle {
    /** The triangles, filled (the default). */
    FILLED,
    /** The triangles' edges as lines, nothing filled. */
    WIRE,
    /** The triangles filled and their edges drawn over them. */
    FILLED_AND_WIRE;

    /**
     * Whether the triangles are filled.
     *
     * @return true for {@link #FILLED} and {@link #FILLED_AND_WIRE}
     */
    public boolean fills() {
        return this != WIRE;
    }

    /**
     * Whether the edges are drawn.
     *
     * @return true for {@link #WIRE} and {@link #FILLED_AND_WIRE}
     */
    public boolean wires() {
        return this != FILLED;
    }
}
