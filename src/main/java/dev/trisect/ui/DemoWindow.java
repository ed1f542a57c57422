package dev.trisect.ui;

import dev.trisect.base.InputException;
import dev.trisect.io.ImageFiles;
import dev.trisect.pipeline.RenderMode;
import dev.trisect.texture.TextureFilter;
import dev.trisect.pipeline.RenderSettings;
import dev.trisect.raster.BorderStyle;
import dev.trisect.tessellate.SplitPolicy;
import dev.trisect.content.SceneAsset;
import dev.trisect.content.SceneLoader;
import java.awt.BorderLayout;
import java.awt.Frame;
import java.awt.event.ActionEvent;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutionException;
import java.util.function.UnaryOperator;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.ActionMap;
import javax.swing.BorderFactory;
import javax.swing.ButtonGroup;
import javax.swing.InputMap;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.KeyStroke;
import javax.swing.SwingWorker;
import javax.swing.Timer;
import javax.swing.WindowConstants;
import javax.swing.filechooser.FileNameExtensionFilter;

/**
 * The demo's main window: the view, the menus, the status bar, the key bindings, and the commands
 * behind them. Built and used on the event thread only; the render thread is reached through
 * {@link DemoState} alone.
 */
final class DemoWindow {
    private final DemoState state;
    private final TripleBuffer buffers = new TripleBuffer();
    private final JFrame frame;
    private final ViewPanel view;
    private final JLabel status = new JLabel(" ");
    private final StatusLine statusLine = new StatusLine(status);
    private final JLabel pace = new JLabel(" ");
    private final RenderLoop loop;
    private final Thread renderThread;
    private final Timer refresh;
    private DevToolsDialog devTools;

    final Command devToolsCommand;
    final Command bordersCommand;
    final Command orbitCommand;
    final Command resetCommand;
    /** Steps the texture filter: nearest, bilinear, trilinear, nearest... Named after the current one. */
    final Command filterCommand;
    final Command freezeCommand;
    final Command borderColourCommand;
    final Command inspectorCommand;
    final Command splitPolicyCommand;
    final Command stepCommand;
    final Command screenshotCommand;
    final Command openCommand;
    final Command exitCommand;
    final List<Command> modeCommands = new ArrayList<>();
    /** Image, Difference, Split: what the view shows, by {@link ViewKind} ordinal. */
    final List<Command> viewCommands = new ArrayList<>();

