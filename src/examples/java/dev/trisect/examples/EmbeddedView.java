package dev.trisect.examples;

import dev.trisect.math.Transform;
import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.texture.ProceduralTextures;
import dev.trisect.view.TrisectView;
import dev.trisect.view.ViewFrame;
import dev.trisect.view.ViewAction;
import java.awt.BorderLayout;
import java.awt.Component;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.Box;
import javax.swing.BoxLayout;
import javax.swing.ButtonGroup;
import javax.swing.JCheckBox;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JRadioButton;
import javax.swing.JSlider;
import javax.swing.JToggleButton;
import javax.swing.SwingUtilities;

/**
 * The view in a program's own window, beside Swing controls: the texturing path and the polygon
 * borders are the view's own actions (so the keys 1 2 3 and B move the controls too), the slider sets
 * the tessellated path's split threshold, and a label shows the frame rate from a frame listener.
 */
public final class EmbeddedView {
    public static void main(String[] args) {
        SwingUtilities.invokeLater(EmbeddedView::open);
    }

    /** Builds and shows the window; returns it (the tests drive it). Event thread. */
    public static JFrame open() {
        Scene scene = new Scene();
        scene.add(new SceneObject(Primitives.plane(40, 40, 20, 20), Material.of(ProceduralTextures.uvGrid(512))));
        for (int i = 0; i < 5; i++) {
            scene.add(new SceneObject(Primitives.box(1, 1, 1), Material.of(ProceduralTextures.crate(256)),
                    Transform.translation(2 * i - 4, 0.5, -i)));
        }
        TrisectView view = new TrisectView(scene);
        view.setCamera(Camera.looking(new Vec3(0, 1.6, 6), new Vec3(0, 0.5, 0)));

        JPanel controls = new JPanel();
        controls.setLayout(new BoxLayout(controls, BoxLayout.Y_AXIS));
        controls.setBorder(BorderFactory.createEmptyBorder(8, 8, 8, 8));
        controls.add(new JLabel("Path"));
        ButtonGroup paths = new ButtonGroup();
        for (ViewAction a : new ViewAction[] {ViewAction.PERSPECTIVE, ViewAction.AFFINE, ViewAction.TESSELLATED,
                ViewAction.SPANS}) {
            JRadioButton b = new JRadioButton(view.action(a));
            paths.add(b);
            controls.add(b);
        }
        controls.add(new JCheckBox(view.action(ViewAction.BORDERS)));
        JLabel threshold = new JLabel();
        JSlider maxEdge = new JSlider(2, 128, (int) view.getRenderSettings().tessellation().maxEdge());
        maxEdge.addChangeListener(e -> {
            threshold.setText("Max edge: " + maxEdge.getValue() + " px");
            RenderSettings r = view.getRenderSettings();
            view.setRenderSettings(r.withTessellation(r.tessellation().withMaxEdge(maxEdge.getValue())));
        });
        threshold.setText("Max edge: " + maxEdge.getValue() + " px");
        controls.add(threshold);
        controls.add(maxEdge);
        controls.add(new JToggleButton(view.action(ViewAction.DEV_TOOLS)));
        controls.add(Box.createVerticalGlue());
        JLabel fps = new JLabel(" ");
        controls.add(fps);
        for (Component c : controls.getComponents()) {
            ((JComponent) c).setAlignmentX(Component.LEFT_ALIGNMENT);
        }
        // Frame listeners run on the render thread: hand the text to the event thread, a few times a second.
        view.addFrameListener(f -> {
            if (f.number() % 10 == 0) {
                String text = String.format(Locale.ROOT, "%.0f fps, %d pieces", f.framesPerSecond(), f.stats().pieces());
                SwingUtilities.invokeLater(() -> fps.setText(text));
            }
        });

        JFrame frame = new JFrame("Trisect embedded");
        frame.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
        ViewFrame.closeOnKeys(frame);
        frame.add(view, BorderLayout.CENTER);
        frame.add(controls, BorderLayout.EAST);
        frame.pack();
        frame.setVisible(true);
        return frame;
    }
}
