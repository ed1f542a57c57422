package dev.trisect.examples;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Highlight;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.texture.ProceduralTextures;
import dev.trisect.view.CameraControls;
import dev.trisect.view.TrisectView;
import dev.trisect.view.ViewFrame;
import java.awt.BorderLayout;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.SwingUtilities;

/**
 * Picking by click and hover: a row of crates and balls, each tinted gold while the pointer is over
 * it; click one to paint it red (click again to restore it), and the bar below names the object, the
 * 3D point and the texel under the mouse. Drag to orbit.
 */
public final class ClickPicking {
    public static void main(String[] args) {
        Scene scene = new Scene();
        SceneObject floor = new SceneObject(Primitives.plane(12, 12, 6, 6), Material.of(ProceduralTextures.uvGrid(256)));
        floor.setName("floor");
        scene.add(floor);
        Material crate = Material.of(ProceduralTextures.crate(128));
        Material grid = Material.of(ProceduralTextures.uvGrid(128));
        Material red = Material.colour(0xCC2222);
        Map<SceneObject, Material> own = new HashMap<>();
        for (int i = 0; i < 4; i++) {
            boolean box = i % 2 == 0;
            SceneObject o = new SceneObject(box ? Primitives.box(1, 1, 1) : Primitives.sphere(0.5, 24, 12),
                    box ? crate : grid, Transform.translation(2 * i - 3, 0.5, 0));
            o.setName((box ? "crate " : "ball ") + (i + 1));
            own.put(o, box ? crate : grid);
            // Hover: tinted gold while the pointer is over it, drawn over the frame (no second render).
            o.setHoverHighlight(Highlight.tint(0xFFD24D));
            scene.add(o);
        }
        SwingUtilities.invokeLater(() -> {
            TrisectView view = new TrisectView(scene);
            view.setCamera(Camera.looking(new Vec3(0, 3, 5.5), new Vec3(0, 0.5, 0)));
            view.setCameraControls(CameraControls.ORBIT);
            JLabel status = new JLabel("Click an object.");
            view.addPickListener((pick, click) -> {
                SceneObject o = pick.object();
                if (own.containsKey(o)) {
                    // The scene may change from any thread while the view draws; the next frame shows it.
                    o.setMaterial(o.materials().get(0) == red ? own.get(o) : red);
                }
                status.setText(String.format(Locale.ROOT, "%s, triangle %d, at (%.2f, %.2f, %.2f), texel %d,%d",
                        o.name(), pick.triangle(), pick.point().x(), pick.point().y(), pick.point().z(), pick.texelX(),
                        pick.texelY()));
            });
            JFrame frame = new JFrame("Click picking");
            frame.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
            ViewFrame.closeOnKeys(frame);
            frame.add(view, BorderLayout.CENTER);
            frame.add(status, BorderLayout.SOUTH);
            frame.pack();
            frame.setVisible(true);
        });
    }
}
