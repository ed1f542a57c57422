package dev.trisect.scene;

import dev.trisect.base.internal.ChangeSignal;
import dev.trisect.math.Mat4;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Lines;
import dev.trisect.mesh.Mesh;
import dev.trisect.render.Colour;
import dev.trisect.render.Fog;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * Everything to draw: the top group of a tree of {@link Group}s and {@link SceneObject}s.
 *
 * <pre>{@code
 * Scene scene = new Scene();
 * scene.add(new SceneObject(Primitives.plane(20, 20, 20, 20), Material.of(ProceduralTextures.uvGrid(512))));
 * SceneObject cube = new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.crate(256)),
 *         Transform.translation(0, 0.5, 0));
 * scene.add(cube);
 * BufferedImage image = SceneRenderer.renderImage(scene, Camera.looking(new Vec3(3, 2, 4), Vec3.ZERO), 800, 600);
 * }</pre>
 *
 * <h2>Threads</h2>
 * Objects and groups may be added, removed, moved, hidden and given other materials from any thread
 * while a view or a {@link SceneRenderer} draws the scene. A frame draws one {@link #snapshot()} of
 * the scene, taken at one instant: it never shows half of a change to one node, nor loses a node
 * added while it was drawn (it is in the next frame). Changes made in separate calls may land in
 * different frames; to make several changes appear together, make them inside
 * {@link #update(Runnable)}. A change to one object never rebuilds another: the renderer keeps each
 * object's mesh as it is and applies the object's transform as it draws.
 */
public final class Scene extends Group {

    /**
     * One visible object as a frame draws it.
     *
     * @param object    the object
     * @param mesh      its mesh, object space
     * @param materials its materials, one per mesh material
     * @param world     object space to world space at the snapshot's instant
     * @param filled    whether its triangles are filled ({@link DrawStyle#fills})
     * @param lines     its own lines, object space
     * @param wire      its mesh's edges when its style draws them, else {@link Lines#EMPTY}
     * @param lineWidth the width of its lines and wire, pixels
     * @param billboards its billboards, points in object space
     * @param labels    its labels, points in object space
     */
    public record Placed(SceneObject object, Mesh mesh, List<Material> materials, Mat4 world, boolean filled,
                         Lines lines, Lines wire, int lineWidth, List<Billboard> billboards, List<Label> labels) {
    }

    /**
     * One shining light as a frame sees it.
     *
     * @param light  the light
     * @param kind   its kind
     * @param vector world space: a point light's position, the unit direction towards a directional
     *               light, zero for an ambient light
     * @param colour its colour
     * @param kc     constant attenuation (1 for lights that are not point lights)
     * @param kl     linear attenuation (0 for lights that are not point lights)
     * @param kq     quadratic attenuation (0 for lights that are not point lights)
     */
    public record PlacedLight(Light light, Light.Kind kind, Vec3 vector, Colour colour, double kc, double kl,
                              double kq) {
    }

    /**
     * The scene at one instant, as a frame draws it.
     *
     * @param objects the visible objects in drawing order, as {@link #snapshot()}
     * @param lights  the visible lights, depth-first
     * @param fog     the fog, if any
     */
    public record Snapshot(List<Placed> objects, List<PlacedLight> lights, Optional<Fog> fog) {
        /**
         * Keeps unmodifiable copies.
         *
         * @param objects the objects
         * @param lights  the lights
         * @param fog     the fog
         */
        public Snapshot {
            objects = List.copyOf(objects);
            lights = List.copyOf(lights);
            Objects.requireNonNull(fog, "fog is null: use Optional.empty()");
        }
    }

    /** Changes counted by {@link #version()}; written under {@link Node#LOCK}. */
    private volatile long version;
    private volatile Fog fog;
    private volatile List<ScreenText> screenText = List.of();

    /** An empty scene. */
    public Scene() {
        super("scene");
    }

    /**
     * A number that grows with every change to this scene that a frame would show: a node added,
     * removed, moved or shown or hidden, an object given other materials, anywhere in the tree. A value
     * set equal to the one in force (the same transform, light values, fog, screen text) is no change. A view
     * draws a new frame only when it grew (or something else changed), so it idles while the scene
     * stands still. Pixels written into a texture in place are not counted (the texture is not part
     * of the graph): ask a view for a frame then ({@code TrisectView.requestFrame()}).
     *
     * @return the count of changes so far, from 0
     */
    public long version() {
        return version;
    }

    /** One more change; under {@link Node#LOCK}. */
    void bump() {
        version++;
        // Idle views wake now, rather than at their next look.
        ChangeSignal.signal();
    }

    /**
     * Runs {@code changes} so that no frame shows some of them without the others: snapshots wait
     * until it returns. Keep it short (a view's next frame waits for it); the calls inside may be any
     * of the graph's methods, on any scene.
      *
     * @param changes the changes, run on the calling thread under the scene's lock
     * @throws NullPointerException when {@code changes} is null
     */
    public void update(Runnable changes) {
        Objects.requireNonNull(changes, "changes is null");
        LOCK.lock();
        try {
            changes.run();
        } finally {
            LOCK.unlock();
        }
    }

    /**
     * The visible objects as of now with their world matrices, in drawing order (depth-first, groups'
     * children in order). Hidden nodes and everything in hidden groups are left out.
      *
     * @return the visible objects as of now, in drawing order: an unmodifiable list
     */
    public List<Placed> snapshot() {
        return capture().objects();
    }

    /**
     * The visible objects and lights and the fog as of now, at one instant (see "Threads" above).
     *
     * @return the scene as a frame draws it
     */
    public Snapshot capture() {
        List<Placed> out = new ArrayList<>();
        List<PlacedLight> lights = new ArrayList<>();
        Fog f;
        LOCK.lock();
        try {
            if (isVisible()) {
                collect(this, matrix(), out, lights);
            }
            f = fog;
        } finally {
            LOCK.unlock();
        }
        return new Snapshot(out, lights, Optional.ofNullable(f));
    }

    private static void collect(Group group, Mat4 world, List<Placed> out, List<PlacedLight> lights) {
        for (Node n : group.children()) {
            if (!n.isVisible()) {
                continue;
            }
            Mat4 m = world.mul(n.matrix());
            if (n instanceof SceneObject o) {
                out.add(o.placed(m));
            } else if (n instanceof Light l) {
                lights.add(l.placed(m));
            } else {
                collect((Group) n, m, out, lights);
            }
        }
    }

    /**
     * Fogs the scene from the next frame on, or clears the fog: every pixel of every object, of its lines
     * and of its billboards is blended towards the fog's colour by its depth ({@link Fog}); the
     * background, labels and screen text are not: for a horizon that fades into the fog, draw on its
     * colour ({@code settings.withBackground(fog.colour().rgb())}).
     *
     * @param fog the fog, or null for none
     */
    public void setFog(Fog fog) {
        LOCK.lock();
        try {
            if (Objects.equals(fog, this.fog)) {
                return;
            }
            this.fog = fog;
            changed();
        } finally {
            LOCK.unlock();
        }
    }

    /**
     * The scene's fog.
     *
     * @return the fog, or empty for none
     */
    public Optional<Fog> fog() {
        return Optional.ofNullable(fog);
    }

    /**
     * Shows {@code texts} over every frame of the scene from the next frame on, anchored to the corners
     * of the screen, in order (a later one over an earlier one where they meet); replaces those shown
     * before.
     *
     * @param texts the screen texts; an empty list for none
     * @throws NullPointerException when the list or one of its texts is null
     */
    public void setScreenText(List<ScreenText> texts) {
        List<ScreenText> copy = copyOf(texts, "texts");
        LOCK.lock();
        try {
            if (copy.equals(this.screenText)) {
                return;
            }
            this.screenText = copy;
            changed();
        } finally {
            LOCK.unlock();
        }
    }

    /**
     * The text shown over the scene's frames.
     *
     * @return the screen texts, in order: an unmodifiable list
     */
    public List<ScreenText> screenText() {
        return screenText;
    }

    /**
     * Every object in the scene, visible or not, depth-first.
     *
     * @return every object, depth-first: an unmodifiable list
     */
    public List<SceneObject> objects() {
        List<SceneObject> out = new ArrayList<>();
        LOCK.lock();
        try {
            gather(this, out);
        } finally {
            LOCK.unlock();
        }
        return Collections.unmodifiableList(out);
    }

    private static void gather(Group group, List<SceneObject> out) {
        for (Node n : group.children()) {
            if (n instanceof SceneObject o) {
                out.add(o);
            } else if (n instanceof Group g) {
                gather(g, out);
            }
        }
    }
}
