package dev.trisect.ui;

import dev.trisect.base.internal.ErrorLine;
import dev.trisect.content.AssetScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Scene;
import dev.trisect.view.FrameInfo;
import dev.trisect.view.TrisectView;
import dev.trisect.view.ViewAction;
import dev.trisect.view.ViewFrame;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Frame;
import java.awt.GraphicsEnvironment;
import java.awt.Rectangle;
import java.awt.Window;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.lang.ref.SoftReference;
import java.nio.file.Path;
import java.util.List;
import javax.swing.Action;
import javax.swing.BorderFactory;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.Timer;
import javax.swing.WindowConstants;

/**
 * The demo's main window: a {@link TrisectView} with menus (built from the view's own commands), a
 * status bar, and the demo's own commands (open a model, save a screenshot, exit). It uses the view
 * as any program may: only its public API. Built and used on the event thread only.
 */
final class DemoWindow {
    private final JFrame frame;
    private final TrisectView view;
    private final JLabel status = new JLabel(" ");
    private final StatusLine statusLine = new StatusLine(status);
    private final JLabel pace = new JLabel(" ") {
        private static final long serialVersionUID = 1L;

        /** Never wider than the bar: a wider one was placed from left of the window's edge, cut at its start. */
        @Override
        public Dimension getPreferredSize() {
            Dimension d = super.getPreferredSize();
            java.awt.Container bar = getParent();
            if (bar != null && bar.getWidth() > 0) {
                java.awt.Insets in = bar.getInsets();
                d.width = Math.min(d.width, Math.max(0, bar.getWidth() - in.left - in.right));
            }
            return d;
        }
    };
    private final Timer refresh;
    /** The newest frame the view drew (written on its render thread). */
    private volatile FrameInfo latest;
    /** {@link System#nanoTime} when {@link #latest} came. */
    private volatile long latestAt;
    /** The cap before the uncapped rate was asked for, or NaN while it is not. Event thread. */
    private double cappedAt = Double.NaN;
    /** Keeps frames coming while the uncapped rate is measured. */
    private final dev.trisect.view.UpdateListener flatOut = (step, frame) -> true;

    /** The demo's own commands (menu items and keys); see {@link DemoCommands#table}. */
    final List<DemoCommands.Entry> commands;
    /** The F1 panel, made when first shown. */
    private javax.swing.JDialog help;
    final FileMenu fileMenu;
    /** The demo's light and fog (keys L and G). */
    final DemoLighting lighting;
    /** The demo's labels, axes and glass pane, wireframe and heads-up line (keys X, Z and H). */
    final DemoShapes shapes;

    DemoWindow(SceneAsset scene, int threads) {
        this(scene, threads, new RecentFiles());
    }

