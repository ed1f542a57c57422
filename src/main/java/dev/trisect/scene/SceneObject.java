package dev.trisect.scene;

import dev.trisect.base.InputException;
import dev.trisect.math.Mat4;
import dev.trisect.math.Transform;
import dev.trisect.mesh.LineShapes;
import dev.trisect.mesh.Lines;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.mesh.ObjModel;
import dev.trisect.mesh.ObjReader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Objects;
import java.util.function.Consumer;

/**
 * A mesh drawn with its materials at a place in the scene (as JavaFX's {@code MeshView},
 * jMonkeyEngine's {@code Geometry}).
 *
 * <pre>{@code
 * SceneObject cube = new SceneObject(Primitives.box(1, 1, 1), Material.of(crate));
 * cube.setTransform(Transform.translation(0, 0.5, 0).withRotation(Quaternion.ofY(30)));
 * scene.add(cube);
 * }</pre>
 *
 * <p>The mesh is immutable and may be shared by many objects; moving, hiding or re-materialling an
 * object changes nothing of any other. Every method may be called from any thread.
 */
public final class SceneObject extends Node {
    /**
     * Everything drawn, swapped as one value: the mesh and its materials, the object's own lines, the
     * lines' width, the mesh's style, its wire colour and (when the style draws it) its wireframe.
     */
    private record Look(Mesh mesh, List<Material> materials, Lines lines, int lineWidth, DrawStyle style,
                        int wireColour, Lines wire) {
        Look with(DrawStyle style, int wireColour) {
            Lines edges = !style.wires() ? Lines.EMPTY
                    : wire.isEmpty() || this.wireColour != wireColour ? LineShapes.edges(mesh, wireColour) : wire;
            return new Look(mesh, materials, lines, lineWidth, style, wireColour, edges);
        }
    }

    /** The mesh of an object of lines alone: no triangles. */
    private static final Mesh NO_TRIANGLES = new MeshBuilder().build();

    private volatile Look look;
    /** The object's billboards and labels, replaced whole under {@link Node#LOCK}. */
    private volatile List<Billboard> billboards = List.of();
    private volatile List<Label> labels = List.of();

    private static final String NOTES_NULL = "notes is null: pass note -> { } to ignore them";

    /**
     * An object drawing every material of {@code mesh} with {@code material}.
     *
     * @param mesh     the mesh, object space; shared freely
     * @param material drawn for every material of the mesh
     * @throws NullPointerException when either is null
     */
    public SceneObject(Mesh mesh, Material material) {
        this(mesh, Collections.nCopies(Objects.requireNonNull(mesh, "mesh is null").materialCount(),
                Objects.requireNonNull(material, "material is null: use Material.of(texture) or Material.colour(rgb)")));
    }

    /**
     * An object drawing {@code mesh} with one material per mesh material, in the mesh's material order
     * ({@link Mesh#materialNames()}).
     *
     * @param mesh      the mesh, object space; shared freely
     * @param materials one per mesh material, in its order
     * @throws NullPointerException     when the mesh, the list or one of its materials is null
     * @throws IllegalArgumentException when the list's size is not the mesh's material count
     */
    public SceneObject(Mesh mesh, List<Material> materials) {
        super(null);
        this.look = new Look(mesh, checked(mesh, materials), Lines.EMPTY, 1, DrawStyle.FILLED, 0xFFFFFF, Lines.EMPTY);
    }

    /**
     * An object of lines alone, such as {@link LineShapes#axes}, a grid or a wire box: no triangles.
     *
     * @param lines the segments, object space
     * @param width their width in whole pixels, 1 to 255
     * @return the object
     * @throws IllegalArgumentException when the width is out of range
     */
    public static SceneObject lines(Lines lines, int width) {
        SceneObject o = new SceneObject(NO_TRIANGLES, Material.colour(0xFFFFFF));
        o.setLines(lines);
        o.setLineWidth(width);
        return o;
    }

    /**
     * An object of billboards alone: no triangles.
     *
     * @param billboards the billboards, their points in object space
     * @return the object
     * @throws NullPointerException when the list or one of its billboards is null
     */
    public static SceneObject billboards(List<Billboard> billboards) {
        SceneObject o = new SceneObject(NO_TRIANGLES, Material.colour(0xFFFFFF));
        o.setBillboards(billboards);
        return o;
    }

    /**
     * An object of labels alone: no triangles.
     *
     * @param labels the labels, their points in object space
     * @return the object
     * @throws NullPointerException when the list or one of its labels is null
     */
    public static SceneObject labels(List<Label> labels) {
        SceneObject o = new SceneObject(NO_TRIANGLES, Material.colour(0xFFFFFF));
        o.setLabels(labels);
        return o;
    }

    /**
     * The object's billboards, moved with it (none unless set).
     *
     * @return the billboards: an unmodifiable list
     */
    public List<Billboard> billboards() {
        return billboards;
    }

