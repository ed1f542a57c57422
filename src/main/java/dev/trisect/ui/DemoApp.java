package dev.trisect.ui;

import com.formdev.flatlaf.FlatDarkLaf;
import dev.trisect.base.InputException;
import dev.trisect.base.internal.BuildVersion;
import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.content.SceneLoader;
import dev.trisect.render.RenderMode;
import java.awt.AWTError;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import javax.swing.ToolTipManager;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine;

/**
 * Launches the desktop demo. Without a display it prints one line pointing to the headless
 * {@code render} command and returns status 1.
 */
@Command(name = "demo", mixinStandardHelpOptions = true, versionProvider = DemoApp.Version.class, sortOptions = false,
        description = "Open the desktop demo: fly through a textured scene; F12 opens the developer tools.")
public final class DemoApp implements Callable<Integer> {
    @Option(names = "--scene", paramLabel = "NAME", defaultValue = "demo",
            description = "Built-in scene to open (default: ${DEFAULT-VALUE}).")
    String scene;

    @Option(names = "--obj", paramLabel = "FILE", description = "Open this OBJ file instead of a built-in scene.")
    Path obj;

    @Option(names = "--mode", paramLabel = "perspective|affine|tessellated|spans", defaultValue = "tessellated",
            description = "Texturing path at start (default: ${DEFAULT-VALUE}).")
    String mode;

    @Option(names = "--render-scale", paramLabel = "F", defaultValue = "1",
            description = "Frame pixels per device pixel, 0.25 to 1; lower is faster (default: ${DEFAULT-VALUE}).")
    double renderScale;

    @Option(names = "--threads", paramLabel = "N",
            description = "Render threads (default: one per processor).")
    Integer threads;

    @Option(names = "--dev-tools", description = "Open the developer tools at start.")
    boolean devTools;

    @Option(names = "--target-ms", paramLabel = "MS",
            description = "Start with the frame budget on: the tessellated path's threshold adapts every frame to "
                    + "hold this engine time per frame, never looser than the threshold set (developer tools, "
                    + "Frame budget).")
    Double targetMs;

    @Option(names = "--soak", paramLabel = "SECONDS",
            description = "Run the endurance check: measure frame rates per path, then change settings, sizes and "
                    + "windows for this long while watching the heap and the event thread; print a report and exit.")
    Integer soak;

    @Option(names = "--report", paramLabel = "FILE", description = "With --soak: also write the report here (JSON).")
    Path report;

