package dev.trisect.view.internal;

import dev.trisect.content.AssetScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Viewport;
import dev.trisect.metrics.Comparison;
import dev.trisect.metrics.HeatMap;
import dev.trisect.metrics.ImageComparison;
import dev.trisect.metrics.TexelToScreen;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Scene;
import dev.trisect.scene.internal.DrawnFrame;

/**
 * What the render loop draws for one frame, on the render thread: the camera moved by the input, the
 * shown path, and — for the difference and split views, the inspector, or when a comparison is due
 * (at least twice a second while the developer tools are open) — the per-pixel path with UV output,
 * the difference measured, the inspected pixel, the hover highlight, the border overlay and the
 * heat map or split. It keeps what lasts from frame to frame for that: the reference framebuffer, the
 * displacements, the scene drawn last and the budget's controller. {@link RenderLoop} decides when to
 * draw and hands the slot on.
 */
final class FrameDrawer {
    /** A comparison is due when the last one is this old. */
    static final long COMPARE_INTERVAL_NANOS = 400_000_000L;

    private final ViewState state;
    private final FrameRenderer renderer;
    private final CameraDriver cameras;
    private final BudgetHook budget = new BudgetHook();
    private final HoverHighlight highlight = new HoverHighlight();
    private Framebuffer reference;
    private float[] displacement;
    /** The scene of the last frame drawn: another one releases the renderer's storage first. */
    private Scene drawnScene;
    /**
     * Frames still to draw after a scene was replaced, even in a still view: until every frame slot has
     * been drawn with the new scene, the others hold the old one's draws (its meshes) from being collected.
     */
    private int settleFrames;
    /** Time the last frame spent on the comparison: the per-pixel render, other paths' timing, measuring. */
    private long compareStageNanos;
    private long frames;
    private long lastCompare;
    private double compareMs;

    FrameDrawer(ViewState state, FrameRenderer renderer) {
        this.state = state;
        this.renderer = renderer;
        this.cameras = new CameraDriver(state);
    }

    /** Frames drawn so far (the last one's serial number). */
    long frames() {
        return frames;
    }

    /** Milliseconds the last measurement of the difference took. */
    double compareMs() {
        return compareMs;
    }

    /** Nanoseconds the last frame spent on the comparison stage. */
    long compareStageNanos() {
        return compareStageNanos;
    }

    /** The frame-time budget's controller. */
    BudgetHook budget() {
        return budget;
    }

    /** Whether a frame is still owed after a scene was replaced (each call counts one off). */
    boolean settling() {
        if (settleFrames > 0) {
            settleFrames--;
            return true;
        }
        return false;
    }

    /** The per-pixel frame kept for the comparison and the inspector, or null; for tests of what is kept. */
    Framebuffer reference() {
        return reference;
    }

    /** A frame failed: the next one starts its reference afresh. */
    void failed() {
        reference = null;
    }

    /**
     * Frame pixels per logical pixel of the view for a frame {@code fw} wide, at least 1: the screen's
     * scale times the render scale, so that labels, screen text, pixel-sized billboards and lines keep
     * their size in Swing's pixels on a high-density screen; never below 1, so that below a render scale
     * of 1 they are drawn with their whole size and magnified with the frame, rather than shrunk illegible.
     */
    double pixelScale(int fw) {
        int w = state.viewWidth();
        double s = w > 0 ? state.screenScale() * fw / w : 1;
        return Math.max(1, Math.min(16, s));
    }

    /**
     * Moves the camera by the controls for the next frame, {@code dt} seconds after the last (with
     * {@code redraw} the last frame's camera), and makes it the view's current camera: the update hooks,
     * which run next, see the camera their frame is drawn with (a light that follows it is lit from there).
     */
    void aim(boolean redraw, double dt) {
        state.drawnWith(cameras.next(redraw, dt), cameras.homeSerial());
    }

