package dev.trisect.scene;

import dev.trisect.math.Mat4;
import dev.trisect.math.Transform;
import java.awt.event.KeyEvent;
import java.awt.event.KeyListener;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.locks.ReentrantLock;

/**
 * Something in a {@link Scene}: a {@link Group}, a {@link SceneObject} or a {@link Light}. A node has a
 * {@link Transform} (its place in its parent's space), can be hidden, and belongs to at most one
 * group at a time.
 *
 * <p>Every method may be called from any thread, also while a renderer draws the scene: see
 * {@link Scene} for what a frame sees.
 */
public abstract sealed class Node permits Group, SceneObject, Light {
    /**
     * Guards every change to a scene graph and every {@link Scene#snapshot()}. One lock for all scenes:
     * a change holds it for microseconds, a snapshot for a walk over the visible nodes, and a node can
     * move between scenes without two locks to order.
     */
    static final ReentrantLock LOCK = new ReentrantLock();

    private volatile Transform transform = Transform.IDENTITY;
    /** {@code transform.matrix()}, kept with it. */
    private volatile Mat4 matrix = Transform.IDENTITY.matrix();
    private volatile boolean visible = true;
    private volatile String name;
    /** The group holding this node, or null. Written under {@link #LOCK}. */
    volatile Group parent;
    private final List<PointerListener> pointerListeners = new CopyOnWriteArrayList<>();
    private final List<KeyListener> keyListeners = new CopyOnWriteArrayList<>();
    private volatile Highlight hoverHighlight;

    Node(String name) {
        this.name = name;
    }

    /**
     * The node's place in its parent's space (in world space for a node at the top of a scene).
     *
     * @return the node's own transform
     */
    public Transform transform() {
        return transform;
    }

    /**
     * Places the node; takes effect from the next frame drawn. The node's points go through
     * {@code transform} and then through each enclosing group's transform.
     *
     * @param transform the new transform, in the parent's space
     * @throws NullPointerException     when {@code transform} is null
     * @throws IllegalArgumentException when, combined with the enclosing groups' transforms (or, for a
     *                                  group, with those of the nodes in it), it would give an object a
     *                                  world matrix that is not finite (a group scaled 1e200 holding an
     *                                  object scaled 1e200); the node keeps its transform
     */
    public void setTransform(Transform transform) {
        Objects.requireNonNull(transform, "transform is null: use Transform.IDENTITY for none");
        Mat4 m = transform.matrix();
        LOCK.lock();
        try {
            if (transform.equals(this.transform)) {
                // An equal value is no change: a hook or listener setting it every frame leaves a still view idle.
                return;
            }
            Group p = parent;
            // Its cause is built only for a message: built on every move, it took most of the move's time.
            checkWorld(this, p == null ? m : p.worldMatrix().mul(m), () -> "its transform " + transform);
            this.transform = transform;
            this.matrix = m;
            changed();
        } finally {
            LOCK.unlock();
        }
    }

    /**
     * Whether the node is drawn (when its groups are too).
     *
     * @return true unless hidden
     */
    public boolean isVisible() {
        return visible;
    }

    /**
     * Shows or hides the node, and for a group everything in it.
     *
     * @param visible true to show, false to hide
     */
    public void setVisible(boolean visible) {
        LOCK.lock();
        try {
            if (visible == this.visible) {
                return;
            }
            this.visible = visible;
            changed();
        } finally {
            LOCK.unlock();
        }
    }

    /**
     * The node's name, for the application's own use; may be null.
     *
     * @return the name, or null
     */
    public String name() {
        return name;
    }

    /**
     * Names the node (any string, or null).
     *
     * @param name the new name, or null
     */
    public void setName(String name) {
        this.name = name;
    }

    /**
     * The group this node is in, or null when it is in none.
     *
     * @return the enclosing group, or null
     */
    public Group parent() {
        return parent;
    }

    /**
     * Object space to world space as of now: the transforms of the node and of every enclosing group,
     * innermost applied first.
      *
     * @return object space to world space, as of now
     */
    public Mat4 worldMatrix() {
        LOCK.lock();
        try {
            Mat4 m = matrix;
            for (Group g = parent; g != null; g = g.parent) {
                m = g.matrix().mul(m);
            }
            return m;
        } finally {
            LOCK.unlock();
        }
    }

    /**
     * An unmodifiable copy of {@code list}, whose every element is checked first, so that a null names
     * the list and where it is rather than failing as a bare {@link NullPointerException}.
     *
     * @param what the list's name in the messages ("labels")
     * @throws NullPointerException when the list or one of its elements is null
     */
    static <T> List<T> copyOf(List<T> list, String what) {
        Objects.requireNonNull(list, () -> what + " is null: use List.of()");
        for (int i = 0; i < list.size(); i++) {
            if (list.get(i) == null) {
                throw new NullPointerException(what + " holds null at index " + i);
            }
        }
        return List.copyOf(list);
    }

