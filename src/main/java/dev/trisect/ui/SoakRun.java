package dev.trisect.ui;

import dev.trisect.base.InputException;
import dev.trisect.base.internal.JsonObject;
import dev.trisect.render.RenderMode;
import dev.trisect.render.SplitPolicy;
import dev.trisect.view.FrameInfo;
import dev.trisect.view.ViewAction;
import java.awt.Frame;
import java.awt.event.KeyEvent;
import java.awt.event.WindowEvent;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import javax.swing.SwingUtilities;

/**
 * The demo's endurance check ({@code trisect demo --soak SECONDS}). It measures the frame rate of
 * each path, then for the given time keeps changing what a user can change — paths, policies,
 * sliders, views, render scale, window size, minimizing, the developer tools window — while it:
 * <ul>
 * <li>posts a task to the event thread every 20 ms and records how long each waited (the event
 * thread's responsiveness);</li>
 * <li>every 60 s returns to one standard state (window size, settings, developer tools closed) and
 * samples the heap after a full collection there, so the samples are comparable and their trend
 * shows whether anything accumulates; between checkpoints it also samples the heap as it is;</li>
 * <li>counts uncaught exceptions on any thread (there should be none).</li>
 * </ul>
 * Frame rates, heap and latency are measured and reported, not asserted: they depend on the machine.
 * It drives the view as a program or a user would: its public methods, its actions, key events.
 */
final class SoakRun {
    private final DemoWindow window;
    private final int seconds;
    private final ReportFile report;
    private final AtomicInteger exceptions = new AtomicInteger();
    private final List<String> exceptionLines = new ArrayList<>();
    private final Random random = new Random(20261121);

    /** The render settings every checkpoint returns to: those the demo opened with, tessellated. */
    private final dev.trisect.render.RenderSettings standard;

    SoakRun(DemoWindow window, int seconds, ReportFile report) {
        this.window = window;
        this.standard = window.view().getRenderSettings().withMode(RenderMode.TESSELLATED);
        this.seconds = seconds;
        this.report = report;
    }

    int run() throws Exception {
        Thread.setDefaultUncaughtExceptionHandler((t, e) -> {
            exceptions.incrementAndGet();
            synchronized (exceptionLines) {
                exceptionLines.add(t.getName() + ": " + e);
            }
        });
        JsonObject out = new JsonObject();
        // The soak measures how fast the view can draw: every frame, as fast as it can, still scene or not.
        window.view().setMaxFrameRate(0);
        window.view().addUpdateListener((step, frame) -> true);
        onEdt(w -> w.frame().setSize(w.frame().getWidth(), w.frame().getHeight()));
        Thread.sleep(1500);
        FrameInfo first = window.latest();
        out.put("frame_size", first == null ? "none" : first.width() + "x" + first.height());
        out.put("render_threads", window.view().getRenderThreads());
        // Let the JIT compile every path's loops before anything is measured.
        for (RenderMode m : RenderMode.values()) {
            onEdt(w -> w.render(r -> r.withMode(m)));
            Thread.sleep(2500);
        }
        out.put("fps_dev_tools_closed", pathRates(false));
        out.put("fps_dev_tools_open_comparing", pathRates(true));
        churn(out);
        Thread.sleep(500);
        out.put("uncaught_exceptions", exceptions.get());
        synchronized (exceptionLines) {
            out.put("exception_messages", new ArrayList<>(exceptionLines.subList(0, Math.min(5, exceptionLines.size()))));
        }
        long framesBefore = frames();
        Thread.sleep(1000);
        boolean rendering = frames() > framesBefore;
        out.put("still_rendering", rendering);
        onEdt(w -> w.frame().dispatchEvent(new WindowEvent(w.frame(), WindowEvent.WINDOW_CLOSING)));
        String json = out.toString();
        // As every command: standard output first (a failure there leaves the report file untouched),
        // then the report, all or nothing; either failure is one line and exit 1.
        System.out.println(json);
        if (System.out.checkError()) {
            System.err.println("trisect: cannot write to standard output");
            return 1;
        }
        if (report != null) {
            try {
                report.write(json + "\n");
            } catch (InputException e) {
                System.err.println("trisect: " + e.getMessage());
                return 1;
            }
        }
        return exceptions.get() == 0 && rendering ? 0 : 1;
    }