    DemoWindow(DemoState state, int threads) {
        this.state = state;
        frame = new JFrame(title(state.scene()));
        frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        view = new ViewPanel(state, buffers, f -> update(s -> s.withSplitFraction(f)));
        loop = new RenderLoop(state, buffers, view::repaint, threads);
        view.attach(loop);

        devToolsCommand = Command.toggle("Developer tools", "Show or hide the developer tools window",
                KeyStroke.getKeyStroke(KeyEvent.VK_F12, 0), c -> showDevTools(c.selected()));
        bordersCommand = Command.toggle("Polygon borders", "Outline every piece filled in yellow",
                KeyStroke.getKeyStroke(KeyEvent.VK_B, 0), c -> update(s -> s.withRender(s.render().withBorders(c.selected()))));
        orbitCommand = Command.toggle("Auto-orbit", "Fly the camera slowly round the scene; any movement stops it",
                KeyStroke.getKeyStroke(KeyEvent.VK_O, 0), c -> state.input.orbit(c.selected()));
        resetCommand = Command.action("Reset camera", "Put the camera back where the scene starts",
                KeyStroke.getKeyStroke(KeyEvent.VK_R, 0), () -> {
                    orbitCommand.show(false);
                    state.input.requestReset();
                });
        borderColourCommand = Command.action("Border colour", "Next outline colouring: yellow; by split depth; "
                + "by error bound (fallback pieces magenta in each)", KeyStroke.getKeyStroke(KeyEvent.VK_C, 0),
                () -> {
                    BorderStyle.Colouring[] all = BorderStyle.Colouring.values();
                    BorderStyle now = state.settings().render().borderStyle();
                    selectBorderStyle(new BorderStyle(all[(now.colouring().ordinal() + 1) % all.length], now.fade()));
                });
        inspectorCommand = Command.toggle("Pixel inspector", "Show what the pixel under the mouse is made of "
                + "(click to pin it): triangle, piece, split level, depth, texel coordinates in both paths, exact "
                + "displacement, mip level and texel; with a crosshair and a magnifier",
                KeyStroke.getKeyStroke(KeyEvent.VK_I, 0), c -> view.inspector(c.selected()));
        splitPolicyCommand = Command.action("Split policy", "Switch the tessellated path's split policy between "
                + "Edge (longest screen edge over Max edge) and Error (affine error bound over Max error)",
                KeyStroke.getKeyStroke(KeyEvent.VK_P, 0), () -> {
                    SplitPolicy next = state.settings().render().tessellation().policy() == SplitPolicy.EDGE
                            ? SplitPolicy.ERROR : SplitPolicy.EDGE;
                    update(s -> s.withRender(s.render().withTessellation(s.render().tessellation().withPolicy(next))));
                });
        freezeCommand = Command.toggle("Freeze frame", "Stop on this frame: the camera and the comparison hold "
                + "still so it can be inspected; settings still apply to it", KeyStroke.getKeyStroke(KeyEvent.VK_SPACE, 0),
                c -> state.freeze.freeze(c.selected()));
        stepCommand = Command.action("Step one frame", "Draw the next frame, 1/60 s on, and stay frozen",
                KeyStroke.getKeyStroke(KeyEvent.VK_PERIOD, 0), () -> {
                    freezeCommand.show(true);
                    state.freeze.step();
                });
        filterCommand = Command.action("Texture filter", "Next texture filter: nearest, bilinear, trilinear "
                + "(OpenGL's GL_NEAREST, GL_LINEAR, GL_LINEAR_MIPMAP_LINEAR)", KeyStroke.getKeyStroke(KeyEvent.VK_F, 0),
                () -> {
                    TextureFilter[] all = TextureFilter.values();
                    selectFilter(all[(state.settings().render().filter().ordinal() + 1) % all.length]);
                });
        screenshotCommand = Command.action("Save screenshot", "Save the frame on screen as a PNG in "
                + Screenshots.folder(),
                KeyStroke.getKeyStroke(KeyEvent.VK_S, InputEvent.CTRL_DOWN_MASK), this::saveScreenshot);
        openCommand = Command.action("Open OBJ\u2026", "Load a Wavefront OBJ model (with its map_Kd textures)",
                KeyStroke.getKeyStroke(KeyEvent.VK_O, InputEvent.CTRL_DOWN_MASK), this::openObj);
        exitCommand = Command.action("Exit", "Close Trisect", KeyStroke.getKeyStroke(KeyEvent.VK_Q, InputEvent.CTRL_DOWN_MASK),
                () -> frame.dispatchEvent(new WindowEvent(frame, WindowEvent.WINDOW_CLOSING)));
        String[] modeTips = {
            "Per-pixel perspective: u/w, v/w, 1/w interpolated and divided at every pixel (the reference)",
            "Affine: u, v interpolated linearly on screen (fast, visibly warped)",
            "Tessellated: split into small pieces, each filled affinely"};
        for (RenderMode m : RenderMode.values()) {
            String name = m.id().substring(0, 1).toUpperCase(Locale.ROOT) + m.id().substring(1);
            Command c = Command.toggle(name, modeTips[m.ordinal()],
                    KeyStroke.getKeyStroke(KeyEvent.VK_1 + m.ordinal(), 0), cmd -> selectMode(m));
            modeCommands.add(c);
        }
        modeCommands.get(state.settings().render().mode().ordinal()).show(true);
        String[][] views = {
            {"Image", "Show this path's image"},
            {"Difference", "Show the displacement against the per-pixel path as a heat map (opens the developer tools)"},
            {"Split", "This path left of a divider, the per-pixel path right of it (opens the developer tools)"}};
        for (ViewKind k : ViewKind.values()) {
            viewCommands.add(Command.toggle(views[k.ordinal()][0], views[k.ordinal()][1],
                    KeyStroke.getKeyStroke(KeyEvent.VK_F5 + k.ordinal(), 0), c -> selectView(k)));
        }
        viewCommands.get(state.settings().view().ordinal()).show(true);
        bordersCommand.show(state.settings().render().borders());
        showFilter(state.settings().render().filter());
        borderColourCommand.putValue(Action.NAME, "Border colour: "
                + state.settings().render().borderStyle().colouring().id());
        splitPolicyCommand.putValue(Action.NAME, "Split policy: "
                + state.settings().render().tessellation().policy().name().toLowerCase(Locale.ROOT));

        frame.setJMenuBar(menus());
        // A gap between message and pace, so that a long message is cut short rather than run into it.
        JPanel bottom = new JPanel(new BorderLayout(16, 0));
        bottom.setBorder(BorderFactory.createEmptyBorder(3, 8, 3, 8));
        bottom.add(status, BorderLayout.CENTER);
        bottom.add(pace, BorderLayout.EAST);
        frame.getContentPane().add(view, BorderLayout.CENTER);
        frame.getContentPane().add(bottom, BorderLayout.SOUTH);
        bindKeys(frame.getRootPane());
        view.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                view.publishSize();
            }
        });
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowIconified(WindowEvent e) {
                state.viewSize(0, 0);
            }

            @Override
            public void windowDeiconified(WindowEvent e) {
                view.publishSize();
            }

            @Override
            public void windowDeactivated(WindowEvent e) {
                // Key releases that happen elsewhere would never reach us: stop moving.
                state.input.releaseAll();
            }

            @Override
            public void windowClosed(WindowEvent e) {
                shutdown();
            }
        });
        frame.pack();
        frame.setLocation(0, 0);
        renderThread = new Thread(loop, "trisect-render");
        refresh = new Timer(250, e -> refreshReadouts());
    }

    private static String title(SceneAsset scene) {
        return "Trisect \u2014 " + scene.name();
    }

    /** Shows the window and starts rendering. */
    void start() {
        frame.setVisible(true);
        view.publishSize();
        view.requestFocusInWindow();
        renderThread.start();
        refresh.start();
        statusLine.rest("Fly with W A S D or the arrows, drag to look, wheel for height, Shift for speed. "
                + "F12: developer tools.");
    }

    JFrame frame() {
        return frame;
    }

    ViewPanel view() {
        return view;
    }

    DevToolsDialog devTools() {
        return devTools;
    }

    RenderLoop loop() {
        return loop;
    }

    DemoState state() {
        return state;
    }

    String statusText() {
        return statusLine.text();
    }

    /** Shows a message in the status bar that clears itself after a few seconds. */
    void status(String message) {
        statusLine.pass(message, System.nanoTime());
    }

    /** Replaces the view settings; the render thread uses them from its next frame. */
    void update(UnaryOperator<ViewSettings> change) {
        state.settings(change.apply(state.settings()));
        splitPolicyCommand.putValue(Action.NAME, "Split policy: "
                + state.settings().render().tessellation().policy().name().toLowerCase(Locale.ROOT));
        ViewKind view = state.settings().view();
        for (Command c : viewCommands) {
            c.show(c == viewCommands.get(view.ordinal()));
        }
        if (devTools != null) {
            devTools.syncFromSettings();
        }
    }

    void selectMode(RenderMode m) {
        for (Command c : modeCommands) {
            c.show(c == modeCommands.get(m.ordinal()));
        }
        update(s -> s.withRender(s.render().withMode(m)));
    }

    /** Sets the texture filter, in every path. */
    void selectFilter(TextureFilter f) {
        showFilter(f);
        update(s -> s.withRender(s.render().withFilter(f)));
    }

    private void showFilter(TextureFilter f) {
        filterCommand.putValue(Action.NAME, "Texture filter: " + f.id());
    }

    /** Sets how the outlines are coloured (and turns them on, since that is what one wants to see). */
    void selectBorderStyle(BorderStyle style) {
        borderColourCommand.putValue(Action.NAME, "Border colour: " + style.colouring().id());
        bordersCommand.show(true);
        update(s -> s.withRender(s.render().withBorders(true).withBorderStyle(style)));
    }

    /** Shows a view; the comparison views belong to the developer tools and open them. */
    void selectView(ViewKind k) {
        update(s -> s.withView(k));
        if (k != ViewKind.IMAGE && !devToolsCommand.selected()) {
            devToolsCommand.show(true);
            showDevTools(true);
        }
    }

    private JMenuBar menus() {
        JMenuBar bar = new JMenuBar();
        JMenu file = new JMenu("File");
        file.setMnemonic(KeyEvent.VK_F);
        file.add(new JMenuItem(openCommand));
        file.add(new JMenuItem(screenshotCommand));
        file.addSeparator();
        file.add(new JMenuItem(exitCommand));
        JMenu viewMenu = new JMenu("View");
        viewMenu.setMnemonic(KeyEvent.VK_V);
        viewMenu.add(new JCheckBoxMenuItem(devToolsCommand));
        viewMenu.add(new JCheckBoxMenuItem(bordersCommand));
        viewMenu.add(new JMenuItem(borderColourCommand));
        viewMenu.add(new JCheckBoxMenuItem(orbitCommand));
        viewMenu.add(new JMenuItem(resetCommand));
        viewMenu.add(new JMenuItem(filterCommand));
        viewMenu.addSeparator();
        viewMenu.add(new JCheckBoxMenuItem(inspectorCommand));
        viewMenu.add(new JCheckBoxMenuItem(freezeCommand));
        viewMenu.add(new JMenuItem(stepCommand));
        viewMenu.addSeparator();
        ButtonGroup viewGroup = new ButtonGroup();
        for (Command c : viewCommands) {
            JRadioButtonMenuItem item = new JRadioButtonMenuItem(c);
            viewGroup.add(item);
            viewMenu.add(item);
        }
        JMenu render = new JMenu("Render");
        render.setMnemonic(KeyEvent.VK_R);
        ButtonGroup group = new ButtonGroup();
        for (Command c : modeCommands) {
            JRadioButtonMenuItem item = new JRadioButtonMenuItem(c);
            group.add(item);
            render.add(item);
        }
        render.addSeparator();
        render.add(new JMenuItem(splitPolicyCommand));
        bar.add(file);
        bar.add(viewMenu);
        bar.add(render);
        return bar;
    }

    /** Every command's key, and the movement keys, on the window's root pane. */
    private void bindKeys(JComponent root) {
        InputMap in = root.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW);
        ActionMap act = root.getActionMap();
        List<Command> commands = new ArrayList<>(List.of(devToolsCommand, bordersCommand, orbitCommand, resetCommand,
                filterCommand, freezeCommand, stepCommand, borderColourCommand, inspectorCommand, splitPolicyCommand,
                screenshotCommand, openCommand, exitCommand));
        commands.addAll(modeCommands);
        commands.addAll(viewCommands);
        for (Command c : commands) {
            in.put(c.key(), c);
            act.put(c, c);
        }
        int[][] moves = {
            {KeyEvent.VK_W, InputState.FORWARD}, {KeyEvent.VK_UP, InputState.FORWARD},
            {KeyEvent.VK_S, InputState.BACK}, {KeyEvent.VK_DOWN, InputState.BACK},
            {KeyEvent.VK_A, InputState.LEFT}, {KeyEvent.VK_LEFT, InputState.LEFT},
            {KeyEvent.VK_D, InputState.RIGHT}, {KeyEvent.VK_RIGHT, InputState.RIGHT},
            {KeyEvent.VK_E, InputState.UP}, {KeyEvent.VK_PAGE_UP, InputState.UP},
            {KeyEvent.VK_Q, InputState.DOWN}, {KeyEvent.VK_PAGE_DOWN, InputState.DOWN},
            {KeyEvent.VK_SHIFT, InputState.FAST}};
        for (int[] move : moves) {
            for (int modifiers : new int[] {0, InputEvent.SHIFT_DOWN_MASK}) {
                String name = "move-" + move[0] + "-" + modifiers;
                in.put(KeyStroke.getKeyStroke(move[0], modifiers, false), name + "-press");
                in.put(KeyStroke.getKeyStroke(move[0], modifiers, true), name + "-release");
                int bit = move[1];
                act.put(name + "-press", new AbstractAction() {
                    private static final long serialVersionUID = 1L;

                    @Override
                    public void actionPerformed(ActionEvent e) {
                        state.input.press(bit);
                    }
                });
                act.put(name + "-release", new AbstractAction() {
                    private static final long serialVersionUID = 1L;

                    @Override
                    public void actionPerformed(ActionEvent e) {
                        state.input.release(bit);
                    }
                });
            }
        }
    }

    private void showDevTools(boolean on) {
        if (on) {
            if (devTools == null) {
                devTools = new DevToolsDialog(this);
            }
            devTools.syncFromSettings();
            devTools.showBeside(frame);
        } else if (devTools != null) {
            devTools.setVisible(false);
        }
        devToolsCommand.show(on);
        state.toolsOpen(on);
        if (!on) {
            toolsClosed();
        }
    }

    /** Called when the developer tools window is closed by its own close button. */
    void devToolsClosed() {
        devToolsCommand.show(false);
        state.toolsOpen(false);
        toolsClosed();
    }

    /** The comparison views live in the tools: closing them goes back to the image. */
    private void toolsClosed() {
        if (state.settings().view() != ViewKind.IMAGE) {
            update(s -> s.withView(ViewKind.IMAGE));
        }
    }

    private void refreshReadouts() {
        statusLine.tick(System.nanoTime());
        String problem = state.takeProblem();
        if (problem != null) {
            status(problem);
        }
        DemoState.Progress p = state.progress();
        RenderSettings r = state.settings().render();
        FrameSlot f = view.front();
        pace.setText(state.freeze.frozen()
                ? String.format(Locale.ROOT, "%s  FROZEN at frame %d  %s", r.mode().id(), f == null ? 0 : f.serial,
                        f == null ? "" : f.width() + "x" + f.height())
                : String.format(Locale.ROOT, "%s  %.0f fps  %s", r.mode().id(), p.fps(),
                        f == null ? "" : f.width() + "x" + f.height()));
        String warning = f == null || f.stats == null ? null
                : Warnings.of(f.stats, state.budget(), state.chosenThreshold(), r.tessellation());
        if (warning != null && !warning.equals(statusLine.text())) {
            status(warning);
        }
        if (devTools != null && devTools.isVisible()) {
            devTools.refresh(p, f, state.measurement());
        }
    }

    private void saveScreenshot() {
        FrameSlot f = view.front();
        if (f == null) {
            status("No frame to save yet.");
            return;
        }
        int w = f.width();
        int h = f.height();
        int[] pixels = f.frame.color().clone();
        Path dir = Screenshots.folder();
        Path out = Screenshots.newFile(dir, LocalDateTime.now());
        Path target = out;
        status("Saving " + target + " \u2026");
        new SwingWorker<Path, Void>() {
            @Override
            protected Path doInBackground() {
                ImageFiles.write(target, w, h, pixels);
                return target;
            }

            @Override
            protected void done() {
                try {
                    status("Saved screenshot to " + get());
                } catch (ExecutionException e) {
                    status("Could not save the screenshot: " + message(e.getCause()));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }.execute();
    }

    private void openObj() {
        JFileChooser chooser = new JFileChooser(Path.of("").toAbsolutePath().toFile());
        chooser.setDialogTitle("Open OBJ");
        chooser.setFileFilter(new FileNameExtensionFilter("Wavefront OBJ (*.obj)", "obj"));
        if (chooser.showOpenDialog(frame) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        loadObj(chooser.getSelectedFile().toPath());
    }

    /** Loads an OBJ in the background; the demo keeps running, and a bad file gets a dialog. */
    void loadObj(Path file) {
        status("Loading " + file + " \u2026");
        List<String> notes = new ArrayList<>();
        new SwingWorker<SceneAsset, Void>() {
            @Override
            protected SceneAsset doInBackground() {
                return SceneLoader.load(file, null, notes::add);
            }

            @Override
            protected void done() {
                try {
                    SceneAsset s = get();
                    state.scene(s);
                    frame.setTitle(title(s));
                    orbitCommand.show(false);
                    status("Loaded " + file.getFileName() + " (" + s.mesh().triangleCount() + " triangles)"
                            + (notes.isEmpty() ? "" : ". " + notes.get(0)));
                } catch (ExecutionException e) {
                    String line = "trisect: " + message(e.getCause());
                    status(line);
                    JOptionPane.showMessageDialog(frame, line, "Cannot open OBJ", JOptionPane.ERROR_MESSAGE);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }.execute();
    }

    /** The one-line message the command line would print for this failure. */
    static String message(Throwable t) {
        if (t instanceof InputException ie) {
            return ie.getMessage();
        }
        if (t instanceof OutOfMemoryError) {
            return "out of memory (lower the render scale, or give Java more with -Xmx)";
        }
        return "internal error: " + t;
    }

    private void shutdown() {
        refresh.stop();
        loop.stop();
        if (devTools != null) {
            devTools.dispose();
        }
        for (Frame f : Frame.getFrames()) {
            if (f.isDisplayable() && f != frame) {
                f.dispose();
            }
        }
    }
}
