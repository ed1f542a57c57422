package dev.trisect.content;

import dev.trisect.math.Vec3;
import dev.trisect.mesh.MeshBuilder;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.texture.ProceduralTextures;
import dev.trisect.texture.Texture;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Supplier;

/**
 * The built-in scenes, all procedural (no asset files). World units are metres; y is up; the
 * floor is the plane y = 0.
 */
public final class DemoScenes {
    /**
     * Floor half-size, metres. At 400 m a floor seen from eye height lies within a few pixels of the
     * horizon, so it reaches the horizon while keeping the triangle count modest.
     */
    private static final double FLOOR_HALF = 400;
    /** Cells per side: 10 m cells, large enough on screen near the camera for affine warping to show. */
    private static final int FLOOR_CELLS = 80;
    /** One repeat of the UV grid per cell, metres. */
    private static final double FLOOR_REPEAT = 10;

    private static final Map<String, Entry> SCENES = new LinkedHashMap<>();

    private record Entry(String description, Supplier<SceneAsset> build) {
    }

    static {
        SCENES.put("floor", new Entry("a floor with a labelled UV grid reaching to the horizon",
                DemoScenes::floor));
        SCENES.put("boxes", new Entry("textured crates on a checkered floor", DemoScenes::boxes));
        SCENES.put("demo", new Entry("the desktop demo's scene: floor, crates, a brick wall seen at a grazing "
                + "angle and a globe", DemoScenes::demo));
        // Textured spheres filling the view, for timing against the triangle count (4 n^2 triangles).
        SCENES.put("sphere", new Entry("a textured globe of 10,000 triangles filling the view",
                () -> sphere("sphere", 50)));
        SCENES.put("sphere100k", new Entry("the textured globe with 99,856 triangles",
                () -> sphere("sphere100k", 158)));
        SCENES.put("sphere160k", new Entry("the textured globe with 160,000 triangles",
                () -> sphere("sphere160k", 200)));
        SCENES.put("sphere1m", new Entry("the textured globe with 1,000,000 triangles",
                () -> sphere("sphere1m", 500)));
    }

    /**
     * The demo scene's sky, 0xRRGGBB: its background in the desktop demo and on the command line, the
     * background of {@link RenderSettings#display()}.
     */
    public static final int SKY = RenderSettings.SKY;

    private DemoScenes() {
    }

    /**
     * The background a built-in scene is drawn on by default, 0xRRGGBB: the sky for the demo scene,
     * black for the others (and for names that are not built-in).
     */
    public static int background(String name) {
        return "demo".equalsIgnoreCase(name) ? SKY : 0;
    }

    /** Names of the built-in scenes, in listing order. */
    public static List<String> names() {
        return List.copyOf(SCENES.keySet());
    }

    /** The one-line description of a built-in scene. */
    public static String describe(String name) {
        Entry e = SCENES.get(name);
        return e == null ? "" : e.description();
    }

    /** Builds the named scene, or empty if there is none by that name (case-insensitive). */
    public static Optional<SceneAsset> byName(String name) {
        Entry e = SCENES.get(name.toLowerCase(Locale.ROOT));
        return e == null ? Optional.empty() : Optional.of(e.build().get());
    }

    /** The floor alone, camera low and looking toward the horizon. */
    public static SceneAsset floor() {
        MeshBuilder b = new MeshBuilder();
        List<Texture> textures = new ArrayList<>();
        addFloor(b, textures, ProceduralTextures.uvGrid(512));
        Camera camera = new Camera(new Vec3(1.3, 1.7, 6.2), new Vec3(0.4, 0, -2), Vec3.UP,
                Camera.DEFAULT_FOV, Camera.DEFAULT_NEAR, Camera.DEFAULT_FAR);
        return new SceneAsset("floor", describe("floor"), b.build(), textures, camera);
    }

    /** A few crates on a checkered floor. */
    public static SceneAsset boxes() {
        MeshBuilder b = new MeshBuilder();
        List<Texture> textures = new ArrayList<>();
        addFloor(b, textures, ProceduralTextures.checker(256, 8, 0xFFD8D2C4, 0xFF5A6E8C));
        addCrates(b, textures);
        Camera camera = new Camera(new Vec3(3.5, 3.2, 7), new Vec3(-0.5, 0.8, -6), Vec3.UP,
                Camera.DEFAULT_FOV, Camera.DEFAULT_NEAR, Camera.DEFAULT_FAR);
        return new SceneAsset("boxes", describe("boxes"), b.build(), textures, camera);
    }

