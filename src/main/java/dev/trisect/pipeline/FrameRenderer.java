package dev.trisect.pipeline;

import dev.trisect.math.Mat4;
import dev.trisect.mesh.Mesh;
import dev.trisect.raster.RowKnots;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.Texture;

/**
 * Draws one frame: transform, cull, clip, tessellate (or project), rasterize, overlay, statistics.
 * This class is the public entry and the order of the stages; each stage is a class of its own
 * (docs/architecture.md has the table): {@link FrameGeometry} (with {@link ClipSpace},
 * {@link ChunkGeometry}, {@link DepthCapSearch}) makes the chunks' screen triangles, {@link BandPass}
 * fills them band by band, {@link Outlines} draws the border overlay, {@link FrameStatsBuilder} makes
 * the statistics, all on the threads of one {@link WorkerPool}.
 *
 * <p>Work is shared out in two ways, neither of which changes a single pixel. Geometry runs over
 * contiguous chunks of the triangle list, each writing its own screen triangles in input order.
 * The frame is then cut into bands of rows; every band takes the chunks in order, so every pixel
 * sees its triangles in input order whatever the number of threads, and the depth test breaks ties
 * the same way each time.
 *
 * <p>All scratch memory is kept from frame to frame: once it has grown to the scene's size, a frame
 * allocates only a few small objects to coordinate threads, nothing per triangle or per pixel.
 * Not thread-safe: one frame at a time. Close it to stop its threads.
 *
 * <p>When anything fails on any of its threads while drawing — an exception, or an error such as
 * {@link OutOfMemoryError} — the frame stops on all threads and the method called rethrows the first
 * failure unchanged (runtime exceptions and errors as themselves), on the calling thread, after all
 * threads have stopped working on it; the renderer's own threads never die of it and the renderer can
 * draw the next frame (see {@link WorkerPool}). A renderer used after {@link #close} throws
 * {@link IllegalStateException}.
 */
public final class FrameRenderer implements AutoCloseable {
    /** Rows per band: small enough to balance threads, large enough to amortize per-band setup. */
    static final int BAND_ROWS = 16;
    /**
     * Frames (render calls) in a row that working storage must have been far larger than they needed
     * before it is given back (see {@link Retention}): the memory of one huge frame goes back after this
     * many ordinary ones.
     */
    public static final int TRIM_FRAMES = Retention.FRAMES;

    private final WorkerPool pool;
    private final FrameGeometry geometry;
    private final BandPass bands;
    private final Outlines outlines;
    private final LinePass lines;
    /**
     * The geometry of the frame last drawn by {@link #render}, which {@link #drawBorders} and
     * {@link #pieceAt} read; null before the first frame, after {@link #coverage} and after a failure.
     */
    private FrameGeometry.Result drawn;
    /** The span path's max error of the frame last drawn by {@link #render}, 0 for the other paths. */
    private double drawnSpanError;
    /** The width of the frame last drawn by {@link #render}, pixels. */
    private int drawnWidth;
    /** The height of the frame last drawn by {@link #render}, pixels. */
    private int drawnHeight;
    /** The one draw of {@link #render(Mesh, Texture[], Mat4, RenderSettings, Framebuffer)}, reused. */
    private final Draws single = new Draws();
    /** Set by {@link #close}: every later call throws instead of reading what the closed renderer kept. */
    private volatile boolean closed;

    /**
     * Most threads a renderer draws with. Each is a platform thread of its own, started at once: an
     * unchecked count (a typo, a size mistaken for a count) would exhaust the process's threads before
     * any frame, so counts beyond it are refused, as the command line's {@code --threads} is.
     */
    public static final int MAX_THREADS = 256;

    /** A renderer using every available processor, up to {@link #MAX_THREADS}. */
    public FrameRenderer() {
        this(defaultThreads());
    }

