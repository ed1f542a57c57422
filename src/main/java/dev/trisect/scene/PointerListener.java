package dev.trisect.scene;

/**
 * Hears the mouse over a node in a view (see {@link Node#addPointerListener}). Called on the event
 * thread; it may change the scene (the next frame shows it) and touch Swing components.
 */
@FunctionalInterface
public interface PointerListener {
    /**
     * The pointer did something to the node or to an object in it.
     *
     * @param event what, to which object, and what the frame shows under the pointer
     */
    void pointer(PointerEvent event);
}