    /**
     * Draws {@code billboards} with the object from the next frame on, their points moved as its mesh is.
     *
     * @param billboards the billboards, in object space; an empty list for none
     * @throws NullPointerException when the list or one of its billboards is null
     */
    public void setBillboards(List<Billboard> billboards) {
        List<Billboard> copy = copyOf(billboards, "billboards");
        LOCK.lock();
        try {
            if (copy.equals(this.billboards)) {
                return;
            }
            this.billboards = copy;
            changed();
        } finally {
            LOCK.unlock();
        }
    }

    /**
     * The object's labels, moved with it (none unless set).
     *
     * @return the labels: an unmodifiable list
     */
    public List<Label> labels() {
        return labels;
    }

    /**
     * Draws {@code labels} with the object from the next frame on, their points moved as its mesh is.
     *
     * @param labels the labels, in object space; an empty list for none
     * @throws NullPointerException when the list or one of its labels is null
     */
    public void setLabels(List<Label> labels) {
        List<Label> copy = copyOf(labels, "labels");
        LOCK.lock();
        try {
            if (copy.equals(this.labels)) {
                return;
            }
            this.labels = copy;
            changed();
        } finally {
            LOCK.unlock();
        }
    }

    /**
     * An object drawing {@code mesh} with {@code material}, placed by {@code transform}.
     *
     * @param mesh      the mesh, object space; shared freely
     * @param material  drawn for every material of the mesh
     * @param transform the object's place in its parent's space
     */
    public SceneObject(Mesh mesh, Material material, Transform transform) {
        this(mesh, material);
        setTransform(transform);
    }

    /**
     * The mesh, in object space.
     *
     * @return the mesh
     */
    public Mesh mesh() {
        return look.mesh();
    }

    /**
     * The materials, one per mesh material: an unmodifiable list.
     *
     * @return the materials, by mesh material
     */
    public List<Material> materials() {
        return look.materials();
    }

    /**
     * Draws every material of the mesh with {@code material} from the next frame on.
     *
     * @param material the material for every mesh material
     */
    public void setMaterial(Material material) {
        Objects.requireNonNull(material, "material is null: use Material.of(texture) or Material.colour(rgb)");
        setMaterials(Collections.nCopies(look.mesh().materialCount(), material));
    }

    /**
     * Replaces the materials (one per mesh material) from the next frame on.
     *
     * @param materials one per mesh material, in its order
     */
    public void setMaterials(List<Material> materials) {
        change(l -> new Look(l.mesh(), checked(l.mesh(), materials), l.lines(), l.lineWidth(), l.style(),
                l.wireColour(), l.wire()));
    }

    /**
     * The object's own lines, object space, drawn with it in every style ({@link Lines#EMPTY} unless set).
     *
     * @return the lines
     */
    public Lines lines() {
        return look.lines();
    }

    /**
     * Draws {@code lines} with the object from the next frame on, moved as its mesh is.
     *
     * @param lines the segments, object space
     */
    public void setLines(Lines lines) {
        Objects.requireNonNull(lines, "lines is null: use Lines.EMPTY for none");
        change(l -> new Look(l.mesh(), l.materials(), lines, l.lineWidth(), l.style(), l.wireColour(), l.wire()));
    }

    /**
     * The width of the object's lines and wireframe, whole pixels.
     *
     * @return the width, 1 unless set
     */
    public int lineWidth() {
        return look.lineWidth();
    }

    /**
     * Sets the width of the object's lines and wireframe from the next frame on, as OpenGL's
     * {@code glLineWidth} for aliased lines.
     *
     * @param width whole pixels, 1 to 255 (a view's logical pixels: on a high-density screen, the screen's
     *              scale times as many device pixels)
     * @throws IllegalArgumentException when out of range
     */
    public void setLineWidth(int width) {
        if (width < 1 || width > 255) {
            throw new IllegalArgumentException("line width must be 1 to 255 pixels, got " + width);
        }
        change(l -> new Look(l.mesh(), l.materials(), l.lines(), width, l.style(), l.wireColour(), l.wire()));
    }

    /**
     * How the mesh is drawn: filled, as wire (its edges) or both.
     *
     * @return the style, {@link DrawStyle#FILLED} unless set
     */
    public DrawStyle drawStyle() {
        return look.style();
    }

    /**
     * Draws the mesh filled, as wire or both from the next frame on. The wireframe, each edge two
     * triangles share once ({@link LineShapes#edges}), is made here, once per mesh and colour.
     *
     * @param style the style
     */
    public void setDrawStyle(DrawStyle style) {
        Objects.requireNonNull(style, "style is null");
        change(l -> l.with(style, l.wireColour()));
    }

    /**
     * The colour of the wireframe.
     *
     * @return 0xRRGGBB, white unless set
     */
    public int wireColour() {
        return look.wireColour();
    }

    /**
     * Sets the colour of the wireframe from the next frame on.
     *
     * @param rgb 0xRRGGBB
     */
    public void setWireColour(int rgb) {
        change(l -> l.with(l.style(), rgb & 0xFFFFFF));
    }