    /** What -V, --version prints, as every command does (without it, nothing). */
    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            return new String[] {BuildVersion.line()};
        }
    }

    @Spec
    CommandSpec spec;

    /** Opens the --report file; set by {@link #launch}. */
    private ReportFile.Opener reports;

    private static final String HEADLESS_HINT = "render headless instead: java -jar trisect.jar render --scene demo "
            + "--out demo.png (see render --help)";

    /**
     * Connects to the display now, where a failure can still be one line: AWT reports an unreachable X
     * server with an {@link AWTError} from deep inside the first window. Returns the display's name when
     * it cannot be reached, null when it can.
     */
    private static String noDisplay() {
        try {
            GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices();
            return null;
        } catch (AWTError | HeadlessException e) {
            String name = System.getenv("DISPLAY");
            return name != null ? "'" + name + "' (is an X server running there?)" : "(" + e.getMessage() + ")";
        }
    }

    /**
     * Runs the demo's command line; returns a process exit status, or -1 when the demo is running.
     *
     * @param reports opens the soak's {@code --report} file
     */
    public static int launch(ReportFile.Opener reports, String... args) {
        DemoApp app = new DemoApp();
        app.reports = reports;
        // Named as typed, so that its usage line reads "trisect demo".
        CommandLine cl = new CommandLine(app).setCommandName("trisect demo");
        PrintWriter err = new PrintWriter(System.err, true);
        cl.setParameterExceptionHandler((ex, a) -> {
            err.println("trisect demo: " + ex.getMessage().lines().findFirst().orElse("invalid arguments")
                    + " (see trisect demo --help)");
            return 2;
        });
        cl.setExecutionExceptionHandler((ex, c, r) -> {
            err.println("trisect: " + DemoWindow.message(ex));
            return ex instanceof InputException ie ? ie.exitStatus() : 1;
        });
        int status = cl.execute(args);
        // --help and --version print; a standard output that cannot take it fails as in every command.
        // Both are asked (no short cut): picocli's writer flushes into System.out, which keeps the error.
        if (status == 0 && (cl.getOut().checkError() | System.out.checkError())) {
            err.println("trisect: cannot write to standard output");
            return 1;
        }
        return status;
    }

    @Override
    public Integer call() throws Exception {
        RenderMode start = null;
        for (RenderMode m : RenderMode.values()) {
            if (m.id().equalsIgnoreCase(mode)) {
                start = m;
            }
        }
        if (start == null) {
            throw InputException.usage("--mode must be perspective, affine, tessellated or spans, got " + mode);
        }
        if (!(renderScale >= 0.25 && renderScale <= 1)) {
            throw InputException.usage("--render-scale must be between 0.25 and 1, got " + renderScale);
        }
        int n = threads == null ? Runtime.getRuntime().availableProcessors() : threads;
        if (n < 1 || n > 256) {
            throw InputException.usage("--threads must be between 1 and 256, got " + n);
        }
        if (targetMs != null && !(targetMs > 0 && targetMs <= 1000)) {
            throw InputException.usage("--target-ms must be more than 0 and at most 1000 milliseconds, got " + targetMs);
        }
        if (soak != null && soak < 1) {
            throw InputException.usage("--soak must be at least 1 second, got " + soak);
        }
        if (report != null && soak == null) {
            throw InputException.usage("--report goes with --soak");
        }
        // As the command line's outputs: Path drops a trailing separator, so r.json/ (a folder, or a slip)
        // would write the file r.json.
        String given = report == null ? "" : spec.findOption("--report").originalStringValues().get(0);
        if (given.endsWith("/") || given.endsWith(java.io.File.separator)) {
            throw InputException.usage("--report '" + given + "' ends with a separator, so it names a directory: "
                    + "give the name of the file to write");
        }
        // What to open is checked before the display, so that a typo is named even where no window can open;
        // --obj with --scene would silently drop one of them.
        if (obj != null && spec.commandLine().getParseResult().hasMatchedOption("--scene")) {
            throw InputException.usage("--obj and --scene both name what to open; give one of them");
        }
        if (obj == null && DemoScenes.byName(scene).isEmpty()) {
            throw InputException.usage("unknown scene '" + scene + "' (built-in scenes: "
                    + String.join(", ", DemoScenes.names()) + ")");
        }
        // The report's folder and writability are checked now, not after the soak.
        try (ReportFile file = report == null ? null : reports.open(report)) {
            return open(start, n, file);
        }
    }

    private int open(RenderMode start, int n, ReportFile file) throws Exception {
        if (GraphicsEnvironment.isHeadless()) {
            System.err.println("trisect: no display for the desktop demo; " + HEADLESS_HINT);
            return 1;
        }
        String display = noDisplay();
        if (display != null) {
            System.err.println("trisect: cannot connect to the display " + display + "; " + HEADLESS_HINT);
            return 1;
        }

        SceneAsset s = obj != null ? SceneLoader.load(obj, null, note -> System.err.println("trisect: note: " + note))
                : DemoScenes.byName(scene).orElseThrow();
        RenderMode initial = start;
        AtomicReference<DemoWindow> window = new AtomicReference<>();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            try {
                // The look and feel is the demo's choice, made here and never by the library.
                FlatDarkLaf.setup();
                ToolTipManager.sharedInstance().setDismissDelay(15000);
                DemoWindow w = new DemoWindow(s, n);
                w.view().setRenderScale(renderScale);
                w.render(r -> r.withMode(initial));
                if (targetMs != null) {
                    w.view().setFrameTimeTarget(targetMs);
                }
                w.start();
                if (devTools) {
                    w.view().showDevTools(true);
                }
                window.set(w);
            } catch (RuntimeException | Error e) {
                failure.set(e);
            }
        });
        if (failure.get() != null) {
            System.err.println("trisect: cannot open the demo window: " + failure.get().getMessage()
                    + "; render headless instead: java -jar trisect.jar render --help");
            return 1;
        }
        if (soak != null) {
            return new SoakRun(window.get(), soak, file).run();
        }
        return -1;
    }

    /** Opens the demo on the event thread for tests: the window, built and shown, with the demo's look. */
    static DemoWindow openForTest(SceneAsset scene, int threads) throws Exception {
        // Its own memory of files, apart from the user's.
        return openForTest(scene, threads,
                new RecentFiles(java.nio.file.Path.of(System.getProperty("java.io.tmpdir"), "trisect-demo-test.properties")));
    }

    /** As {@link #openForTest(SceneAsset, int)}, remembering files in {@code recent}. */
    static DemoWindow openForTest(SceneAsset scene, int threads, RecentFiles recent) throws Exception {
        AtomicReference<DemoWindow> window = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            FlatDarkLaf.setup();
            DemoWindow w = new DemoWindow(scene, threads, recent);
            w.start();
            window.set(w);
        });
        return window.get();
    }
}
