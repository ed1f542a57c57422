package dev.trisect.cli;

import dev.trisect.base.InputException;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.content.SceneLoader;
import dev.trisect.math.Vec3;
import dev.trisect.render.CullMode;
import dev.trisect.scene.Camera;
import java.nio.file.Path;
import java.util.function.Consumer;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** What to draw and from where: scene, camera, frame size, culling, background. Shared by the commands. */
final class FrameOptions {
    @Spec(Spec.Target.MIXEE)
    CommandSpec spec;

    @Option(names = "--obj", paramLabel = "FILE",
            description = "Wavefront OBJ file to render (its mtllib/map_Kd supply textures unless --texture is given).")
    Path obj;

    @Option(names = "--scene", paramLabel = "NAME",
            description = "Built-in scene to render, not with --obj (default: ${DEFAULT-VALUE}; "
                    + "see --list-scenes).", defaultValue = "floor")
    String scene;

    @Option(names = "--texture", paramLabel = "FILE",
            description = "Texture for every material of the OBJ: PNG, JPEG, BMP, GIF, TGA, PBM, PGM, PPM or PAM "
                    + "(default: the OBJ's map_Kd textures).")
    Path texture;

    @Option(names = "--list-scenes", description = "List the built-in scenes and exit.")
    boolean listScenes;

    @Option(names = "--size", paramLabel = "WxH", converter = Converters.SizeConverter.class,
            defaultValue = "1280x720", description = "Frame size in pixels (default: ${DEFAULT-VALUE}).")
    Converters.Size size;

    @Option(names = "--eye", paramLabel = "x,y,z", converter = Converters.Vec3Converter.class,
            description = "Camera position, world space (default: the scene's camera).")
    Vec3 eye;

    @Option(names = "--target", paramLabel = "x,y,z", converter = Converters.Vec3Converter.class,
            description = "Point the camera looks at, world space (default: the scene's camera).")
    Vec3 target;

    @Option(names = "--up", paramLabel = "x,y,z", converter = Converters.Vec3Converter.class,
            defaultValue = "0,1,0", description = "Camera up direction, world space (default: ${DEFAULT-VALUE}).")
    Vec3 up;

    @Option(names = "--fov", paramLabel = "DEG", defaultValue = "60",
            description = "Vertical field of view in degrees, from 1e-6 up to 180 (default: ${DEFAULT-VALUE}).")
    double fov;

    @Option(names = "--near", paramLabel = "N",
            description = "Near plane distance, world units (default: 0.1; an OBJ's own camera may need less).")
    Double near;

    @Option(names = "--far", paramLabel = "F",
            description = "Far plane distance, world units (default: 1000; an OBJ's own camera may need more).")
    Double far;

    @Option(names = "--cull", paramLabel = "back|none", converter = Converters.CullConverter.class,
            defaultValue = "back",
            description = "Drop triangles seen from behind (counter-clockwise = front), or none (default: back).")
    CullMode cull;

    @Option(names = "--background", paramLabel = "RRGGBB", converter = Converters.ColourConverter.class,
            description = "Background colour (default: the scene's: 9DB8D3 sky for demo, as in the desktop demo; "
                    + "000000 otherwise).")
    Integer background;

    @Option(names = "--line-width", paramLabel = "PX", defaultValue = "1",
            description = "Width of the OBJ's lines (l elements) in whole pixels, 1 to 255, as OpenGL's glLineWidth "
                    + "(default: ${DEFAULT-VALUE}).")
    int lineWidth;

    /** The lines' width in pixels, checked. */
    int lineWidth() {
        if (lineWidth < 1 || lineWidth > MAX_LINE_WIDTH) {
            throw InputException.usage("--line-width must be a whole number of pixels from 1 to " + MAX_LINE_WIDTH
                    + ", got " + lineWidth);
        }
        return lineWidth;
    }

    /** Widest line accepted, pixels: llvmpipe's limit (GL_ALIASED_LINE_WIDTH_RANGE). */
    static final int MAX_LINE_WIDTH = 255;

    /** The background colour, 0xRRGGBB: the one given, or the scene's own. */
    int background() {
        return background != null ? background : obj != null ? 0 : DemoScenes.background(scene);
    }

    /** Prints the built-in scenes. */
    static void listScenes(java.io.PrintWriter out) {
        int width = 0;
        for (String name : DemoScenes.names()) {
            width = Math.max(width, name.length());
        }
        for (String name : DemoScenes.names()) {
            out.printf("%-" + width + "s  %s%n", name, DemoScenes.describe(name));
        }
        out.flush();
    }

    /** Loads the scene the options name; notes for the user go to {@code notes}. */
    SceneAsset loadScene(Consumer<String> notes) {
        if (obj != null) {
            // Both name what to draw: taking one and silently dropping the other would draw what was not asked.
            if (spec.commandLine().getParseResult().hasMatchedOption("--scene")) {
                throw InputException.usage("--obj and --scene both name what to draw; give one of them");
            }
            try {
                return SceneLoader.load(obj, texture, notes);
            } catch (OutOfMemoryError e) {
                // Reading comes before any frame: --size cannot help here, only a larger heap.
                throw new InputException(obj + ": not enough memory to read this model (give Java more with -Xmx, "
                        + "e.g. java -Xmx4g -jar trisect.jar)");
            }
        }
        if (texture != null) {
            throw InputException.usage("--texture applies to --obj; the built-in scenes bring their own textures");
        }
        return DemoScenes.byName(scene).orElseThrow(() -> InputException.usage(
                "unknown scene '" + scene + "' (built-in scenes: " + String.join(", ", DemoScenes.names()) + ")"));
    }

    /** The camera: the scene's, with whatever the options set in its place. */
    Camera camera(SceneAsset s) {
        Camera own = s.camera();
        double n = near != null ? near : own.near();
        double f = far != null ? far : own.far();
        if (!Double.isFinite(fov)) {
            throw InputException.usage("--fov must be a number between 0 and 180 degrees, got " + fov);
        }
        if (near != null && (!(near > 0) || Double.isInfinite(near))) {
            throw InputException.usage("--near must be a positive number, got " + near);
        }
        if (far != null && (!(far > 0) || Double.isInfinite(far))) {
            throw InputException.usage("--far must be a positive number, got " + far);
        }
        if (!(n < f)) {
            throw InputException.usage("--near (" + n + ") must be less than --far (" + f + ")");
        }
        if (!(f <= Camera.maxFar(n))) {
            throw InputException.usage("--far " + f + " is too large for --near " + n + ": the projection needs "
                    + "2 x near x far to be a finite double, so --far may be at most " + Camera.maxFar(n));
        }
        Vec3 e = eye != null ? eye : own.eye();
        Vec3 t = target != null ? target : own.target();
        if (e.equals(t)) {
            throw InputException.usage("--eye and --target are the same point (" + e + "): the camera has no direction");
        }
        try {
            return new Camera(e, t, up, fov, n, f);
        } catch (IllegalArgumentException ex) {
            throw InputException.usage(ex.getMessage());
        }
    }
}