    /** Replaces the look by {@code next} of the current one, atomically against snapshots and other changes. */
    private void change(java.util.function.UnaryOperator<Look> next) {
        LOCK.lock();
        try {
            Look changed = next.apply(look);
            if (changed.equals(look)) {
                // The same mesh, materials, lines and style: no change (a setter given what is in force).
                return;
            }
            look = changed;
            changed();
        } finally {
            LOCK.unlock();
        }
    }

    /** The look as one value, read under the lock by {@link Scene#snapshot()}. */
    Scene.Placed placed(Mat4 world) {
        Look l = look;
        return new Scene.Placed(this, l.mesh(), l.materials(), world, l.style().fills(), l.lines(), l.wire(),
                l.lineWidth(), billboards, labels);
    }

    private static List<Material> checked(Mesh mesh, List<Material> materials) {
        Objects.requireNonNull(mesh, "mesh is null");
        Objects.requireNonNull(materials, "materials list is null");
        List<Material> copy = new ArrayList<>(materials.size());
        for (int i = 0; i < materials.size(); i++) {
            copy.add(Objects.requireNonNull(materials.get(i), "material " + i + " (" + (i < mesh.materialCount()
                    ? mesh.materialNames().get(i) : "beyond the mesh's") + ") is null: use Material.of(texture) "
                    + "or Material.colour(rgb)"));
        }
        if (copy.size() != mesh.materialCount()) {
            throw new IllegalArgumentException("the mesh has " + mesh.materialCount() + " materials "
                    + mesh.materialNames() + " but " + copy.size() + " were given");
        }
        return List.copyOf(copy);
    }

    /**
     * {@link #load(Path, Consumer)} without remarks.
     *
     * @param obj the OBJ file
     * @return the object, named after the file
     */
    public static SceneObject load(Path obj) {
        return load(obj, note -> { });
    }

    /**
     * An object from a Wavefront OBJ file and the textures its MTL files name ({@code map_Kd}). A
     * material without a texture is its diffuse colour ({@code Kd}) where the MTL gives one, as
     * {@link Material#colour(int)}; with neither it gets the built-in UV grid (as the command line and
     * the demo show such files), and {@code notes} hears of it. The file's {@code l} elements are the
     * object's {@link #lines()}, one pixel wide, each coloured by its material's {@code Kd} as the
     * command line colours it. The object is named after the file.
     *
     * @param obj   the OBJ file
     * @param notes receives one-line remarks for the user (never errors; those are thrown)
     * @return the object, named after the file
     * @throws NullPointerException when {@code obj} or {@code notes} is null
     * @throws InputException for anything unreadable, with a one-line message naming the file and line
     */
    public static SceneObject load(Path obj, Consumer<String> notes) {
        return load(obj, notes, false);
    }

    /**
     * As {@link #load(Path, Consumer)}, but where {@code placeholders} is true a {@code map_Kd}
     * texture that cannot be read (missing, unreadable, not an image) does not reject the model: its
     * materials get a magenta and black checkerboard that no real texture is mistaken for, and
     * {@code notes} hears the one-line message the strict load would have thrown. For viewers, where a
     * model with one lost texture is still worth seeing; renders that must be exact use the strict load.
     *
     * @param obj          the OBJ file
     * @param notes        receives one-line remarks for the user
     * @param placeholders whether an unreadable texture gets a placeholder (true) or rejects the model
     * @return the object, named after the file
     * @throws InputException for anything else unreadable, with a one-line message naming the file and line
     */
    public static SceneObject load(Path obj, Consumer<String> notes, boolean placeholders) {
        Objects.requireNonNull(obj, "OBJ path is null");
        Objects.requireNonNull(notes, NOTES_NULL);
        return load(ObjReader.read(obj, true, notes), String.valueOf(obj.getFileName()), notes, placeholders);
    }

    /**
     * As {@link #load(Path, Consumer, boolean)}, from a model already read (with its materials, {@link
     * ObjReader#read(Path, boolean, Consumer) ObjReader.read(obj, true, notes)}), for a caller that also
     * needs what the file named, such as its texture files.
     *
     * @param model        the OBJ file as read, with each material's {@code map_Kd} file
     * @param name         the object's name, and the file named in notes (the OBJ file's name)
     * @param notes        receives one-line remarks for the user
     * @param placeholders whether an unreadable texture gets a placeholder (true) or rejects the model
     * @return the object
     * @throws InputException for a texture that cannot be read (without {@code placeholders}), with a
     *                        one-line message naming the MTL file and line
     */
    public static SceneObject load(ObjModel model, String name, Consumer<String> notes, boolean placeholders) {
        // Checked before any work: notes is called only for some files, so a null one would pass most.
        Objects.requireNonNull(notes, NOTES_NULL);
        Mesh mesh = model.mesh();
        List<Material> materials = ObjMaterials.of(model, name, notes, placeholders);
        SceneObject o = new SceneObject(mesh, materials);
        // The file's l elements, coloured by their material's Kd, as the command line draws them.
        o.setLines(model.lines());
        o.setName(name);
        return o;
    }
}
