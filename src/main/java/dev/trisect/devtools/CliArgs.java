package dev.trisect.devtools;

import dev.trisect.content.SceneAsset;
import dev.trisect.render.Colour;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.Shading;
import dev.trisect.render.TessellationSettings;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Light;
import dev.trisect.scene.Scene;
import dev.trisect.view.internal.ViewState;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** The command line that reproduces a frame of the demo headless, for copying and for checks. */
public final class CliArgs {
    private CliArgs() {
    }

    /**
     * {@code compare} arguments for the measured frame: same scene, size, camera and path settings, and
     * the light and fog it was drawn with (see {@link #unreproducible}).
     */
    public static List<String> compare(SceneAsset scene, ViewState.Measurement m) {
        List<String> a = frame("compare", scene, m.camera(), m.settings().render(), m.width(), m.height());
        a.addAll(lightAndFog(m));
        return a;
    }

    /**
     * Why no command line draws the measured frame's light, or null when one does: the command line
     * lights every material alike, by at most one directional and one point light besides the ambient
     * colour, as the OpenGL reference takes them.
     */
    public static String unreproducible(ViewState.Measurement m) {
        if (m.shading() == null) {
            return "its materials are lit differently, and the command line lights every material alike";
        }
        if (m.shading() == Shading.NONE) {
            return null;
        }
        if (shining(m, Light.Kind.DIRECTIONAL).size() > 1 || shining(m, Light.Kind.POINT).size() > 1) {
            return "it has more than one directional or point light, and the command line takes one of each";
        }
        return null;
    }

    /**
     * The light and fog options of the measured frame: with lit materials the ambient colour the
     * ambient lights sum to, the directional and the point light, each as placed for that frame, and the
     * shading; the fog with its colour. Numbers as Java prints doubles, which read back bit for bit.
     */
    static List<String> lightAndFog(ViewState.Measurement m) {
        List<String> a = new ArrayList<>();
        if (m.shading() != null && m.shading() != Shading.NONE) {
            double[] ambient = new double[3];
            for (Scene.PlacedLight l : shining(m, Light.Kind.AMBIENT)) {
                ambient[0] += l.colour().r();
                ambient[1] += l.colour().g();
                ambient[2] += l.colour().b();
            }
            a.addAll(List.of("--ambient", triple(ambient[0], ambient[1], ambient[2])));
            for (Scene.PlacedLight l : shining(m, Light.Kind.DIRECTIONAL)) {
                a.addAll(List.of("--light", l.vector().toString(), "--light-colour", colour(l.colour())));
            }
            for (Scene.PlacedLight l : shining(m, Light.Kind.POINT)) {
                a.addAll(List.of("--point", l.vector().toString(), "--point-colour", colour(l.colour()),
                        "--attenuation", triple(l.kc(), l.kl(), l.kq())));
            }
            a.addAll(List.of("--shade", m.shading().name().toLowerCase(Locale.ROOT)));
        }
        m.fog().ifPresent(f -> a.addAll(List.of("--fog", switch (f.mode()) {
            case LINEAR -> "linear," + f.start() + "," + f.end();
            case EXP -> "exp," + f.density();
            case EXP2 -> "exp2," + f.density();
        }, "--fog-colour", colour(f.colour()))));
        return a;
    }

    /**
     * The measured frame's lights of {@code kind} that lit it: a directional light with no direction,
     * or a light placed beyond the double range, shines on no frame.
     */
    private static List<Scene.PlacedLight> shining(ViewState.Measurement m, Light.Kind kind) {
        return m.lights().stream().filter(l -> l.kind() == kind && switch (kind) {
            case AMBIENT -> true;
            case DIRECTIONAL -> l.vector().isFinite() && l.vector().length() > 0;
            case POINT -> l.vector().isFinite();
        }).toList();
    }

    private static String colour(Colour c) {
        return triple(c.r(), c.g(), c.b());
    }

    private static String triple(double x, double y, double z) {
        return x + "," + y + "," + z;
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