    /** Frames per second of each path, 2 s to settle then 8 s measured. */
    private JsonObject pathRates(boolean devTools) throws Exception {
        onEdt(w -> w.view().showDevTools(devTools));
        JsonObject rates = new JsonObject();
        for (RenderMode m : RenderMode.values()) {
            onEdt(w -> w.render(r -> r.withMode(m)));
            Thread.sleep(2000);
            long f0 = frames();
            long t0 = System.nanoTime();
            Thread.sleep(8000);
            long f1 = frames();
            rates.put(m.id(), round((f1 - f0) * 1e9 / (System.nanoTime() - t0)));
        }
        return rates;
    }

    private void churn(JsonObject out) throws Exception {
        AtomicLong worstWait = new AtomicLong();
        AtomicLong over100 = new AtomicLong();
        AtomicLong posts = new AtomicLong();
        long[] histogram = new long[1001];
        volatileRun = true;
        Thread watchdog = new Thread(() -> {
            while (volatileRun) {
                long posted = System.nanoTime();
                SwingUtilities.invokeLater(() -> {
                    long waitedMs = (System.nanoTime() - posted) / 1_000_000;
                    worstWait.accumulateAndGet(waitedMs, Math::max);
                    if (waitedMs > 100) {
                        over100.incrementAndGet();
                    }
                    histogram[(int) Math.min(1000, waitedMs)]++;
                    posts.incrementAndGet();
                });
                try {
                    Thread.sleep(20);
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "trisect-soak-watchdog");
        watchdog.setDaemon(true);
        watchdog.start();
        List<Double> heap = new ArrayList<>();
        List<Double> checkpoints = new ArrayList<>();
        checkpoints.add(checkpoint());
        long start = System.nanoTime();
        long nextHeap = start + 15_000_000_000L;
        long nextCheckpoint = start + 60_000_000_000L;
        long f0 = frames();
        int actions = 0;
        while (System.nanoTime() - start < seconds * 1_000_000_000L) {
            act(actions++);
            Thread.sleep(300 + random.nextInt(600));
            if (System.nanoTime() >= nextCheckpoint) {
                checkpoints.add(checkpoint());
                nextCheckpoint += 60_000_000_000L;
                nextHeap = System.nanoTime() + 15_000_000_000L;
            } else if (System.nanoTime() >= nextHeap) {
                heap.add(heapAfterGc());
                nextHeap += 15_000_000_000L;
            }
        }
        checkpoints.add(checkpoint());
        volatileRun = false;
        watchdog.join(1000);
        double elapsed = (System.nanoTime() - start) / 1e9;
        out.put("soak_seconds", round(elapsed));
        out.put("actions", actions);
        out.put("frames_during_soak", frames() - f0);
        out.put("heap_checkpoints_mb", checkpoints.stream().map(SoakRun::round).toList());
        out.put("heap_checkpoint_first_mb", round(checkpoints.get(0)));
        out.put("heap_checkpoint_last_mb", round(checkpoints.get(checkpoints.size() - 1)));
        out.put("heap_checkpoint_slope_mb_per_min", round(slope(checkpoints) * 100) / 100.0);
        out.put("heap_between_checkpoints_mb", heap.stream().map(SoakRun::round).toList());
        out.put("heap_between_max_mb", round(heap.stream().mapToDouble(Double::doubleValue).max().orElse(0)));
        out.put("edt_tasks_timed", posts.get());
        out.put("edt_max_wait_ms", worstWait.get());
        out.put("edt_p99_wait_ms", percentile(histogram, 0.99));
        out.put("edt_waits_over_100ms", over100.get());
    }

    private volatile boolean volatileRun;

    /** One change a user could make, chosen at random among many. */
    private void act(int n) throws Exception {
        int choice = random.nextInt(16);
        switch (choice) {
            case 0 -> perform(ViewAction.BORDERS);
            case 1 -> onEdt(w -> w.render(r -> r.withMode(RenderMode.values()[random.nextInt(RenderMode.values().length)])));
            case 2 -> perform(ViewAction.DEV_TOOLS);
            case 3 -> onEdt(w -> w.render(r -> r.withTessellation(r.tessellation()
                    .withPolicy(random.nextBoolean() ? SplitPolicy.EDGE : SplitPolicy.ERROR))));
            case 4 -> onEdt(w -> w.render(r -> r.withTessellation(r.tessellation().withMaxEdge(2 + random.nextInt(120)))));
            case 5 -> onEdt(w -> w.render(r -> r.withTessellation(r.tessellation()
                    .withMaxError(0.05 * Math.pow(160, random.nextDouble())))));
            case 6 -> perform(new ViewAction[] {ViewAction.SHOW_IMAGE, ViewAction.SHOW_DIFFERENCE,
                ViewAction.SHOW_SPLIT}[random.nextInt(3)]);
            case 7 -> onEdt(w -> w.view().setRenderScale(0.25 + 0.75 * random.nextDouble()));
            case 8 -> onEdt(w -> {
                int[][] sizes = {{80, 60}, {16, 12}, {1296, 800}, {2000, 1300}, {640, 480}, {300, 900}};
                int[] size = sizes[random.nextInt(sizes.length)];
                w.frame().setSize(size[0], size[1]);
            });
            case 9 -> {
                onEdt(w -> w.frame().setExtendedState(Frame.ICONIFIED));
                Thread.sleep(400);
                onEdt(w -> w.frame().setExtendedState(Frame.NORMAL));
            }
            case 10 -> perform(ViewAction.AUTO_ORBIT);
            case 11 -> perform(ViewAction.RESET_CAMERA);
            case 12 -> {
                int key = new int[] {KeyEvent.VK_W, KeyEvent.VK_A, KeyEvent.VK_S, KeyEvent.VK_D}[n % 4];
                key(KeyEvent.KEY_PRESSED, key);
                Thread.sleep(200);
                key(KeyEvent.KEY_RELEASED, key);
            }
            case 13 -> onEdt(w -> {
                // A drag, as the mouse makes one.
                int x = w.view().getWidth() / 2;
                int y = w.view().getHeight() / 2;
                mouse(w, java.awt.event.MouseEvent.MOUSE_PRESSED, x, y);
                mouse(w, java.awt.event.MouseEvent.MOUSE_DRAGGED, x + random.nextInt(41) - 20, y + random.nextInt(21) - 10);
                mouse(w, java.awt.event.MouseEvent.MOUSE_RELEASED, x, y);
            });
            case 14 -> onEdt(w -> {
                // Close the developer tools in the middle of whatever frame is being drawn.
                for (java.awt.Window d : java.awt.Window.getWindows()) {
                    if (d instanceof javax.swing.JDialog dialog && "Developer tools".equals(dialog.getTitle())
                            && d.isVisible()) {
                        d.dispatchEvent(new WindowEvent(d, WindowEvent.WINDOW_CLOSING));
                    }
                }
            });
            default -> onEdt(w -> w.render(r -> r.withTessellation(r.tessellation().withMaxDepth(random.nextInt(25)))));
        }
    }

    private void perform(ViewAction a) throws Exception {
        onEdt(w -> w.view().action(a).actionPerformed(new java.awt.event.ActionEvent(w.view(), 0, "soak")));
    }

    /** A key event delivered to the view as the keyboard would. */
    private void key(int id, int code) throws Exception {
        onEdt(w -> w.view().dispatchEvent(new KeyEvent(w.view(), id, System.currentTimeMillis(), 0, code,
                KeyEvent.CHAR_UNDEFINED)));
    }

    private static void mouse(DemoWindow w, int id, int x, int y) {
        int mask = id == java.awt.event.MouseEvent.MOUSE_RELEASED ? 0 : java.awt.event.InputEvent.BUTTON1_DOWN_MASK;
        w.view().dispatchEvent(new java.awt.event.MouseEvent(w.view(), id, System.currentTimeMillis(), mask, x, y, 1,
                false, java.awt.event.MouseEvent.BUTTON1));
    }

    /** Frames the view has drawn so far. */
    private long frames() {
        FrameInfo f = window.latest();
        return f == null ? 0 : f.number();
    }

    /** The standard state, a moment to settle, then the heap after a full collection. */
    private double checkpoint() throws Exception {
        onEdt(w -> {
            w.frame().setExtendedState(Frame.NORMAL);
            w.frame().setSize(STANDARD_WIDTH, STANDARD_HEIGHT);
            w.view().showDevTools(false);
            if (Boolean.TRUE.equals(w.view().action(ViewAction.AUTO_ORBIT).getValue(javax.swing.Action.SELECTED_KEY))) {
                w.view().action(ViewAction.AUTO_ORBIT).actionPerformed(null);
            }
            w.view().setRenderScale(1);
            w.render(r -> standard);
        });
        // Settled means: frames of the standard size are on screen, and far more than the renderer's trim
        // window (FrameRenderer.TRIM_FRAMES, 5 frames) have passed since, so no buffer of an earlier state
        // is still held.
        long deadline = System.currentTimeMillis() + 20_000;
        long settledFrom = -1;
        while (System.currentTimeMillis() < deadline) {
            Thread.sleep(100);
            FrameInfo f = window.latest();
            boolean standard = f != null && onEdtGet(w -> {
                double scale = w.view().getGraphicsConfiguration() == null ? 1
                        : w.view().getGraphicsConfiguration().getDefaultTransform().getScaleX();
                return f.width() == (int) Math.round(w.view().getWidth() * scale)
                        && f.height() == (int) Math.round(w.view().getHeight() * scale);
            });
            if (!standard) {
                settledFrom = -1;
            } else if (settledFrom < 0) {
                settledFrom = f.number();
            } else if (f.number() - settledFrom > SETTLE_FRAMES) {
                break;
            }
        }
        return heapAfterGc();
    }

    /**
     * Frames a checkpoint waits: 36 times the renderer's trim window (FrameRenderer.TRIM_FRAMES, 5 frames),
     * 3 s at 60 fps, so that the collector too has had time to give back what the earlier state held.
     */
    private static final int SETTLE_FRAMES = 180;

    /** Least-squares slope per sample interval (one minute between checkpoints). */
    private static double slope(List<Double> y) {
        int n = y.size();
        if (n < 2) {
            return 0;
        }
        double mx = (n - 1) / 2.0;
        double my = y.stream().mapToDouble(Double::doubleValue).average().orElse(0);
        double num = 0;
        double den = 0;
        for (int i = 0; i < n; i++) {
            num += (i - mx) * (y.get(i) - my);
            den += (i - mx) * (i - mx);
        }
        return num / den;
    }

    private static final int STANDARD_WIDTH = 1296;
    private static final int STANDARD_HEIGHT = 800;

    private static double heapAfterGc() {
        System.gc();
        System.gc();
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed() / 1048576.0;
    }

    private static long percentile(long[] histogram, double q) {
        long total = Arrays.stream(histogram).sum();
        long seen = 0;
        for (int i = 0; i < histogram.length; i++) {
            seen += histogram[i];
            if (seen >= q * total) {
                return i;
            }
        }
        return histogram.length - 1;
    }

    private void onEdt(Consumer<DemoWindow> task) throws Exception {
        SwingUtilities.invokeAndWait(() -> task.accept(window));
    }

    private <T> T onEdtGet(java.util.function.Function<DemoWindow, T> task) throws Exception {
        Object[] box = new Object[1];
        SwingUtilities.invokeAndWait(() -> box[0] = task.apply(window));
        @SuppressWarnings("unchecked")
        T t = (T) box[0];
        return t;
    }

    private static double round(double v) {
        return Math.round(v * 10) / 10.0;
    }
}