    /**
     * Draws a frame of {@code fw x fh} pixels into {@code back}, or into a new slot when it is null or
     * of another size; returns the slot drawn into. Its camera is the one {@link #aim} chose, or the
     * host's when one was set since (an update hook may set it).
     */
    FrameSlot draw(FrameSlot back, ViewSettings settings, int fw, int fh, FreezeGate.Action action) {
        Camera camera = cameras.settled();
        long homeSerial = cameras.homeSerial();
        if (back == null || !back.is(fw, fh)) {
            back = new FrameSlot(fw, fh);
        }
        if (!state.toolsOpen() && state.inspected() < 0) {
            // Nothing can ask for the per-pixel frame until the tools or the inspector open: its 36 bytes a
            // pixel go (they stayed for as long as the view, at the size the tools last had).
            reference = null;
            displacement = null;
        }
        // One consistent snapshot of the scene for every render of this frame; the draws are the slot's
        // own, so that a click on the frame on screen is picked against what that frame drew.
        Scene scene = state.scene();
        if (scene != drawnScene) {
            // A scene replaced: its storage, sized for it, goes now rather than after the trim window, so
            // that the view can load the largest model that fits alone after another.
            renderer.release();
            reference = null;
            displacement = null;
            // The first scene replaces none: no slot holds another's draws, and a still view draws it once.
            settleFrames = drawnScene == null ? 0 : 2;
            drawnScene = scene;
        }
        Scene.Snapshot snapshot = scene.capture();
        DrawnFrame drawn = new DrawnFrame(snapshot, camera, fw, fh, back.draws, pixelScale(fw))
                .withScreenText(scene.screenText());
        Draws draws = back.draws;
        if (!state.toolsOpen() && settings.view() != ViewKind.IMAGE) {
            // The comparison views belong to the developer tools: never shown (nor paid for) without them.
            settings = settings.withView(ViewKind.IMAGE);
        }
        long now = System.nanoTime();
        // Measure only while someone can read the numbers: the developer tools are open.
        // A frame drawn while frozen is always measured: the numbers must describe the frame on screen.
        boolean compareDue = settings.compare() && state.toolsOpen()
                && (action != FreezeGate.Action.RUN || now - lastCompare >= COMPARE_INTERVAL_NANOS);
        long inspected = state.inspected();
        boolean needReference = settings.view() != ViewKind.IMAGE || compareDue || inspected >= 0;
        Framebuffer fb = back.frame;
        // The triangle ids always (picking and the pointer read them: no pick draws again); the UV output
        // only for the comparison and the inspector.
        fb.recordIds(true);
        fb.recordUv(needReference);
        Viewport viewport = new Viewport(fw, fh);
        long compareStart = System.nanoTime();
        double[] paths = null;
        if (needReference) {
            if (reference == null || reference.width() != fw || reference.height() != fh) {
                reference = new Framebuffer(fw, fh);
                reference.recordUv(true);
                displacement = new float[fw * fh];
            }
            RenderSettings shown = settings.render().withBorders(false);
            TimedDraw draw = (mode, into) -> {
                long t0 = System.nanoTime();
                renderer.render(draws, shown.withMode(mode), into);
                return System.nanoTime() - t0;
            };
            // Before this path, so that the overlay and the inspector see this path's pieces.
            paths = drawReference(shown.mode(), compareDue, reference, draw);
        }
        long compareNanos = System.nanoTime() - compareStart;
        // This path last, so that its pieces are the ones the overlay outlines; the overlay comes after
        // the comparison, which measures the rendered image and never the borders.
        RenderSettings render = budget.apply(settings.render(), state.budget());
        // The inspected pixel is probed: the fill notes the line or quad drawn last there.
        renderer.probe(inspected >= 0 ? (int) (inspected >> 32) : -1, (int) inspected);
        back.stats = renderer.render(draws, render.withBorders(false), fb);
        renderer.probe(-1, -1);
        if (paths != null) {
            paths[settings.render().mode().ordinal()] = back.stats.totalNanos() / 1e6;
            state.pathMs(paths, scene);
        }
        long afterThisPath = System.nanoTime();
        frames++;
        back.serial = frames;
        back.camera = camera;
        back.drawn = drawn;
        state.drawnWith(camera, homeSerial);
        back.render = settings.render();
        back.drawnRender = render;
        back.view = settings.view();
        back.splitFraction = settings.splitFraction();
        back.heatScale = settings.heatScale();
        if (compareDue) {
            long t0 = System.nanoTime();
            // The exact displacement: the loop knows the geometry (maps are built per visible triangle).
            TexelToScreen exact = new TexelToScreen(draws, viewport);
            Comparison c = ImageComparison.compare(fw, fh, fb.colour(), fb.uv(), reference.colour(), reference.uv(),
                    exact, displacement);
            compareMs = (System.nanoTime() - t0) / 1e6;
            lastCompare = now;
            // The settings the frame was drawn with (the budget may have chosen the threshold), so that the
            // copied compare command reproduces these numbers.
            state.measurement(new ViewState.Measurement(c, back.serial, camera, settings.withRender(render), fw, fh,
                    System.nanoTime(), snapshot.lights(), snapshot.fog(),
                    ViewState.Measurement.shading(drawn.placed(), AssetScenes.assetOf(scene).map(SceneAsset::mesh)
                            .orElse(null))), scene);
        } else if (settings.view() == ViewKind.DIFFERENCE) {
            // Between measurements the heat map needs only the displacements, at a fraction of the cost.
            ImageComparison.displacements(fw, fh, fb.uv(), reference.uv(),
                    new TexelToScreen(draws, viewport), displacement);
        }
        compareNanos += System.nanoTime() - afterThisPath;
        back.inspection = null;
        back.underMarks = null;
        long t0 = System.nanoTime();
        if (inspected >= 0) {
            int ix = (int) (inspected >> 32);
            int iy = (int) inspected;
            if (ix < fw && iy < fh) {
                back.inspection = inspect(fb, draws, viewport, drawn, settings, ix, iy, true);
                back.underMarks = InspectorPainter.patch(fb.colour(), fw, fh, ix, iy);
            }
        }
        // The pinned pixels' readouts, afresh each frame.
        long[] pins = state.pins();
        java.util.List<PixelInspector.Inspection> read = new java.util.ArrayList<>();
        for (long p : inspected >= 0 ? pins : new long[0]) {
            int px = (int) (p >> 32);
            int py = (int) p;
            if (px < fw && py < fh) {
                read.add(inspect(fb, draws, viewport, drawn, settings, px, py, false));
            }
        }
        back.pins = read.toArray(PixelInspector.Inspection[]::new);
        back.inspectNanos = System.nanoTime() - t0;
        compareStageNanos = compareNanos;
        highlight.apply(fb, draws, drawn.placed(), state.hovered());
        if (settings.view() == ViewKind.DIFFERENCE) {
            back.overlayNanos = 0;
        } else if (settings.render().borders()) {
            // The fallback pieces' magenta outlines come with the others (B), as on the command line, never alone.
            back.overlayNanos = renderer.drawBorders(fb, settings.render().borderStyle(), render.tessellation());
        } else {
            back.overlayNanos = 0;
        }
        if (settings.view() == ViewKind.DIFFERENCE) {
            // The top the legend shows: this frame's worst pixel, unless the user set one.
            back.heatScale = settings.heatTopFitted() ? settings.heatScale().fitted(displacement) : settings.heatScale();
            HeatMap.render(displacement, fb.uv(), reference.uv(), fw, fh, back.heatScale, fb.colour());
        } else if (settings.view() == ViewKind.SPLIT) {
            int divider = (int) Math.round(settings.splitFraction() * fw);
            if (divider < fw) {
                int[] dst = fb.colour();
                int[] src = reference.colour();
                for (int y = 0; y < fh; y++) {
                    System.arraycopy(src, y * fw + divider, dst, y * fw + divider, fw - divider);
                }
            }
        }
        return back;
    }

