package dev.trisect.ui;

import dev.trisect.TestObjs;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.content.SceneLoader;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.view.FrameInfo;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import javax.swing.SwingWorker;

/**
 * Opens OBJ files one after another in the demo, through File ▸ Open as a user does, and says whether
 * each was loaded and drawn: for scripts/demo-heap.sh, which runs it under various heaps. The demo starts
 * with the floor; after each file it waits until a frame of the file's triangles is on screen and
 * {@link FrameRenderer#TRIM_FRAMES} twice over more have followed. Prints one line per file; exits 0
 * when every file was drawn, 1 at the first that was not (a failed load, a failed frame, or no frame
 * within about two minutes of polling), each with the heap in use after a full collection once it is drawn.
 *
 * <p>{@code DemoHeapProbe --make DIR} writes the models instead: DIR/grid1m.obj (1,000,000 triangles
 * and 2 more), DIR/grid2m.obj (2,000,000), DIR/small.obj (2).
 */
public final class DemoHeapProbe {
    private DemoHeapProbe() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length == 2 && args[0].equals("--make")) {
            Path dir = Files.createDirectories(Path.of(args[1]));
            TestObjs.grid(dir.resolve("grid1m.obj"), 708);
            TestObjs.grid(dir.resolve("grid2m.obj"), 1000);
            TestObjs.grid(dir.resolve("small.obj"), 1);
            return;
        }
        DemoWindow w = DemoApp.openForTest(DemoScenes.byName("floor").orElseThrow(), FrameRenderer.defaultThreads());
        // Frames keep coming (a still view idles), so that each model is seen drawn for a while.
        w.view().addUpdateListener((seconds, frame) -> true);
        AtomicReference<String> failed = new AtomicReference<>();
        w.view().addMessageListener(m -> {
            if (m.startsWith("trisect: cannot draw the frame")) {
                failed.compareAndSet(null, m);
            }
        });
        int status = 0;
        for (String name : args) {
            Path file = Path.of(name);
            AtomicReference<SwingWorker<SceneAsset, Void>> job = new AtomicReference<>();
            // As File > Open reads a file (FileMenu.load(Path)), with the worker kept to wait on.
            SwingUtilities.invokeAndWait(() -> job.set(w.fileMenu.load(file, notes -> SceneLoader.load(file, null, notes, true))));
            int triangles;
            try {
                triangles = job.get().get().mesh().triangleCount();
            } catch (ExecutionException e) {
                System.out.println(file.getFileName() + ": not loaded: " + DemoWindow.message(e.getCause()));
                status = 1;
                break;
            }
            String drawn = awaitFrames(w, triangles, failed);
            System.out.printf("%s: %s (%d triangles; heap in use after a full collection %.0f MiB)%n",
                    file.getFileName(), drawn == null ? "drawn" : drawn, triangles, heapAfterGc() / 1048576.0);
            if (drawn != null) {
                status = 1;
                break;
            }
        }
        System.exit(status);
    }

    private static long heapAfterGc() throws InterruptedException {
        for (int i = 0; i < 3; i++) {
            System.gc();
            Thread.sleep(50);
        }
        Runtime rt = Runtime.getRuntime();
        return rt.totalMemory() - rt.freeMemory();
    }

    /** Null once frames of {@code triangles} have been on screen long enough; else what went wrong. */
    private static String awaitFrames(DemoWindow w, int triangles, AtomicReference<String> failed)
            throws InterruptedException {
        long first = -1;
        // Bounded waiting, not timing: 6,000 polls 20 ms apart, about two minutes.
        for (int poll = 0; poll < 6000; poll++) {
            if (failed.get() != null) {
                return failed.get();
            }
            FrameInfo f = w.latest();
            if (f != null && f.stats().trianglesIn() == triangles) {
                if (first < 0) {
                    first = f.number();
                } else if (f.number() - first >= 2L * FrameRenderer.TRIM_FRAMES) {
                    return null;
                }
            }
            Thread.sleep(20);
        }
        return "no frame of it within 6,000 polls (about 2 minutes)";
    }
}