    /** @param threads threads to render with, 1..{@link #MAX_THREADS} (the calling thread is one of them) */
    public FrameRenderer(int threads) {
        if (threads < 1 || threads > MAX_THREADS) {
            throw new IllegalArgumentException("threads must be between 1 and " + MAX_THREADS + ", got " + threads);
        }
        this.pool = new WorkerPool(threads, "trisect-render");
        this.geometry = new FrameGeometry(threads);
        this.bands = new BandPass(threads);
        this.outlines = new Outlines(threads);
        this.lines = new LinePass(threads);
    }

    /**
     * One thread per available processor, at most {@link #MAX_THREADS}.
     *
     * @return the default thread count
     */
    public static int defaultThreads() {
        return Math.min(MAX_THREADS, Runtime.getRuntime().availableProcessors());
    }

    /** Threads this renderer fills frames with. */
    public int threads() {
        return pool.threads();
    }

    /**
     * Draws {@code mesh} into {@code frame}: one draw (see {@link #render(Draws, RenderSettings, Framebuffer)}).
     *
     * @param textures       the texture of each material of the mesh, by material index
     * @param viewProjection world space to clip space (projection * view), as OpenGL
     * @return what the frame did
     */
    public FrameStats render(Mesh mesh, Texture[] textures, Mat4 viewProjection, RenderSettings settings,
                             Framebuffer frame) {
        single.clear();
        single.add(mesh, textures, viewProjection);
        try {
            return render(single, settings, frame);
        } finally {
            single.clear();
        }
    }

    /**
     * Draws every draw into {@code frame}, one depth buffer for all, after clearing it: each mesh's
     * positions go through that draw's own model-view-projection, so moving one object never touches
     * another's data. The draws' lines come after every triangle (and, with the borders on, after the
     * overlay), depth-tested against them ({@link LinePass}); they leave the UV output as it is. Triangles are numbered across the draws (see {@link Draws}) in the UV output
     * and in {@link #pieceAt}.
     *
     * @return what the frame did ({@code trianglesIn} counts every draw's triangles)
     */
    public FrameStats render(Draws draws, RenderSettings settings, Framebuffer frame) {
        checkOpen();
        long start = System.nanoTime();
        drawn = null;
        outlines.retain();
        FrameGeometry.Result g = geometry.run(draws, settings, frame.width(), frame.height(), pool);
        long geometryDone = System.nanoTime();
        BandPass.Result b = bands.draw(frame, geometry.chunks(), g.chunkCount(), draws.textures(), settings, outlines,
                pool);
        lines.draw(draws, frame, pool);
        long end = System.nanoTime();
        drawn = g;
        drawnSpanError = settings.mode().knots() ? settings.knotError() : 0;
        drawnWidth = frame.width();
        drawnHeight = frame.height();
        return new FrameStatsBuilder(pool.threads(), start)
                .geometry(draws.triangleCount(), geometry.chunks(), g, geometryDone)
                .bands(b, end, settings.borders());
    }

    /**
     * The filled triangle of the last frame drawn by {@link #render} that shows pixel (x, y), for the
     * pixel inspector: see {@link PieceLookup#find}.
     *
     * @return the piece, or null when none holds the pixel
     */
    public PieceInfo pieceAt(int x, int y, int triangle, double depth) {
        checkOpen();
        return PieceLookup.find(geometry.chunks(), drawnChunks(), x, y, triangle, depth);
    }

    /**
     * The piece filled per pixel (the fallback: a sliver, or one a cap stopped short) whose outline
     * lights pixel (x, y) in the last frame drawn by {@link #render} when the borders are drawn, by the
     * overlay's own rules and depth test against {@code depth} (the frame's 1/w there); the last in
     * drawing order when several do. For the pixel inspector: it explains a magenta mark.
     *
     * @return the piece, or null when no fallback piece's outline lights the pixel
     */
    public PieceInfo fallbackOutlineAt(int x, int y, double depth) {
        checkOpen();
        return PieceLookup.fallbackOutline(geometry.chunks(), drawnChunks(), x, y, drawnHeight, depth);
    }

