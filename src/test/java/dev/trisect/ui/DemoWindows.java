package dev.trisect.ui;

import dev.trisect.content.DemoScenes;
import java.io.IOException;
import java.nio.file.Files;

/** Demo windows for the GUI tests that open their own. */
final class DemoWindows {
    private DemoWindows() {
    }

    /**
     * A new demo window on the demo scene, drawing with one thread, its recent files kept in a fresh
     * temporary folder (not the user's). Event thread; not yet started.
     */
    static DemoWindow demo() throws IOException {
        return new DemoWindow(DemoScenes.demo(), 1,
                new RecentFiles(Files.createTempDirectory("trisect-recent").resolve("demo.properties")));
    }
}
