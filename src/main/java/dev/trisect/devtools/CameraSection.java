package dev.trisect.devtools;


import dev.trisect.math.Vec3;
import dev.trisect.scene.Camera;
import dev.trisect.view.internal.FrameSlot;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewState;
import java.awt.Toolkit;
import java.awt.datatransfer.StringSelection;
import java.util.Locale;
import javax.swing.JButton;
import javax.swing.JComponent;

/** Developer tools: where the camera of the frame on screen is, and a way to copy it for the command line. */
final class CameraSection implements ToolSection {
    private final ToolsForm form = new ToolsForm("Camera");
    private Camera shown;

    CameraSection(ViewController owner) {
        form.readouts(new String[][] {
            {"Eye", "Camera position of the frame on screen, world units (x,y,z; y is up)"},
            {"Target", "A point the camera looks at, one unit ahead, world units"}});
        JButton copy = new JButton("Copy as --eye/--target");
        copy.setToolTipText("Copy the camera as command-line options (with --fov, --near, --far) to render this "
                + "view headless");
        copy.addActionListener(e -> {
            if (shown == null) {
                owner.message("No frame yet.");
                return;
            }
            String options = CliArgs.cameraOptions(shown);
            Toolkit.getDefaultToolkit().getSystemClipboard().setContents(new StringSelection(options), null);
            owner.message("Copied " + options);
        });
        form.row(copy);
    }

    @Override
    public JComponent component() {
        return form.panel();
    }

    @Override
    public void refresh(ViewState.Progress progress, FrameSlot front, ViewState.Measurement m) {
        if (front == null || front.camera == null) {
            return;
        }
        shown = front.camera;
        form.set("Eye", rounded(shown.eye()));
        form.set("Target", rounded(shown.target()));
    }

    /** A point to the millimetre (for a scene in metres), as the copied options give it in full. */
    static String rounded(Vec3 p) {
        return String.format(Locale.ROOT, "%.3f, %.3f, %.3f", p.x(), p.y(), p.z()).replace("-0.000", "0.000");
    }

    @Override
    public String readout(String name) {
        return form.get(name);
    }
}