    /**
     * Checks, under {@link #LOCK}, that {@code node} placed by {@code world} (its world matrix as it would
     * be) and every node under it get finite world matrices: a product of valid transforms can overflow,
     * and an object whose matrix holds an infinity would vanish from every frame without a word.
     *
     * @param cause what would place it so, for the message (asked for only when there is one)
     * @throws IllegalArgumentException naming the node, its world matrix's largest entry and the cause
     */
    static void checkWorld(Node node, Mat4 world, java.util.function.Supplier<String> cause) {
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 4; c++) {
                if (!Double.isFinite(world.get(r, c))) {
                    throw new IllegalArgumentException(cause.get() + " would give " + node + " a world matrix that is not "
                            + "finite (" + world.get(r, c) + " in row " + r + ", column " + c + "): the enclosing "
                            + "groups' transforms and its own multiply beyond double range");
                }
            }
        }
        if (node instanceof Group g) {
            for (Node n : g.children()) {
                checkWorld(n, world.mul(n.matrix), cause);
            }
        }
    }

    /**
     * Hears the mouse over this node in a view: for an object, the pointer entering and leaving it,
     * presses, drags, releases and clicks on it; for a group, the same for every object in it (each
     * passed on from the object unless a listener nearer it consumed it), and entering and leaving the
     * group as a whole. On the event thread (see {@link PointerEvent}). A view reads which object
     * each pixel shows from the triangle ids every frame of it records: listening costs no frame time.
     * The pointer is over an object where a pick finds it ({@link SceneRenderer#pick}): on its opaque and
     * alpha-tested triangles, not on its blended ones, lines, billboards or labels.
     *
     * @param listener told of each event
     */
    public void addPointerListener(PointerListener listener) {
        pointerListeners.add(Objects.requireNonNull(listener, "listener is null"));
    }

    /**
     * Stops telling a listener about the mouse.
     *
     * @param listener one added before
     */
    public void removePointerListener(PointerListener listener) {
        pointerListeners.remove(listener);
    }

    /**
     * Whether anything listens to the mouse over this node.
     *
     * @return true when a pointer listener is added
     */
    public boolean hasPointerListeners() {
        return !pointerListeners.isEmpty();
    }

    /**
     * Tells this node's pointer listeners of {@code event} and then, unless one consumed it, those of
     * each group holding it, outermost last; entering and leaving are told to this node alone. Views
     * call it; a program may, to make events of its own.
     *
     * @param event what happened; its {@link PointerEvent#node()} should be this node
     */
    public void firePointerEvent(PointerEvent event) {
        PointerEvent e = event;
        for (Node n = this; n != null; n = n.parent) {
            if (n != this) {
                e = e.to(n);
            }
            for (PointerListener l : n.pointerListeners) {
                l.pointer(e);
            }
            if (e.isConsumed() || e.kind() == PointerEvent.Kind.ENTERED || e.kind() == PointerEvent.Kind.EXITED) {
                event.consumed(e.isConsumed());
                return;
            }
        }
    }

    /**
     * Marks this node in a view while the pointer is over it — for a group, all of it while the pointer
     * is over any object in it — or stops doing so. The nearest node holding a highlight wins.
     *
     * @param highlight how to mark it ({@link Highlight#tint}, {@link Highlight#outline}), or null for none
     */
    public void setHoverHighlight(Highlight highlight) {
        LOCK.lock();
        try {
            hoverHighlight = highlight;
            changed();
        } finally {
            LOCK.unlock();
        }
    }

    /**
     * How this node is marked while the pointer is over it.
     *
     * @return the highlight, or null for none
     */
    public Highlight hoverHighlight() {
        return hoverHighlight;
    }

    /**
     * Hears the keys while this node has a view's keyboard ({@code TrisectView.giveKeyboard}), or one
     * of the nodes in it has and did not consume them: before the view's own keys (camera, commands),
     * which a consumed key does not reach. On the event thread.
     *
     * @param listener told of each key event
     */
    public void addKeyListener(KeyListener listener) {
        keyListeners.add(Objects.requireNonNull(listener, "listener is null"));
    }

    /**
     * Stops telling a listener about keys.
     *
     * @param listener one added before
     */
    public void removeKeyListener(KeyListener listener) {
        keyListeners.remove(listener);
    }

    /**
     * Tells this node's key listeners of {@code event} and then, unless one consumed it, those of each
     * group holding it, outermost last. Views call it for the node holding their keyboard.
     *
     * @param event a key pressed, released or typed
     */
    public void fireKeyEvent(KeyEvent event) {
        for (Node n = this; n != null && !event.isConsumed(); n = n.parent) {
            for (KeyListener l : n.keyListeners) {
                switch (event.getID()) {
                    case KeyEvent.KEY_PRESSED -> l.keyPressed(event);
                    case KeyEvent.KEY_RELEASED -> l.keyReleased(event);
                    default -> l.keyTyped(event);
                }
            }
        }
    }

    /**
     * Counts a change a frame would show in the scene this node is in (nothing when it is in none):
     * see {@link Scene#version()}. Under {@link #LOCK}.
     */
    final void changed() {
        Node top = this;
        while (top.parent != null) {
            top = top.parent;
        }
        if (top instanceof Scene s) {
            s.bump();
        }
    }

    /** The transform's matrix; read under {@link #LOCK} for a consistent frame. */
    Mat4 matrix() {
        return matrix;
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + (name == null ? "" : " " + name);
    }
}
