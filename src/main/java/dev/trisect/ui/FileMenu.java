package dev.trisect.ui;

import dev.trisect.base.internal.ErrorLine;
import dev.trisect.base.internal.Counts;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.content.SceneLoader;
import java.awt.event.InputEvent;
import dev.trisect.scene.Scene;
import java.awt.event.KeyEvent;
import java.lang.ref.SoftReference;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutionException;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Supplier;
import javax.swing.Action;
import javax.swing.JFileChooser;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.KeyStroke;
import javax.swing.SwingWorker;
import javax.swing.filechooser.FileNameExtensionFilter;

/**
 * The demo's ways to a scene: Open OBJ (in the folder it showed last), the files opened lately, and
 * the built-in scenes, each one action for its menu item (and key). A file that cannot be opened gets
 * the command line's one-line message in a dialog and the demo keeps running. Event thread only.
 */
final class FileMenu {
    private final DemoWindow window;
    private final RecentFiles recent;
    private final JMenu recentMenu = new JMenu("Open recent");
    private final JMenu scenes = new JMenu("Built-in scene");
    final Action open;
    /**
     * Counts the scenes asked for (a model to load, a built-in scene): a load that finishes after
     * another scene was asked for is dropped, so the last choice stays on screen. A large OBJ takes
     * seconds to read, and a built-in scene chosen meanwhile was replaced by it when it came.
     */
    private long asked;

    FileMenu(DemoWindow window, RecentFiles recent) {
        this.window = window;
        this.recent = recent;
        open = action("Open OBJ\u2026", "Load a Wavefront OBJ model (with its map_Kd textures); opens in the folder "
                + "used last", KeyStroke.getKeyStroke(KeyEvent.VK_O, InputEvent.CTRL_DOWN_MASK), this::openObj);
        for (String name : DemoScenes.names()) {
            String label = name.substring(0, 1).toUpperCase(Locale.ROOT) + name.substring(1);
            scenes.add(MenuItems.item(action(label, DemoScenes.describe(name), null,
                    () -> builtIn(label, () -> DemoScenes.byName(name).orElseThrow()))));
        }
        rebuildRecent();
    }

    /** Adds Open OBJ, Open recent and the built-in scenes to {@code file}. */
    void addTo(JMenu file) {
        file.add(MenuItems.item(open));
        file.add(recentMenu);
        file.add(scenes);
    }

    /** The submenus, for tests. */
    JMenu recentMenu() {
        return recentMenu;
    }

    JMenu scenesMenu() {
        return scenes;
    }

    private static Action action(String name, String description, KeyStroke key, Runnable behaviour) {
        return DemoCommands.command(name, description, key, behaviour);
    }

    private void rebuildRecent() {
        recentMenu.removeAll();
        List<Path> files = recent.files();
        for (Path p : files) {
            JMenuItem item = MenuItems.item(action(String.valueOf(p.getFileName()), p.toString(), null, () -> load(p)));
            recentMenu.add(item);
        }
        if (files.isEmpty()) {
            JMenuItem none = new JMenuItem("(none yet)");
            none.setEnabled(false);
            recentMenu.add(none);
        } else {
            recentMenu.addSeparator();
            recentMenu.add(MenuItems.item(action("Clear recent files", "Forget the files opened lately", null, () -> {
                recent.clear();
                rebuildRecent();
            })));
        }
    }

    private void openObj() {
        JFileChooser chooser = new JFileChooser(recent.folder().toFile());
        chooser.setDialogTitle("Open OBJ");
        chooser.setFileFilter(new FileNameExtensionFilter("Wavefront OBJ (*.obj)", "obj"));
        if (chooser.showOpenDialog(window.frame()) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        load(chooser.getSelectedFile().toPath());
    }

    /** Loads an OBJ in the background; the demo keeps running, and a bad file gets a dialog. */
    void load(Path file) {
        // A lost texture does not reject the model here: a placeholder and a warning instead.
        load(file, notes -> SceneLoader.load(file, null, notes, true));
    }

    /**
     * As {@link #load(Path)}, reading the file with {@code reader} (given where notes go), on a
     * background thread; its result is shown unless another scene is asked for before it comes.
     *
     * @return the load under way
     */
    SwingWorker<SceneAsset, Void> load(Path file, Function<Consumer<String>, SceneAsset> reader) {
        window.status("Loading " + file + " \u2026");
        List<String> notes = new ArrayList<>();
        return inBackground(() -> reader.apply(notes::add), s -> {
            window.show(s);
            // The placeholder stays on screen, so its warning stays in the bar when the message goes.
            window.sceneNote(standingNote(notes));
            recent.opened(file);
            rebuildRecent();
            window.status(loaded(file, s.mesh().triangleCount(), notes));
        }, line -> {
            if (!Files.exists(file)) {
                recent.forget(file);
                rebuildRecent();
            }
            JOptionPane.showMessageDialog(window.frame(), line, "Cannot open OBJ", JOptionPane.ERROR_MESSAGE);
        });
    }

    /**
     * Shows a built-in scene, made by {@code maker} on a background thread (the largest, a million-triangle
     * globe, takes a second to build, which on the event thread froze the window), unless another scene
     * is asked for before it is made.
     *
     * @return the making under way
     */
    SwingWorker<SceneAsset, Void> builtIn(String label, Supplier<SceneAsset> maker) {
        window.status("Building " + label + " \u2026");
        return inBackground(maker, s -> {
            window.show(s);
            window.status("Built-in scene " + label);
        }, line -> { });
    }

    /**
     * Makes a scene on a background thread and, on the event thread, hands it to {@code shown}, unless
     * another scene was asked for meanwhile (that one stays); a failure goes to the status bar as the
     * command line's one line, then to {@code failed}.
     */
    private SwingWorker<SceneAsset, Void> inBackground(Supplier<SceneAsset> make, Consumer<SceneAsset> shown,
                                                       Consumer<String> failed) {
        long request = ++asked;
        // The scene on screen goes before the next is made, so that the largest model that fits alone
        // opens after another; it comes back if the new one fails and the collector has not taken it.
        SoftReference<Scene> previous = window.releaseScene();
        SwingWorker<SceneAsset, Void> worker = new SwingWorker<>() {
            @Override
            protected SceneAsset doInBackground() {
                return make.get();
            }

            @Override
            protected void done() {
                if (request != asked) {
                    return;
                }
                try {
                    shown.accept(get());
                } catch (ExecutionException e) {
                    window.restoreScene(previous.get());
                    String line = ErrorLine.of(DemoWindow.message(e.getCause()));
                    window.status(line);
                    failed.accept(line);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        };
        worker.execute();
        return worker;
    }

    /** What the status bar keeps showing for a model loaded with these notes, or null for none. */
    static String standingNote(List<String> notes) {
        return notes.isEmpty() ? null
                : "\u26a0 " + notes.get(0) + (notes.size() > 1 ? " (and " + (notes.size() - 1) + " more)" : "");
    }

    /** The status line after a load: what was loaded, and the first note (a placeholder texture...) with how many follow. */
    static String loaded(Path file, int triangles, List<String> notes) {
        String s = "Loaded " + file.getFileName() + " (" + Counts.of(triangles, "triangle") + ")";
        return notes.isEmpty() ? s : s + ". " + standingNote(notes);
    }
}
