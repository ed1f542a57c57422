package dev.trisect.scene;

import java.awt.event.MouseEvent;

/**
 * The mouse over an object of a view's scene (as JavaFX's {@code MouseEvent} on a node): what
 * happened, to which object, and what the view's frame shows under the pointer. Delivered on the
 * event thread, first to the object and then to each group holding it, outermost last, until a
 * listener {@link #consume consumes} it (see {@link Node#addPointerListener}).
 *
 * <p>{@link Kind#ENTERED} and {@link Kind#EXITED} are not passed on: each node hears them itself,
 * once each time the pointer comes onto (or leaves) it or anything in it, as its own {@link #node()}.
 * A press, its drags and its release belong to the object pressed, wherever the pointer goes
 * meanwhile (the pick says what is under it now, and is null off every object).
 */
public final class PointerEvent {
    /** What the pointer did. */
    public enum Kind {
        /** The pointer came onto the node (onto one of its objects, for a group). */
        ENTERED,
        /** The pointer left the node. */
        EXITED,
        /** A button was pressed on the object. */
        PRESSED,
        /** The pointer moved with a button held, after a press on the object. */
        DRAGGED,
        /** The button of a press on the object was let go. */
        RELEASED,
        /** A press and release on the object without a drag between them. */
        CLICKED
    }

    private final Kind kind;
    private final SceneObject target;
    private final Node node;
    private final Pick pick;
    private final MouseEvent mouse;
    private boolean consumed;

    /**
     * @param kind   what happened
     * @param target the object it happened to
     * @param node   the node told of it now: the target or a group holding it
     * @param pick   what the frame on screen shows under the pointer, or null where it shows no object
     * @param mouse  the view's mouse event behind it (coordinates in the view, logical pixels)
     */
    public PointerEvent(Kind kind, SceneObject target, Node node, Pick pick, MouseEvent mouse) {
        this.kind = kind;
        this.target = target;
        this.node = node;
        this.pick = pick;
        this.mouse = mouse;
    }

    /**
     * What the pointer did.
     *
     * @return the kind of event
     */
    public Kind kind() {
        return kind;
    }

    /**
     * The object it happened to: under the pointer, or the one pressed for a drag and a release.
     *
     * @return the object
     */
    public SceneObject target() {
        return target;
    }

    /**
     * The node told of it now: the target itself, or a group holding it as the event is passed on.
     *
     * @return the node whose listener is called
     */
    public Node node() {
        return node;
    }

    /**
     * What the view's frame on screen shows under the pointer: object, triangle, exact 3D point, texel.
     *
     * @return the pick, or null where the pointer is over no object (a drag or release off the object,
     *         an exit)
     */
    public Pick pick() {
        return pick;
    }

    /**
     * The view's mouse event behind it, for its buttons, modifiers and position in the view.
     *
     * @return the mouse event
     */
    public MouseEvent mouse() {
        return mouse;
    }

    /**
     * Stops the event here: the groups further out do not hear it, and the view's camera controls
     * leave a consumed press (and its drag) alone.
     */
    public void consume() {
        consumed = true;
    }

    /**
     * Whether a listener consumed it.
     *
     * @return true once {@link #consume} was called
     */
    public boolean isConsumed() {
        return consumed;
    }

    /** Sets whether it is consumed (the result of passing it on). */
    void consumed(boolean c) {
        consumed = c;
    }

    /**
     * The same event as told to another node (the consumed state goes with it).
     *
     * @param other the node told next
     * @return an event for {@code other}
     */
    PointerEvent to(Node other) {
        PointerEvent e = new PointerEvent(kind, target, other, pick, mouse);
        e.consumed = consumed;
        return e;
    }

    @Override
    public String toString() {
        return kind + " " + target + (node == target ? "" : " at " + node);
    }
}
