package dev.trisect.scene;

import dev.trisect.math.Viewport;
import dev.trisect.pipeline.Draws;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.internal.DrawnFrame;
import java.awt.image.BufferedImage;
import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * Draws a {@link Scene} seen by a {@link Camera} into a framebuffer, and tells what a pixel of the
 * last frame shows. Owns its worker threads: close it when done (or use {@link #renderImage} for a
 * single picture).
 *
 * <pre>{@code
 * try (SceneRenderer renderer = new SceneRenderer()) {
 *     Framebuffer frame = new Framebuffer(800, 600);
 *     FrameStats stats = renderer.render(scene, camera, RenderSettings.display(), frame);
 *     renderer.pick(400, 300).ifPresent(p -> System.out.println(p.object().name() + " at " + p.point()));
 * }
 * }</pre>
 *
 * <p>All objects go into one frame with one depth buffer; nearer surfaces win. The projection's aspect
 * ratio is the framebuffer's, so the image is never stretched. Methods are synchronized: one frame at
 * a time, and {@link #pick} may be called from another thread (a view's event thread).
 */
public final class SceneRenderer implements AutoCloseable {
    private final FrameRenderer renderer;
    /** The draws of the last frame, kept for {@link #pick}'s redraw. */
    private final Draws draws = new Draws();
    private boolean closed;
    /** What the last frame drew, for {@link #pick}; null before the first frame. */
    private Drawn last;

    /** A renderer using every available processor, up to 256. */
    public SceneRenderer() {
        this(FrameRenderer.defaultThreads());
    }

    /**
     * @param threads threads to render with, 1 to 256 (the calling thread is one of them; the others are
     *                started here)
     * @throws IllegalArgumentException when {@code threads} is below 1 or above 256
     */
    public SceneRenderer(int threads) {
        this.renderer = new FrameRenderer(threads);
    }

    /**
     * Threads this renderer draws with.
     *
     * @return the number of threads, the calling one included
     */
    public int threads() {
        return renderer.threads();
    }

    /**
     * Draws every visible object of {@code scene}, lit by its lights and fogged by its fog, as one
     * {@link Scene#capture()}, into {@code frame},
     * which is cleared to the settings' background first.
     *
     * @param scene    what to draw, as of now
     * @param camera   where from
     * @param settings how (path, filter, borders, background)
     * @param frame    where to; its size gives the projection's aspect
     * @return what the frame did
     * @throws IllegalStateException after {@link #close()}
     * @throws NullPointerException  for a null argument
     */
    public synchronized FrameStats render(Scene scene, Camera camera, RenderSettings settings, Framebuffer frame) {
        checkOpen();
        Objects.requireNonNull(scene, "scene is null");
        Objects.requireNonNull(camera, "camera is null");
        Objects.requireNonNull(settings, "render settings are null: use RenderSettings.display() or defaults()");
        Objects.requireNonNull(frame, "framebuffer is null");
        Drawn d = new Drawn(scene.capture(), camera, settings, frame.width(), frame.height(), draws);
        d.frame.withScreenText(scene.screenText());
        FrameStats stats = renderer.render(draws, settings, frame);
        d.idsFrame = frame.ids() != null ? frame : null;
        d.idsArray = frame.ids();
        d.idsClears = frame.clearCount();
        last = d;
        return stats;
    }

    /**
     * What pixel (x, y) of the last frame drawn shows: the object, its triangle, the 3D point and the
     * texel. It describes the objects as they were drawn, not as they may have moved since. Which
     * triangle the pixel shows is read from the frame's triangle ids; the point, the texture
     * coordinates and the texel then follow from that triangle and the camera alone (see {@link Pick}).
     * When that frame recorded its ids ({@link Framebuffer#recordIds}, or the UV output, which brings
     * them) and nothing has been drawn into its framebuffer since ({@link Framebuffer#clearCount()}),
     * they are read from there; otherwise the frame is drawn once more, recording them, into a
     * framebuffer of its own (the same pixels: drawing is deterministic) — about the cost of one frame,
     * and {@value #REDRAW_BYTES_PER_PIXEL} bytes a pixel of memory (colour, depth and ids), 3 GiB for a
     * 16384x16384 frame. When that does not fit in Java's heap, pick refuses with a message before
     * drawing; a frame drawn with its ids recorded needs nothing more.
     *
     * <p>Only the surfaces that write depth are picked: opaque and alpha-tested triangles (through an
     * alpha-tested cut-out's holes, what is behind). A blended surface ({@link Material.AlphaMode#BLEND},
     * glass) is seen through: the pick is of the surface behind it. Lines (a {@link DrawStyle#WIRE}
     * object's edges included), billboards, labels and screen text are not picked: where they alone
     * cover the pixel, the pick is of what is behind them, or empty.
     *
     * @param x the pixel's column, 0 at the left
     * @param y the pixel's row, 0 at the top
     * @return the pick, or empty where the pixel shows the background, or before the first frame
     * @throws IllegalArgumentException when (x, y) is outside the last frame
     * @throws IllegalStateException    after {@link #close()}, or when the frame must be drawn again for the
     *                                  pick and its framebuffer with ids does not fit in the heap (the
     *                                  message says so and what helps)
     */
    public synchronized Optional<Pick> pick(int x, int y) {
        checkOpen();
        Drawn d = last;
        if (d == null) {
            return Optional.empty();
        }
        if (x < 0 || y < 0 || x >= d.width || y >= d.height) {
            throw new IllegalArgumentException("pixel (" + x + ", " + y + ") is outside the last frame, "
                    + d.width + "x" + d.height);
        }
        // The caller's framebuffer is read only while it still holds that frame: drawn into since
        // (by another renderer, or cleared), it would describe another picture.
        Framebuffer held = d.idsFrame;
        // The same array too: recording switched off and on again gives the framebuffer a new, empty one.
        int[] ids = held != null && held.ids() != null && held.ids() == d.idsArray && held.clearCount() == d.idsClears
                ? held.ids() : null;
        if (ids == null) {
            Framebuffer f = redrawFrame(d.width, d.height);
            renderer.render(d.draws, d.settings.withBorders(false), f);
            d.idsFrame = f;
            d.idsArray = f.ids();
            d.idsClears = f.clearCount();
            ids = f.ids();
        }
        int id = ids[y * d.width + x] - 1;
        return id < 0 ? Optional.empty() : Optional.of(d.frame.pick(id, x, y));
    }

    /** Bytes a pixel of {@link #pick}'s redraw takes: colour, depth and the triangle id, 4 bytes each. */
    static final int REDRAW_BYTES_PER_PIXEL = 12;

    /**
     * A framebuffer recording the triangle ids for {@link #pick}'s redraw, or a refusal naming what it
     * needs when it cannot fit: refused before allocating when it exceeds the heap's maximum, and likewise
     * when the allocation itself runs out (the arrays made are garbage at once).
     */
    private static Framebuffer redrawFrame(int width, int height) {
        long bytes = (long) width * height * REDRAW_BYTES_PER_PIXEL;
        if (bytes >= Runtime.getRuntime().maxMemory()) {
            throw redrawTooLarge(width, height, bytes);
        }
        try {
            Framebuffer f = new Framebuffer(width, height);
            f.recordIds(true);
            return f;
        } catch (OutOfMemoryError e) {
            throw redrawTooLarge(width, height, bytes);
        }
    }

    private static IllegalStateException redrawTooLarge(int width, int height, long bytes) {
        return new IllegalStateException(String.format(java.util.Locale.ROOT, "pick: the last frame (%dx%d) "
                + "recorded no triangle ids, and drawing it again with them needs %.1f MiB (%d bytes a pixel), "
                + "more than Java's heap has room for: record the ids as you draw (Framebuffer.recordIds(true)), "
                + "draw a smaller frame, or give Java more with -Xmx", width, height, bytes / 1048576.0,
                REDRAW_BYTES_PER_PIXEL));
    }

    /**
     * Draws {@code scene} seen by {@code camera} into a new image as a new {@code TrisectView} shows it,
     * with {@link RenderSettings#display()} (trilinear filtering, sky-blue background); the command
     * line's look is {@link RenderSettings#defaults()}, given to the form taking settings.
     *
     * @param scene  what to draw
     * @param camera where from
     * @param width  pixels, 1..{@link Viewport#MAX_SIDE}
     * @param height pixels, 1..{@link Viewport#MAX_SIDE}
     * @return the picture, {@code TYPE_INT_RGB}
     */
    public static BufferedImage renderImage(Scene scene, Camera camera, int width, int height) {
        return renderImage(scene, camera, RenderSettings.display(), width, height);
    }

    /**
     * Draws {@code scene} seen by {@code camera} with {@code settings} into a new image.
     *
     * @param scene    what to draw
     * @param camera   where from
     * @param settings how
     * @param width    pixels, 1..{@link Viewport#MAX_SIDE}
     * @param height   pixels, 1..{@link Viewport#MAX_SIDE}
     * @return the picture, {@code TYPE_INT_RGB}
     */
    public static BufferedImage renderImage(Scene scene, Camera camera, RenderSettings settings, int width,
                                            int height) {
        new Viewport(width, height); // checks the size with its message
        Framebuffer frame = new Framebuffer(width, height);
        try (SceneRenderer r = new SceneRenderer()) {
            r.render(scene, camera, settings, frame);
        }
        return frame.toImage();
    }

    /** Stops the worker threads; further calls throw {@link IllegalStateException}. */
    @Override
    public synchronized void close() {
        closed = true;
        renderer.close();
    }

    private void checkOpen() {
        if (closed) {
            throw new IllegalStateException("this SceneRenderer is closed");
        }
    }

    /** One frame as drawn, with what {@link #pick}'s redraw needs. */
    private static final class Drawn {
        final DrawnFrame frame;
        final RenderSettings settings;
        final int width;
        final int height;
        final Draws draws;
        /** The framebuffer holding this frame's triangle ids, or null. */
        Framebuffer idsFrame;
        /** {@link Framebuffer#clearCount()} of {@link #idsFrame} right after this frame was drawn into it. */
        long idsClears;
        /** The ids array this frame was drawn into. */
        int[] idsArray;

        Drawn(Scene.Snapshot snapshot, Camera camera, RenderSettings settings, int width, int height,
              Draws draws) {
            this.frame = new DrawnFrame(snapshot, camera, width, height, draws);
            this.settings = settings;
            this.width = width;
            this.height = height;
            this.draws = draws;
        }
    }
}