    /** Floor, crates, a long brick wall along the view direction, and a globe. */
    public static SceneAsset demo() {
        MeshBuilder b = new MeshBuilder();
        List<Texture> textures = new ArrayList<>();
        addFloor(b, textures, ProceduralTextures.uvGrid(512));
        addCrates(b, textures);
        b.material("bricks");
        textures.add(ProceduralTextures.bricks(512, 256));
        // A wall 3 m high running 80 m away from the camera: seen almost edge-on, it is where affine
        // texturing bends the courses of bricks the most. Front face toward -x (the camera's side).
        Primitives.grid(b, new Vec3(6, 0, -80), new Vec3(0, 0, 80), new Vec3(0, 3, 0), 4, 1, 0, 0, 20, 1);
        b.material("globe");
        textures.add(ProceduralTextures.globe(512, 256));
        Primitives.sphere(b, new Vec3(-3.5, 1.6, -9), 1.6, 32, 16);
        Camera camera = new Camera(new Vec3(0.5, 1.8, 6), new Vec3(0, 1.0, -10), Vec3.UP,
                Camera.DEFAULT_FOV, Camera.DEFAULT_NEAR, Camera.DEFAULT_FAR);
        return new SceneAsset("demo", describe("demo"), b.build(), textures, camera);
    }

    /** A globe of 4 n^2 triangles (2n slices, n + 1 stacks) filling most of the view. */
    static SceneAsset sphere(String name, int n) {
        MeshBuilder b = new MeshBuilder();
        List<Texture> textures = new ArrayList<>();
        b.material("globe");
        textures.add(ProceduralTextures.globe(1024, 512));
        Primitives.sphere(b, Vec3.ZERO, 1.6, 2 * n, n + 1);
        Camera camera = new Camera(new Vec3(0.6, 0.9, 3.6), Vec3.ZERO, Vec3.UP,
                Camera.DEFAULT_FOV, Camera.DEFAULT_NEAR, Camera.DEFAULT_FAR);
        return new SceneAsset(name, describe(name), b.build(), textures, camera);
    }

    private static void addFloor(MeshBuilder b, List<Texture> textures, Texture texture) {
        b.material("floor");
        textures.add(texture);
        Primitives.floor(b, -FLOOR_HALF, FLOOR_HALF, -FLOOR_HALF, FLOOR_HALF, 0, FLOOR_CELLS, FLOOR_CELLS,
                FLOOR_REPEAT);
    }

    private static void addCrates(MeshBuilder b, List<Texture> textures) {
        b.material("crate");
        textures.add(ProceduralTextures.crate(256));
        for (double[] c : CRATES) {
            Primitives.box(b, new Vec3(c[0], c[1], c[2]), new Vec3(c[3], c[3], c[3]));
        }
    }

    /** The crates of the demo and boxes scenes: centre x, y, z and side, metres. */
    private static final double[][] CRATES = {{0, 1, -6, 2}, {2.6, 0.6, -4, 1.2}, {-2.2, 0.75, -3.5, 1.5},
        {1.2, 2.5, -6.3, 1}, {-1, 1.5, -16, 3}};

    /**
     * Where the things of a built-in scene stand, for labels: each thing's name and the middle of its top,
     * world space, metres (the crates named by their size, the wall, the globe); empty for the floor, the
     * globes and names that are not built in.
     *
     * @param name a built-in scene's name, case-insensitive
     * @return name to point, in a fixed order
     */
    public static Map<String, Vec3> landmarks(String name) {
        String n = name.toLowerCase(Locale.ROOT);
        Map<String, Vec3> at = new LinkedHashMap<>();
        if (n.equals("demo") || n.equals("boxes")) {
            for (double[] c : CRATES) {
                at.put("crate " + (c[3] == Math.rint(c[3]) ? Long.toString(Math.round(c[3])) : Double.toString(c[3]))
                        + " m", new Vec3(c[0], c[1] + c[3] / 2, c[2]));
            }
        }
        if (n.equals("demo")) {
            at.put("brick wall, 80 m", new Vec3(6, 3, -12));
            at.put("globe", new Vec3(-3.5, 3.2, -9));
        }
        return at;
    }
}
