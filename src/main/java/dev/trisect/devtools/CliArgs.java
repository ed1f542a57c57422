package dev.trisect.devtools;

import dev.trisect.content.SceneAsset;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.TessellationSettings;
import dev.trisect.scene.Camera;
import dev.trisect.view.internal.ViewState;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** The command line that reproduces a frame of the demo headless, for copying and for checks. */
public final class CliArgs {
    private CliArgs() {
    }

    /** {@code compare} arguments for the measured frame: same scene, size, camera and path settings. */
    public static List<String> compare(SceneAsset scene, ViewState.Measurement m) {
        return frame("compare", scene, m.camera(), m.settings().render(), m.width(), m.height());
    }

    /**
     * {@code render} arguments (without {@code --out}) for a frame of {@code scene} drawn with camera
     * {@code c} and settings {@code r} at {@code width x height}: the command-line twin of a view's frame.
     */
    public static List<String> render(SceneAsset scene, Camera c, RenderSettings r, int width, int height) {
        return frame("render", scene, c, r, width, height);
    }

    private static List<String> frame(String command, SceneAsset scene, Camera c, RenderSettings r, int width,
                                      int height) {
        List<String> a = new ArrayList<>();
        a.add(command);
        if (scene.source() != null) {
            a.add("--obj");
            a.add(scene.source().toString());
        } else {
            a.add("--scene");
            a.add(scene.name());
        }
        TessellationSettings t = r.tessellation();
        a.addAll(List.of("--size", width + "x" + height,
                "--eye", c.eye().toString(), "--target", c.target().toString(), "--up", c.up().toString(),
                "--fov", Double.toString(c.fovY()), "--near", Double.toString(c.near()), "--far", Double.toString(c.far()),
                "--cull", r.cull().name().toLowerCase(Locale.ROOT),
                "--background", String.format(Locale.ROOT, "%06X", r.background()),
                "--mode", r.mode().id(), "--split", t.policy().id(),
                "--max-edge", Double.toString(t.maxEdge()), "--max-error",
                Double.toString(r.mode().knots() ? r.knotError() : t.maxError()),
                "--split-point", t.splitPoint().id(), "--max-depth", Integer.toString(t.maxDepth()),
                "--max-pieces", Integer.toString(t.maxPieces()), "--filter", r.filter().id()));
        if (t.maxFramePieces() != TessellationSettings.AUTO_FRAME_PIECES) {
            a.add("--max-frame-pieces");
            a.add(Integer.toString(t.maxFramePieces()));
        }
        if (r.borders()) {
            a.addAll(List.of("--borders", "--border-colour", r.borderStyle().colouring().id()));
            if (r.borderStyle().fade()) {
                a.add("--border-fade");
            }
        }
        return a;
    }

    /** The camera as command-line options: {@code --eye x,y,z --target x,y,z --up ... --fov ... --near ... --far ...}. */
    public static String cameraOptions(Camera c) {
        return String.join(" ", "--eye", c.eye().toString(), "--target", c.target().toString(), "--up",
                c.up().toString(), "--fov", Double.toString(c.fovY()), "--near", Double.toString(c.near()), "--far",
                Double.toString(c.far()));
    }

    /** How the copied command starts: the jar {@code mvn package} builds, run from the repository root. */
    static final String LAUNCHER = "java -jar target/trisect.jar";

    /** The whole {@code compare} command line for a shell, each argument quoted where it needs it. */
    public static String compareCommand(SceneAsset scene, ViewState.Measurement m) {
        StringBuilder b = new StringBuilder(LAUNCHER);
        for (String arg : compare(scene, m)) {
            b.append(' ').append(shellQuote(arg));
        }
        return b.toString();
    }

    /** {@code arg} as one POSIX shell word: bare when it is safe, else in single quotes. */
    static String shellQuote(String arg) {
        if (!arg.isEmpty() && arg.matches("[A-Za-z0-9_.,:/=+@%-]+")) {
            return arg;
        }
        return "'" + arg.replace("'", "'\\''") + "'";
    }
}