    /** The inspector's reading of frame pixel (x, y) of this frame (before anything is drawn over the image). */
    private PixelInspector.Inspection inspect(Framebuffer fb, Draws draws, Viewport viewport, DrawnFrame drawn,
                                              ViewSettings settings, int x, int y, boolean probed) {
        return PixelInspector.inspect(renderer.drawn(), fb, reference, new TexelToScreen(draws, viewport), drawn,
                settings.render().filter(), settings.render().mode().divides(),
                settings.render().borders() && settings.view() != ViewKind.DIFFERENCE, x, y, probed);
    }

    /** Draws this frame in one path into a framebuffer; returns the nanoseconds it took. */
    interface TimedDraw {
        long draw(RenderMode mode, Framebuffer into);
    }

    /**
     * Draws the per-pixel path into {@code reference} (which records the UV output the comparison and
     * the inspector read) and, when {@code timeAll}, first times there every other path but the shown
     * one: all are then drawn as the shown path is (after this, into a framebuffer recording the UV
     * output too), so the developer tools' rows of engine time compare like with like. Recording the
     * UV output costs a frame 10-30 %; timed in a frame without it, the other paths looked 10-20 %
     * cheaper than the shown one.
     *
     * @param shown the path the view shows, which the caller draws and times itself
     * @return each path's milliseconds by {@link RenderMode} ordinal (the shown path's left 0), or null
     *         when not {@code timeAll}
     */
    static double[] drawReference(RenderMode shown, boolean timeAll, Framebuffer reference, TimedDraw draw) {
        double[] paths = null;
        if (timeAll) {
            paths = new double[RenderMode.values().length];
            for (RenderMode m : RenderMode.values()) {
                if (m != RenderMode.PERSPECTIVE && m != shown) {
                    paths[m.ordinal()] = draw.draw(m, reference) / 1e6;
                }
            }
        }
        // Last into the reference: the comparison reads the per-pixel frame from it.
        long perspective = draw.draw(RenderMode.PERSPECTIVE, reference);
        if (paths != null) {
            paths[RenderMode.PERSPECTIVE.ordinal()] = perspective / 1e6;
        }
        return paths;
    }
}
