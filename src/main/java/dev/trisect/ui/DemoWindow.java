package dev.trisect.ui;

import dev.trisect.base.InputException;
import dev.trisect.content.AssetScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Scene;
import dev.trisect.render.TessellationSettings;
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
import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.lang.ref.SoftReference;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.LocalDateTime;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutionException;
import javax.imageio.ImageIO;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.ActionMap;
import javax.swing.BorderFactory;
import javax.swing.ButtonGroup;
import javax.swing.InputMap;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JPanel;
import javax.swing.KeyStroke;
import javax.swing.SwingWorker;
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
    private final JLabel pace = new JLabel(" ");
    private final Timer refresh;
    /** The newest frame the view drew (written on its render thread). */
    private volatile FrameInfo latest;

    final Action screenshotCommand;
    final Action openCommand;
    final Action exitCommand;
    final Action helpCommand;
    /** The F1 panel, made when first shown. */
    private javax.swing.JDialog help;
    final FileMenu fileMenu;

    DemoWindow(SceneAsset scene, int threads) {
        this(scene, threads, new RecentFiles());
    }

    /** @param recent where the files opened and Open OBJ's folder are remembered */
    DemoWindow(SceneAsset scene, int threads, RecentFiles recent) {
        frame = new JFrame(title(scene));
        frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        view = new TrisectView(AssetScenes.scene(scene), threads);
        view.setCamera(scene.camera());
        view.setPreferredSize(new Dimension(1280, 720));
        view.addFrameListener(f -> latest = f);
        view.addMessageListener(this::status);

        screenshotCommand = command("Save screenshot", "Save the frame on screen as a PNG in "
                + Screenshots.folder(), KeyStroke.getKeyStroke(KeyEvent.VK_S, InputEvent.CTRL_DOWN_MASK),
                this::saveScreenshot);
        fileMenu = new FileMenu(this, recent);
        openCommand = fileMenu.open;
        helpCommand = command("Keys and mouse", "Show every key and mouse gesture of the demo in a panel",
                KeyStroke.getKeyStroke(KeyEvent.VK_F1, 0), this::toggleHelp);
        exitCommand = command("Exit", "Close Trisect", KeyStroke.getKeyStroke(KeyEvent.VK_Q, InputEvent.CTRL_DOWN_MASK),
                () -> frame.dispatchEvent(new WindowEvent(frame, WindowEvent.WINDOW_CLOSING)));

        frame.setJMenuBar(menus());
        // P switches the policy: say so in the status bar, where it shows without the developer tools.
        Action policy = view.action(ViewAction.SPLIT_POLICY);
        policy.addPropertyChangeListener(e -> {
            if (Action.NAME.equals(e.getPropertyName())) {
                status(policyChanged(view.getRenderSettings()));
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
        bindKeys(frame.getRootPane());
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

    /** A plain command of the demo's own: one action for its menu item and its key. */
    static Action command(String name, String description, KeyStroke key, Runnable behaviour) {
        Action a = new AbstractAction(name) {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(ActionEvent e) {
                behaviour.run();
            }
        };
        a.putValue(Action.SHORT_DESCRIPTION, description);
        a.putValue(Action.ACCELERATOR_KEY, key);
        return a;
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

    private JMenuBar menus() {
        JMenuBar bar = new JMenuBar();
        JMenu file = new JMenu("File");
        file.setMnemonic(KeyEvent.VK_F);
        fileMenu.addTo(file);
        file.addSeparator();
        file.add(MenuItems.item(screenshotCommand));
        file.addSeparator();
        file.add(MenuItems.item(exitCommand));
        JMenu viewMenu = new JMenu("View");
        viewMenu.setMnemonic(KeyEvent.VK_V);
        viewMenu.add(MenuItems.check(view.action(ViewAction.DEV_TOOLS)));
        viewMenu.add(MenuItems.check(view.action(ViewAction.BORDERS)));
        viewMenu.add(MenuItems.item(view.action(ViewAction.BORDER_COLOUR)));
        viewMenu.add(MenuItems.check(view.action(ViewAction.STAT_OVERLAY)));
        viewMenu.add(MenuItems.check(view.action(ViewAction.AUTO_ORBIT)));
        viewMenu.add(MenuItems.item(view.action(ViewAction.RESET_CAMERA)));
        viewMenu.add(MenuItems.item(view.action(ViewAction.TEXTURE_FILTER)));
        viewMenu.addSeparator();
        viewMenu.add(MenuItems.check(view.action(ViewAction.PIXEL_INSPECTOR)));
        viewMenu.add(MenuItems.item(view.action(ViewAction.COPY_INSPECTION)));
        viewMenu.add(MenuItems.check(view.action(ViewAction.FREEZE)));
        viewMenu.add(MenuItems.item(view.action(ViewAction.STEP)));
        viewMenu.addSeparator();
        radioGroup(viewMenu, ViewAction.SHOW_IMAGE, ViewAction.SHOW_DIFFERENCE, ViewAction.SHOW_SPLIT);
        JMenu render = new JMenu("Render");
        render.setMnemonic(KeyEvent.VK_R);
        radioGroup(render, ViewAction.PERSPECTIVE, ViewAction.AFFINE, ViewAction.TESSELLATED, ViewAction.SPANS);
        render.addSeparator();
        render.add(MenuItems.item(view.action(ViewAction.SPLIT_POLICY)));
        JMenu helpMenu = new JMenu("Help");
        helpMenu.setMnemonic(KeyEvent.VK_H);
        helpMenu.add(MenuItems.item(helpCommand));
        bar.add(file);
        bar.add(viewMenu);
        bar.add(render);
        bar.add(helpMenu);
        for (JMenu m : List.of(file, viewMenu, render, helpMenu)) {
            for (java.awt.Component item : m.getMenuComponents()) {
                if (item instanceof JMenuItem i && i.getToolTipText() != null) {
                    i.setToolTipText(wrapped(i.getToolTipText()));
                }
            }
        }
        return bar;
    }

    /** A tooltip in lines of at most 64 characters, so that none runs across the screen. */
    static String wrapped(String tip) {
        StringBuilder out = new StringBuilder("<html>");
        int line = 0;
        for (String word : tip.replace("&", "&amp;").replace("<", "&lt;").split(" ")) {
            boolean breakHere = line > 0 && line + 1 + word.length() > 64;
            out.append(breakHere ? "<br>" : line > 0 ? " " : "").append(word);
            line = (breakHere || line == 0 ? 0 : line + 1) + word.length();
        }
        return out.append("</html>").toString();
    }

    private void radioGroup(JMenu menu, ViewAction... actions) {
        ButtonGroup group = new ButtonGroup();
        for (ViewAction a : actions) {
            javax.swing.JRadioButtonMenuItem item = MenuItems.radio(view.action(a));
            group.add(item);
            menu.add(item);
        }
    }

    /** Shows the F1 panel beside the window, or hides it. */
    private void toggleHelp() {
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

    /** The demo's own keys on the window (the view binds its own while it has the keyboard). */
    private void bindKeys(JComponent root) {
        InputMap in = root.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW);
        ActionMap act = root.getActionMap();
        for (Action a : List.of(screenshotCommand, openCommand, exitCommand, helpCommand)) {
            in.put((KeyStroke) a.getValue(Action.ACCELERATOR_KEY), a);
            act.put(a, a);
        }
    }

    private void refreshReadouts() {
        statusLine.tick(System.nanoTime());
        FrameInfo f = latest;
        String path = howDrawn(view.getRenderSettings(), f == null ? null : f.settings(), view.getFrameTimeTarget());
        String size = f == null ? "" : f.width() + "x" + f.height();
        boolean frozen = Boolean.TRUE.equals(view.action(ViewAction.FREEZE).getValue(Action.SELECTED_KEY));
        pace.setText(frozen
                ? String.format(Locale.ROOT, "%s  FROZEN at frame %d  %s", path, f == null ? 0 : f.number(), size)
                : String.format(Locale.ROOT, "%s  %.0f fps  %s", path, f == null ? 0 : f.framesPerSecond(), size));
        // A warning lasts while its frames do (none stays after the frame on screen stopped earning
        // it), and never covers a passing message: StatusLine keeps the two apart.
        statusLine.warn(f == null ? null : f.warning());
    }

    /**
     * The status bar's name of how frames are drawn: the path, the split policy and its threshold where
     * the path uses them, and the texture filter ("tessellated, edge 32 px, trilinear").
     *
     * @param user     the settings in force
     * @param drawn    those the newest frame was drawn with (the budget may have chosen its threshold), or null
     * @param targetMs the frame-time target, 0 when off
     */
    static String howDrawn(RenderSettings user, RenderSettings drawn, double targetMs) {
        RenderSettings r = drawn != null && drawn.mode() == user.mode()
                && drawn.tessellation().policy() == user.tessellation().policy() ? drawn : user;
        return switch (user.mode()) {
            case TESSELLATED -> "tessellated, " + policy(r.tessellation())
                    + (targetMs > 0 ? " (auto)" : "") + ", " + user.filter().id();
            case SPANS -> "spans, max error " + number(user.knotError()) + " px, " + user.filter().id();
            default -> user.mode().id() + ", " + user.filter().id();
        };
    }

    /** A split policy and its threshold: "edge 32 px", "error 0.5 px". */
    static String policy(TessellationSettings t) {
        return t.policy().id() + " " + number(t.policy().threshold(t)) + " px";
    }

    /** A threshold as the tools show it: whole pixels without decimals, else up to three. */
    private static String number(double v) {
        return v == Math.rint(v) ? Long.toString(Math.round(v))
                : new java.math.BigDecimal(String.format(Locale.ROOT, "%.3f", v)).stripTrailingZeros().toPlainString();
    }

    /**
     * What P (or the Render menu's item) says in the status bar, so that the switch shows without the
     * developer tools: the policy now in force, and the key of the path that uses it when another shows.
     */
    static String policyChanged(RenderSettings r) {
        TessellationSettings t = r.tessellation();
        String what = (t.policy().measuresError() ? "Error (split while an edge's affine error bound is over "
                : "Edge (split while a piece's longest edge is over ") + number(t.policy().threshold(t)) + " px)";
        return "Split policy: " + what + (r.mode() == RenderMode.TESSELLATED ? ""
                : "; the tessellated path (3) uses it");
    }

    private void saveScreenshot() {
        BufferedImage image = view.frameImage();
        if (image == null) {
            status("No frame to save yet.");
            return;
        }
        Path target = Screenshots.newFile(Screenshots.folder(), LocalDateTime.now());
        status("Saving " + target + " \u2026");
        new SwingWorker<Path, Void>() {
            @Override
            protected Path doInBackground() throws IOException {
                // All or nothing: a partial file never takes the final name.
                Path part = target.resolveSibling(target.getFileName() + ".part");
                try {
                    if (!ImageIO.write(image, "png", part.toFile())) {
                        throw new IOException("no PNG writer");
                    }
                    Files.move(part, target, StandardCopyOption.ATOMIC_MOVE);
                } finally {
                    Files.deleteIfExists(part);
                }
                return target;
            }

            @Override
            protected void done() {
                try {
                    status("Saved screenshot to " + get());
                } catch (ExecutionException e) {
                    status("Could not save the screenshot: " + e.getCause().getMessage());
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }.execute();
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
        frame.setTitle(title(s));
        // A new scene: the last one's note (a placeholder texture) no longer applies.
        sceneNote(null);
    }

    /** The one-line message the command line would print for this failure. */
    static String message(Throwable t) {
        if (t instanceof InputException ie) {
            return ie.getMessage();
        }
        if (t instanceof OutOfMemoryError) {
            return "out of memory (give Java more with -Xmx)";
        }
        return "internal error: " + t;
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