    /**
     * The knots of row y of the filled triangle that shows pixel (x, y) in the last frame drawn by
     * {@link #render}, when that frame took the span path, for the pixel inspector: found as
     * {@link #pieceAt} finds the triangle, placed as the fill placed them.
     *
     * @return the row's knots, or null when the frame was not drawn in the span path or no triangle
     *         holds the pixel
     */
    public RowKnots knotsAt(int x, int y, int triangle, double depth) {
        checkOpen();
        if (drawnSpanError <= 0) {
            return null;
        }
        return PieceLookup.knots(geometry.chunks(), drawnChunks(), x, y, triangle, depth, drawnWidth, drawnSpanError);
    }

    /**
     * Outlines the pieces of the frame last drawn by {@link #render} into {@code frame}, exactly as
     * rendering with borders on would have. Lets a caller measure the image before the overlay covers
     * it (the comparison with another path must never count the overlay), then add the overlay.
     * Valid until the next {@code render} or {@code coverage} call; {@code frame} must be the one rendered.
     * The style colours by split depth (red at {@code tessellation}'s depth cap) or by error bound
     * (yellow at its Max error), and may fade outlines where pieces are dense. A frame of the span path
     * also gets its knot ticks, at the knots that frame's fill placed.
     *
     * @return nanoseconds it took
     * @throws IllegalArgumentException when {@code frame} is not the size of the frame last drawn
     */
    public long drawBorders(Framebuffer frame, BorderStyle style, TessellationSettings tessellation) {
        checkOpen();
        if (drawn != null && (frame.width() != drawnWidth || frame.height() != drawnHeight)) {
            // The pieces are in the drawn frame's pixels: in another frame they would land anywhere.
            throw new IllegalArgumentException("the framebuffer is " + frame.width() + "x" + frame.height()
                    + " but the frame last drawn was " + drawnWidth + "x" + drawnHeight
                    + ": outline the framebuffer that was rendered");
        }
        long start = System.nanoTime();
        outlines.drawAll(frame, geometry.chunks(), drawnChunks(), style, tessellation, drawnSpanError, pool);
        return System.nanoTime() - start;
    }

    /**
     * Counts, per pixel, how many of the frame's filled triangles (pieces, in the tessellated path)
     * cover its centre, ignoring depth: 1 everywhere inside a closed or tiled surface seen from one
     * side means no gaps and no overlaps. For tests and overdraw views.
     *
     * @return {@code width * height} counts, row 0 at the top
     */
    public int[] coverage(Mesh mesh, Texture[] textures, Mat4 viewProjection, RenderSettings settings,
                          int width, int height) {
        checkOpen();
        drawn = null;
        single.clear();
        single.add(mesh, textures, viewProjection);
        try {
            FrameGeometry.Result g = geometry.run(single, settings, width, height, pool);
            return bands.coverage(geometry.chunks(), g.chunkCount(), width, height, pool);
        } finally {
            single.clear();
        }
    }

    private int drawnChunks() {
        return drawn == null ? 0 : drawn.chunkCount();
    }

    /** Triangles the chunks' screen-triangle storage holds room for, for tests of trimming. */
    long retainedTriangleCapacity() {
        return geometry.chunks().retainedTriangleCapacity();
    }

    /** Positions the clip-space arrays hold room for, for tests of trimming. */
    long retainedPositionCapacity() {
        return geometry.clipSpace().capacity();
    }

    /** Outline plans kept (one per chunk outlined lately), for tests of trimming. */
    int retainedOutlinePlans() {
        return outlines.plans();
    }

    /** Stops the renderer's threads; every later call throws {@link IllegalStateException}. */
    @Override
    public void close() {
        closed = true;
        pool.close();
    }

    private void checkOpen() {
        if (closed) {
            throw new IllegalStateException("this FrameRenderer is closed: its threads have stopped");
        }
    }
}
