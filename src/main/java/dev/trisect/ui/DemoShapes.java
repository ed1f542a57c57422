package dev.trisect.ui;

import dev.trisect.content.AssetScenes;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Quaternion;
import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.LineShapes;
import dev.trisect.mesh.Mesh;
import dev.trisect.mesh.Primitives;
import dev.trisect.scene.Camera;
import dev.trisect.scene.DrawStyle;
import dev.trisect.scene.Label;
import dev.trisect.scene.Material;
import dev.trisect.scene.Node;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.ScreenText;
import dev.trisect.view.FrameInfo;
import dev.trisect.view.TrisectView;
import dev.trisect.view.UpdateListener;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;

/**
 * The demo's other shapes, made with the scene API as any program would: labels on the scene's things,
 * an axes gizmo at the world origin and a glass pane (the X key, together, since each shows the engine
 * drawing something other than textured triangles); the scene's objects filled, filled with their
 * wireframe, or as wire alone (Z); and a heads-up line with the frame rate in the frame's bottom-left
 * corner, drawn by the engine as screen text (H). All three start off, so that the demo's frame is the
 * command line's ({@code render --scene demo}) until asked for. Sized by the scene's first camera: the
 * axes are a tenth of the distance from that camera to its target long, the pane a fifth of it wide. The
 * things' labels are drawn on top (a label behind a crate still reads); the axes' are depth-tested.
 * Every scene shown gets the same state. Event thread, apart from {@link #update}, which the view calls
 * on its render thread.
 */
final class DemoShapes implements UpdateListener {
    /** The draw styles Z steps through. */
    static final DrawStyle[] STYLES = {DrawStyle.FILLED, DrawStyle.FILLED_AND_WIRE, DrawStyle.WIRE};
    /** The glass pane's colour, 0xRRGGBB, and opacity. */
    static final int GLASS = 0x3080FF;
    static final double GLASS_OPACITY = 0.35;
    /** At most this many labels on a model's materials (the largest first). */
    static final int MAX_LABELS = 12;

    private final TrisectView view;
    private final Supplier<FrameInfo> latest;
    /** Written on the event thread, read by {@link #update} on the render thread. */
    private volatile Scene scene;
    private Camera first;
    private List<Node> extras = List.of();
    private boolean shown;
    private DrawStyle style = DrawStyle.FILLED;
    private volatile boolean hud;

    /**
     * @param latest the newest frame the view drew, or null before the first (for the heads-up line)
     */
    DemoShapes(TrisectView view, Supplier<FrameInfo> latest) {
        this.view = view;
        this.latest = latest;
        view.addUpdateListener(this);
    }

    /** Gives {@code shown} (the view's new scene, first seen from {@code camera}) the state the last one had. */
    void sceneShown(Scene shownScene, Camera camera) {
        scene = shownScene;
        first = camera;
        extras = List.of();
        apply();
    }

    /** Shows or hides the labels, the axes gizmo and the glass pane. */
    void setExtras(boolean on) {
        shown = on;
        apply();
    }

    /** Whether the labels, axes and pane show. */
    boolean extras() {
        return shown;
    }

    /** Steps the scene's objects to the next draw style (filled, filled and wire, wire) and returns it. */
    DrawStyle cycleStyle() {
        style = DemoCommands.next(STYLES, style);
        apply();
        return style;
    }

    /** The draw style of the scene's objects. */
    DrawStyle style() {
        return style;
    }

    /** Shows or hides the heads-up line. */
    void setHud(boolean on) {
        Scene s = scene;
        if (s == null) {
            hud = on;
            return;
        }
        // Under the scene's lock, as the render thread's write of the line, so that neither overtakes the other.
        s.update(() -> {
            hud = on;
            s.setScreenText(hudText());
        });
        view.requestFrame();
    }

    /** Whether the heads-up line shows. */
    boolean hud() {
        return hud;
    }

    private void apply() {
        if (scene == null) {
            return;
        }
        Scene s = scene;
        List<Node> old = extras;
        List<Node> made = shown ? (old.isEmpty() ? extrasFor(s, first) : old) : List.of();
        DrawStyle st = style;
        s.update(() -> {
            for (SceneObject o : s.objects()) {
                if (o.mesh().triangleCount() > 0 && !made.contains(o)) {
                    o.setDrawStyle(st);
                }
            }
            for (Node n : old) {
                if (!made.contains(n)) {
                    s.remove(n);
                }
            }
            for (Node n : made) {
                if (!old.contains(n)) {
                    s.add(n);
                }
            }
            s.setScreenText(hudText());
        });
        extras = made;
        view.requestFrame();
    }

