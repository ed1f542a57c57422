package dev.trisect.scene;

import dev.trisect.math.Mat4;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/**
 * Nodes that are placed, shown and hidden together: a group's transform applies to everything in it,
 * and hiding the group hides all of it (as JavaFX's {@code Group}, jMonkeyEngine's {@code Node}).
 *
 * <pre>{@code
 * Group crates = new Group("crates");
 * crates.add(new SceneObject(Primitives.box(1, 1, 1), Material.of(crate)));
 * scene.add(crates);
 * crates.setVisible(false);   // from any thread, while a view draws
 * }</pre>
 */
public sealed class Group extends Node permits Scene {
    /** Copy-on-write: replaced whole under {@link Node#LOCK}, so a reader never sees a half-made list. */
    private volatile List<Node> children = List.of();

    /** An empty, unnamed group. */
    public Group() {
        super(null);
    }

    /**
     * An empty group with a name.
     *
     * @param name the group's name, or null
     */
    public Group(String name) {
        super(name);
    }

    /**
     * Adds nodes at the end of this group. A node already in a group (this one included) is moved
     * here; a node is never in two groups.
     *
     * @param nodes the nodes to add, in order
     * @return this group, for chaining
     * @throws NullPointerException     for a null node (and nothing is added)
     * @throws IllegalArgumentException for a {@link Scene}, a group that holds this one (a cycle), or a node
     *                                  whose transform, combined with this group's world matrix, would give an
     *                                  object a world matrix that is not finite; nothing is added
     */
    public Group add(Node... nodes) {
        for (Node n : nodes) {
            Objects.requireNonNull(n, "cannot add a null node");
        }
        LOCK.lock();
        try {
            // Every node is checked before any is added, so that a refused call changes nothing.
            for (Node n : nodes) {
                if (n instanceof Scene) {
                    throw new IllegalArgumentException("a scene cannot be added to a group");
                }
                for (Group g = this; g != null; g = g.parent) {
                    if (g == n) {
                        throw new IllegalArgumentException(n + " holds " + this + ": adding it would make a cycle");
                    }
                }
            }
            Mat4 world = worldMatrix();
            for (Node n : nodes) {
                checkWorld(n, world.mul(n.matrix()), () -> "adding it to " + this);
            }
            for (Node n : nodes) {
                if (n.parent != null) {
                    // The scene it leaves changes too.
                    n.parent.changed();
                    n.parent.detach(n);
                }
                List<Node> grown = new ArrayList<>(children.size() + 1);
                grown.addAll(children);
                grown.add(n);
                children = List.copyOf(grown);
                n.parent = this;
            }
            changed();
            return this;
        } finally {
            LOCK.unlock();
        }
    }

    /**
     * Takes a node out of this group.
     *
     * @param node the node to take out
     * @return whether it was in this group
     */
    public boolean remove(Node node) {
        LOCK.lock();
        try {
            if (node == null || node.parent != this) {
                return false;
            }
            detach(node);
            changed();
            return true;
        } finally {
            LOCK.unlock();
        }
    }

    /** Takes every node out of this group. */
    public void clear() {
        LOCK.lock();
        try {
            for (Node n : children) {
                n.parent = null;
            }
            children = List.of();
            changed();
        } finally {
            LOCK.unlock();
        }
    }

    /**
     * The nodes in this group as of now, in order: an unmodifiable copy.
     *
     * @return the children, in order
     */
    public List<Node> children() {
        return children;
    }

    /** Removes {@code n}, a child of this group; under {@link Node#LOCK}. */
    private void detach(Node n) {
        List<Node> kept = new ArrayList<>(children);
        kept.remove(n);
        children = List.copyOf(kept);
        n.parent = null;
    }
}