    /** @param recent where the files opened and Open OBJ's folder are remembered */
    DemoWindow(SceneAsset scene, int threads, RecentFiles recent) {
        frame = new JFrame(title(scene));
        frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        view = new TrisectView(AssetScenes.scene(scene), threads);
        view.setCamera(scene.camera());
        lighting = new DemoLighting(view);
        lighting.sceneShown(view.getScene(), scene.camera());
        shapes = new DemoShapes(view, () -> latest);
        shapes.sceneShown(view.getScene(), scene.camera());
        view.setPreferredSize(new Dimension(1280, 720));
        view.addFrameListener(f -> {
            latestAt = System.nanoTime();
            latest = f;
        });
        view.addMessageListener(this::status);

        fileMenu = new FileMenu(this, recent);
        commands = DemoCommands.table(this);
        frame.setJMenuBar(DemoMenus.bar(view, fileMenu, commands));
        // P switches the policy: say so in the status bar, where it shows without the developer tools.
        Action policy = view.action(ViewAction.SPLIT_POLICY);
        policy.addPropertyChangeListener(e -> {
            if (Action.NAME.equals(e.getPropertyName())) {
                status(PaceText.policyChanged(view.getRenderSettings()));
            }
        });
        // A gap between message and pace, so that a long message is cut short rather than run into it.
        JPanel bottom = new JPanel(new BorderLayout(16, 0));
        bottom.setBorder(BorderFactory.createEmptyBorder(3, 8, 3, 8));
        bottom.add(status, BorderLayout.CENTER);
        bottom.add(pace, BorderLayout.EAST);
        frame.getContentPane().add(view, BorderLayout.CENTER);
        frame.getContentPane().add(bottom, BorderLayout.SOUTH);
        // Ctrl+W and Escape close it too, as every example's window (ViewFrame.closeOnKeys); Ctrl+Q is Exit's.
        ViewFrame.closeOnKeys(frame);
        DemoCommands.bindKeys(frame.getRootPane(), commands);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                shutdown();
            }
        });
        frame.pack();
        fitTo(frame, GraphicsEnvironment.getLocalGraphicsEnvironment().getMaximumWindowBounds());
        refresh = new Timer(250, e -> refreshReadouts());
    }

    /**
     * Puts the window in the top left of {@code usable} (the screen less its panels), no larger than
     * it: the 1280x720 view and its bars come to 1280x767, more than a 1280x720 screen, a 1366x768 one
     * less its panel, or a 2560x1440 one scaled 2x, where the status bar fell off the bottom. The view
     * then gets the room left and renders at that size.
     */
    static void fitTo(Window window, Rectangle usable) {
        window.setSize(Math.min(window.getWidth(), usable.width), Math.min(window.getHeight(), usable.height));
        window.setLocation(usable.x, usable.y);
    }

    private static String title(SceneAsset scene) {
        return "Trisect \u2014 " + scene.name();
    }

    /** Shows the window and starts rendering (the view starts when shown). */
    void start() {
        frame.setVisible(true);
        view.requestFocusInWindow();
        refresh.start();
        statusLine.rest(HINT);
    }

    /** The status bar's resting hint. */
    private static final String HINT = "Fly with W A S D or the arrows, drag to look, wheel for height, Shift for "
            + "speed. F12: developer tools.";

    /**
     * Sets what the status bar shows when nothing else does for the scene on screen: a note that stays
     * as long as the scene (a texture replaced by a placeholder), or the hint with null.
     */
    void sceneNote(String note) {
        statusLine.rest(note == null ? HINT : note);
    }

    JFrame frame() {
        return frame;
    }

    TrisectView view() {
        return view;
    }

    /** The newest frame drawn, or null before the first. */
    FrameInfo latest() {
        return latest;
    }

    String statusText() {
        return statusLine.text();
    }

    /** The right side of the status bar: how frames are drawn, their rate and size. */
    String paceText() {
        return pace.getText();
    }

    /** Shows a message in the status bar that clears itself after a few seconds. */
    void status(String message) {
        statusLine.pass(message, System.nanoTime());
    }

    /** Changes the render settings, as a program using the view would. */
    void render(java.util.function.UnaryOperator<RenderSettings> change) {
        view.setRenderSettings(change.apply(view.getRenderSettings()));
    }

    /** Shows the F1 panel beside the window, or hides it. */
    void toggleHelp() {
        if (help == null) {
            help = DemoHelp.panel(frame);
        }
        if (!help.isVisible()) {
            help.setLocation(frame.getX() + frame.getWidth() - help.getWidth() - 20, frame.getY() + 60);
        }
        help.setVisible(!help.isVisible());
    }

    /** The F1 panel, or null before it was first shown; for tests. */
    javax.swing.JDialog helpPanel() {
        return help;
    }

    private void refreshReadouts() {
        statusLine.tick(System.nanoTime());
        FrameInfo f = latest;
        boolean frozen = Boolean.TRUE.equals(view.action(ViewAction.FREEZE).getValue(Action.SELECTED_KEY));
        String full = PaceText.pace(view.getRenderSettings(), f, System.nanoTime() - latestAt,
                view.getFrameTimeTarget(), frozen);
        java.awt.Container bar = pace.getParent();
        java.awt.Insets in = bar.getInsets();
        java.awt.FontMetrics metrics = pace.getFontMetrics(pace.getFont());
        pace.setText(PaceText.fit(full, metrics::stringWidth, bar.getWidth() - in.left - in.right));
        pace.setToolTipText(full);
        // A warning lasts while its frames do (none stays after the frame on screen stopped earning
        // it), and never covers a passing message: StatusLine keeps the two apart.
        statusLine.warn(f == null ? null : f.warning());
    }

    /**
     * Draws frames flat out, with no cap, so that the status bar's rate is the uncapped one (a still
     * scene draws no frames at all, an animated one at most the cap); off, the cap comes back.
     */
    void measureUncapped(boolean on) {
        if (on && Double.isNaN(cappedAt)) {
            cappedAt = view.getMaxFrameRate();
            view.setMaxFrameRate(0);
            view.addUpdateListener(flatOut);
            status("Uncapped: frames drawn continuously as fast as they can be, no cap (M again to stop)");
        } else if (!on && !Double.isNaN(cappedAt)) {
            view.removeUpdateListener(flatOut);
            view.setMaxFrameRate(cappedAt);
            cappedAt = Double.NaN;
            status("Capped again: frames only when something changes, animated ones at most "
                    + Math.round(view.getMaxFrameRate()) + " a second");
        }
    }

    /** Loads an OBJ in the background (see {@link FileMenu#load}). */
    void loadObj(Path file) {
        fileMenu.load(file);
    }

    /**
     * Takes the scene on screen away (an empty one shows until the next), so that its memory can go
     * while another loads.
     *
     * @return the scene taken away, softly held: the collector may take it when memory runs short
     */
    SoftReference<Scene> releaseScene() {
        Scene shown = view.getScene();
        view.setScene(new Scene());
        return new SoftReference<>(shown);
    }

    /** Shows {@code s} again after a load failed, unless it is gone (null) or another scene shows. */
    void restoreScene(Scene s) {
        if (s != null && view.getScene().children().isEmpty()) {
            view.setScene(s);
        }
    }

    /** Shows a scene from its own camera, named in the title. */
    void show(SceneAsset s) {
        view.setScene(AssetScenes.scene(s));
        view.setCamera(s.camera());
        lighting.sceneShown(view.getScene(), s.camera());
        shapes.sceneShown(view.getScene(), s.camera());
        frame.setTitle(title(s));
        // A new scene: the last one's note (a placeholder texture) no longer applies.
        sceneNote(null);
    }

    /** What to do when the demo runs out of memory. */
    static final String MEMORY_HINT = "give Java more with -Xmx";

    /** Why {@code t} happened, in the words the command line would print after "trisect: ". */
    static String message(Throwable t) {
        return ErrorLine.reason(t, MEMORY_HINT);
    }

    private void shutdown() {
        refresh.stop();
        view.close();
        for (Frame f : Frame.getFrames()) {
            if (f.isDisplayable() && f != frame) {
                f.dispose();
            }
        }
    }
}