    /** The labels, axes and pane for {@code s}, seen first from {@code camera}. */
    static List<Node> extrasFor(Scene s, Camera camera) {
        double d = Math.max(1e-3, camera.eye().sub(camera.target()).length());
        List<Node> nodes = new ArrayList<>();
        List<Label> labels = new ArrayList<>();
        for (Map.Entry<String, Vec3> e : landmarks(s).entrySet()) {
            labels.add(Label.of(e.getKey(), e.getValue()).withBackground(0xA0000000).onTop());
        }
        double len = 0.1 * d;
        labels.add(Label.of("x", new Vec3(1.08 * len, 0, 0)).withColour(0xFF6060));
        labels.add(Label.of("y", new Vec3(0, 1.08 * len, 0)).withColour(0x60FF60));
        labels.add(Label.of("z", new Vec3(0, 0, 1.08 * len)).withColour(0x6090FF));
        SceneObject axes = SceneObject.lines(LineShapes.axes(len), 2);
        axes.setName("axes");
        nodes.add(axes);
        // The pane stands a third of the way from the camera to its target, a little right of the line
        // between them, upright and facing the camera: what is behind it shows through, tinted.
        Vec3 ahead = camera.target().sub(camera.eye()).normalize();
        Vec3 right = ahead.cross(Vec3.UP).normalize();
        Vec3 at = camera.eye().add(ahead.scale(0.3 * d)).add(right.scale(0.08 * d)).add(Vec3.UP.scale(-0.02 * d));
        double w = 0.2 * d;
        SceneObject pane = new SceneObject(Primitives.box(w, 0.6 * w, 0.01 * w),
                Material.colour(GLASS).withOpacity(GLASS_OPACITY), Transform.translation(at.x(), at.y(), at.z())
                .withRotation(Quaternion.ofY(Math.toDegrees(Math.atan2(-ahead.x(), -ahead.z())))));
        pane.setName("glass pane");
        // Its label stands on its bottom edge, over the glass (depth-tested at its own point).
        pane.setLabels(List.of(Label.of("glass pane, " + Math.round(100 * GLASS_OPACITY) + " %",
                new Vec3(0, -0.28 * w, 0)).withBackground(0xA0000000)));
        nodes.add(pane);
        SceneObject names = SceneObject.labels(labels);
        names.setName("labels");
        nodes.add(names);
        return List.copyOf(nodes);
    }

    /**
     * Where labels go on {@code s}: a built-in scene's things ({@link DemoScenes#landmarks}), else the
     * top middle of each material's triangles (a model's parts, the largest {@link #MAX_LABELS}),
     * named after the material.
     */
    static Map<String, Vec3> landmarks(Scene s) {
        SceneAsset asset = AssetScenes.assetOf(s).orElse(null);
        Map<String, Vec3> at = asset == null || asset.source() != null ? new LinkedHashMap<>()
                : DemoScenes.landmarks(asset.name());
        if (!at.isEmpty()) {
            return at;
        }
        for (SceneObject o : s.objects()) {
            Mesh m = o.mesh();
            int n = m.materialCount();
            double[] box = new double[6 * n];
            int[] count = new int[n];
            float[] p = m.positions();
            int[] corners = m.cornerPositions();
            int[] mats = m.triangleMaterials();
            for (int t = 0; t < m.triangleCount(); t++) {
                int k = mats[t];
                for (int c = 0; c < 3; c++) {
                    int v = 3 * corners[3 * t + c];
                    for (int a = 0; a < 3; a++) {
                        double x = p[v + a];
                        box[6 * k + a] = count[k] == 0 && c == 0 ? x : Math.min(box[6 * k + a], x);
                        box[6 * k + 3 + a] = count[k] == 0 && c == 0 ? x : Math.max(box[6 * k + 3 + a], x);
                    }
                }
                count[k]++;
            }
            List<Integer> order = new ArrayList<>();
            for (int k = 0; k < n; k++) {
                if (count[k] > 0) {
                    order.add(k);
                }
            }
            order.sort((a, b) -> Integer.compare(count[b], count[a]));
            for (int k : order.subList(0, Math.min(MAX_LABELS, order.size()))) {
                double[] top = new double[4];
                o.worldMatrix().transformPoint((box[6 * k] + box[6 * k + 3]) / 2, box[6 * k + 4],
                        (box[6 * k + 2] + box[6 * k + 5]) / 2, top, 0);
                Vec3 label = new Vec3(top[0] / top[3], top[1] / top[3], top[2] / top[3]);
                // A part with a NaN or infinite vertex (the OBJ reader keeps them) has no place to label.
                if (label.isFinite()) {
                    at.putIfAbsent(m.materialNames().get(k), label);
                }
            }
        }
        return at;
    }

    /** The heads-up line, or none when it is off. */
    private List<ScreenText> hudText() {
        if (!hud) {
            return List.of();
        }
        FrameInfo f = latest.get();
        // The rate over the last second, a dash until frames have come for a whole second (a still view
        // draws one frame and idles: it has no rate), then the newest frame's time.
        String text = f == null ? "first frame" : (f.framesPerSecond() > 0 ? PaceText.fps(f.framesPerSecond())
                : "\u2013 fps") + String.format(Locale.ROOT, " \u00b7 %.1f ms a frame", f.frameMillis());
        return List.of(ScreenText.of(ScreenText.Corner.BOTTOM_LEFT, text).withBackground(0xA0000000));
    }

    /** Writes the newest frame's rate into the heads-up line before each frame; never asks for frames. */
    @Override
    public boolean update(double seconds, long frame) {
        Scene s = view.getScene();
        if (hud && s == scene) {
            s.update(() -> {
                if (hud) {
                    s.setScreenText(hudText());
                }
            });
        }
        return false;
    }
}
