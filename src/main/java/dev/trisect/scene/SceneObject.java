package dev.trisect.scene;

import dev.trisect.base.InputException;
import dev.trisect.math.Transform;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.ObjModel;
import dev.trisect.mesh.ObjReader;
import dev.trisect.texture.ProceduralTextures;
import dev.trisect.texture.Texture;
import dev.trisect.texture.TextureReader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
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
    /** Mesh and materials together, swapped as one value. */
    private record Look(Mesh mesh, List<Material> materials) {
    }

    private volatile Look look;

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
        this.look = look(mesh, materials);
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
        Look next = look(look.mesh(), materials);
        LOCK.lock();
        try {
            look = next;
            changed();
        } finally {
            LOCK.unlock();
        }
    }

    /** Mesh and materials as one value, read under the lock by {@link Scene#snapshot()}. */
    Mesh lookMesh() {
        return look.mesh();
    }

    List<Material> lookMaterials() {
        return look.materials();
    }

    private static Look look(Mesh mesh, List<Material> materials) {
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
        return new Look(mesh, List.copyOf(copy));
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
     * the demo show such files), and {@code notes} hears of it. The object is named after the file.
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
        return load(ObjReader.read(obj, true), String.valueOf(obj.getFileName()), notes, placeholders);
    }

    /**
     * As {@link #load(Path, Consumer, boolean)}, from a model already read (with its materials, {@link
     * ObjReader#read ObjReader.read(obj, true)}), for a caller that also needs what the file named, such
     * as its texture files.
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
        List<Material> materials = new ArrayList<>();
        Map<Path, Material> loaded = new HashMap<>();
        Material grid = null;
        List<String> untextured = new ArrayList<>();
        // A material only lines use (OBJ l elements take its Kd) needs no texture: no note for it.
        boolean[] filled = new boolean[mesh.materialCount()];
        for (int m : mesh.triangleMaterials()) {
            filled[m] = true;
        }
        for (int i = 0; i < mesh.materialCount(); i++) {
            Path map = model.materialTextures().get(i);
            Integer kd = model.materialColours().get(i);
            if (map == null && kd != null) {
                materials.add(Material.colour(kd));
            } else if (map == null) {
                if (grid == null) {
                    grid = Material.of(ProceduralTextures.uvGrid(512));
                }
                materials.add(grid);
                if (filled[i]) {
                    untextured.add(mesh.materialNames().get(i));
                }
            } else {
                String source = model.textureSources().get(i);
                materials.add(loaded.computeIfAbsent(map, file -> {
                    try {
                        return Material.of(readMapKd(file, source));
                    } catch (InputException e) {
                        if (!placeholders) {
                            throw e;
                        }
                        notes.accept(e.getMessage() + "; drawn with a magenta checkerboard instead");
                        return Material.of(ProceduralTextures.checker(64, 8, 0xFFFF00FF, 0xFF000000));
                    }
                }));
            }
        }
        if (!untextured.isEmpty()) {
            notes.accept(name + ": no texture for material" + (untextured.size() > 1 ? "s " : " ")
                    + String.join(", ", untextured) + " (no map_Kd); using the built-in UV grid");
        }
        SceneObject o = new SceneObject(mesh, materials);
        o.setName(name);
        return o;
    }

    /** Reads a material's texture; a failure names the MTL file and line that gave it. */
    private static Texture readMapKd(Path file, String source) {
        try {
            return TextureReader.read(file);
        } catch (InputException e) {
            throw source == null ? e : new InputException(source + ": map_Kd: " + e.getMessage(), e);
        }
    }
}
