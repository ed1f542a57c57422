package dev.trisect.ui;

import dev.trisect.content.DemoScenes;
import dev.trisect.view.ViewAction;
import dev.trisect.view.internal.ViewController;
import dev.trisect.view.internal.ViewState;
import java.awt.Point;
import java.awt.Rectangle;
import java.nio.file.Path;
import javax.swing.SwingUtilities;

/**
 * The screenshots of docs/demo.md that show the developer tools' newer features, taken from the real
 * demo window on an X server with ImageMagick's {@code import}: the Difference view with its legend
 * (demo-heatmap.png), the inspector with pinned pixels and the magnifier's note (demo-pins.png), the
 * tools window docked beside the demo (demo-docked.png), and the scene's labels, axes gizmo, glass pane,
 * wireframe and frame-rate HUD (X, Z, H: demo-shapes.png). Run by {@code scripts/demo-shots.sh}.
 */
public final class DemoShots {
    private DemoShots() {
    }

    public static void main(String[] args) throws Exception {
        Path docs = Path.of(args.length > 0 ? args[0] : "docs");
        DemoWindow w = DemoApp.openForTest(DemoScenes.demo(), 2);
        ViewController c = (ViewController) w.view().getClientProperty(ViewController.class);
        ViewState state = c.state();
        try {
            SwingUtilities.invokeAndWait(() -> w.frame().setBounds(0, 0, 1000, 640));
            settle();
            // Labels, the axes gizmo and the glass pane (X), the objects filled with their wire (Z), the HUD (H).
            SwingUtilities.invokeAndWait(() -> {
                w.shapes.setExtras(true);
                w.shapes.cycleStyle();
                w.shapes.setHud(true);
                // Frames flat out, so that the HUD has a rate to show (a still view draws one frame and idles).
                w.measureUncapped(true);
            });
            settle();
            shoot(viewBounds(w), docs.resolve("demo-shapes.png"));
            SwingUtilities.invokeAndWait(() -> {
                w.shapes.setExtras(false);
                w.shapes.cycleStyle();
                w.shapes.cycleStyle();
                w.shapes.setHud(false);
                w.measureUncapped(false);
            });
            settle();
            // The heat map of the tessellated path against the per-pixel one, its legend on its panel.
            SwingUtilities.invokeAndWait(() -> w.view().action(ViewAction.SHOW_DIFFERENCE).actionPerformed(null));
            settle();
            shoot(viewBounds(w), docs.resolve("demo-heatmap.png"));
            SwingUtilities.invokeAndWait(() -> {
                w.view().action(ViewAction.SHOW_IMAGE).actionPerformed(null);
                w.view().showDevTools(false);
                w.view().action(ViewAction.BORDERS).actionPerformed(null);
                w.view().action(ViewAction.PIXEL_INSPECTOR).actionPerformed(null);
            });
            settle();
            // The inspector on a pixel among the outlines, and three pinned pixels.
            state.inspect(430, 420);
            state.togglePin(250, 470);
            state.togglePin(600, 430);
            state.togglePin(820, 500);
            settle();
            shoot(viewBounds(w), docs.resolve("demo-pins.png"));
            SwingUtilities.invokeAndWait(() -> {
                w.view().action(ViewAction.PIXEL_INSPECTOR).actionPerformed(null);
                w.view().showDevTools(true);
            });
            settle();
            shoot(new Rectangle(0, 0, 1480, 700), docs.resolve("demo-docked.png"));
        } finally {
            SwingUtilities.invokeAndWait(() -> w.frame().dispose());
        }
        System.exit(0);
    }

    private static Rectangle viewBounds(DemoWindow w) throws Exception {
        Rectangle[] r = new Rectangle[1];
        SwingUtilities.invokeAndWait(() -> {
            Point at = w.view().getLocationOnScreen();
            r[0] = new Rectangle(at.x, at.y, w.view().getWidth(), w.view().getHeight());
        });
        return r[0];
    }

    /** Long enough for a few frames and the tools' readouts on a loaded machine. */
    private static void settle() throws InterruptedException {
        Thread.sleep(6000);
    }

    private static void shoot(Rectangle r, Path file) throws Exception {
        Process p = new ProcessBuilder("import", "-window", "root", "-crop",
                r.width + "x" + r.height + "+" + r.x + "+" + r.y, "+repage", file.toString()).inheritIO().start();
        if (p.waitFor() != 0) {
            throw new IllegalStateException("import failed for " + file);
        }
        System.out.println("wrote " + file);
    }
}
