package dev.trisect.pipeline;

import dev.trisect.math.Mat4;
import dev.trisect.mesh.Mesh;
import dev.trisect.raster.Commands;
import dev.trisect.raster.LitTextures;
import dev.trisect.render.BorderStyle;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.TessellationSettings;
import dev.trisect.texture.Texture;
import java.util.List;

/**
 * Draws one frame: transform, cull, clip, tessellate (or project), rasterize, overlay, statistics.
 * This class is the public entry and the list of the frame's {@link FramePass passes}, run in order;
 * each is a class of its own (docs/architecture.md has the table): {@link FrameGeometry} (with
 * {@link ClipSpace}, {@link ChunkGeometry}, {@link DepthCapSearch}) makes the chunks' screen
 * triangles, {@link BandPass} fills them band by band, and with the borders on {@link Outlines} draws
 * the border overlay on each band as it is filled, {@link LineGeometry} sets up the lines that each band draws over its filled
 * frame, {@link QuadGeometry} sets up the billboards, labels and screen text that each band draws last; {@link FrameStatsBuilder} makes the statistics, all
 * on the threads of one {@link WorkerPool}. What the frame drew is kept as a {@link FrameRecord}
 * ({@link #drawn()}), which answers the pixel inspector's questions until the next frame.
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
    private final LineGeometry lines;
    private final QuadGeometry quads;
    /** Lit copies of textures, kept from frame to frame (rule: {@link LitTextures}). */
    private final LitTextures lit;
    /** Whether frames draw from {@link #lit} ({@link #cacheLitTextures}). */
    private volatile boolean litOn = true;
    /**
     * The frame's passes, in the order they run: the geometry, the lines' geometry, the fill, the quads
     * (see {@link FramePass}).
     */
    private final List<FramePass> passes;
    /**
     * What the frame last drawn by {@link #render} (or laid out by {@link #coverage}) drew, which
     * {@link #drawBorders} and the inspector's questions read; null before the first frame and after
     * a failure.
     */
    private FrameRecord drawn;
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

    /** The pixel {@link #probe} notes the last line or quad of, or -1. */
    private volatile int probeX = -1;
    private volatile int probeY = -1;

    /** A renderer using every available processor, up to {@link #MAX_THREADS}. */
    public FrameRenderer() {
        this(defaultThreads());
    }

    /** @param threads threads to render with, 1..{@link #MAX_THREADS} (the calling thread is one of them) */
    public FrameRenderer(int threads) {
        this(threads, List.of());
    }

    /**
     * A renderer whose frames run {@code later} after the fill, in order (a pass being tried out, or
     * a test's probe): the list of passes with more entries.
     */
    FrameRenderer(int threads, List<FramePass> later) {
        if (threads < 1 || threads > MAX_THREADS) {
            throw new IllegalArgumentException("threads must be between 1 and " + MAX_THREADS + ", got " + threads);
        }
        this.pool = new WorkerPool(threads, "trisect-render");
        this.geometry = new FrameGeometry(threads);
        this.bands = new BandPass(threads);
        this.outlines = new Outlines(threads);
        this.lines = new LineGeometry();
        this.quads = new QuadGeometry();
        this.lit = new LitTextures(threads, LitTextures.DEFAULT_BUDGET);
        List<FramePass> all = new java.util.ArrayList<>(List.of(this::geometryPass, this::setUpPass, this::fillPass));
        all.addAll(later);
        this.passes = List.copyOf(all);
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
     * overlay), depth-tested against them ({@link LineGeometry}), and the quads after the lines
     * ({@link QuadGeometry}); neither touches the UV output.
     * Triangles are numbered across the draws (see {@link Draws}) in the UV output and in
     * {@link FrameRecord#pieceAt}.
     *
     * @return what the frame did ({@code trianglesIn} counts every draw's triangles)
     */
    public FrameStats render(Draws draws, RenderSettings settings, Framebuffer frame) {
        checkOpen();
        long start = System.nanoTime();
        drawn = null;
        outlines.retain();
        FrameJob job = new FrameJob(draws, settings, frame, pool, geometry.chunks(), start);
        for (FramePass pass : passes) {
            pass.run(job);
        }
        drawn = record(job.chunkCount(), frame.width(), frame.height(), settings);
        return new FrameStatsBuilder(pool.threads(), job.start)
                .geometry(draws.triangleCount(), job.chunks, job.geometry, job.geometryDone)
                .bands(job.bands, job.bandsDone, settings.borders(), job.lines, draws.segmentCount(), job.quads);
    }

    /** The geometry pass: the chunks' screen triangles. */
    private void geometryPass(FrameJob job) {
        job.geometry = geometry.run(job.draws, job.settings, job.frame.width(), job.frame.height(), job.pool);
        job.geometryDone = System.nanoTime();
    }

    /**
     * The fill pass: every band cleared and filled, fogged (its lines drawn before the fog, which fogs
     * them as OpenGL does; the quads fog their own fragments, see {@link QuadGeometry}), outlined right after when the borders are on, and
     * its lines and quads drawn.
     */
    private void fillPass(FrameJob job) {
        int w = job.frame.width();
        bands.probe(probeX >= 0 && probeX < w && probeY >= 0 && probeY < job.frame.height() ? probeY * w + probeX : -1);
        LitTextures cache = litOn ? lit : null;
        if (cache != null) {
            cache.begin(job.draws.textures());
        } else {
            lit.clear();
        }
        job.bands = bands.draw(job.frame, job.chunks, job.chunkCount(), job.draws.textures(), job.draws.states(),
                cache, job.settings, job.draws.fogPass(), outlines, new Commands[] {lines.commands(), quads.commands()}, 1,
                job.pool);
        if (cache != null) {
            cache.end();
        }
        job.bandsDone = System.nanoTime();
    }

    /**
     * Whether the following frames draw triangles of one colour from lit copies of their textures
     * ({@link LitTextures}; on until set): the same pixels either way, for measuring what the copies
     * save. Turned off, the copies kept are dropped by the next frame. Any thread may call it.
     */
    public void cacheLitTextures(boolean on) {
        checkOpen();
        litOn = on;
    }

    /** The renderer's lit copies of textures: how many it keeps, their bytes, the last frame's hits. */
    public LitTextures litTextures() {
        return lit;
    }

    /**
     * The set-up of what comes after the triangles: the draws' segments clipped, set up and binned
     * ({@link LineGeometry}), then their quads ({@link QuadGeometry}), for the fill to draw per band.
     */
    private void setUpPass(FrameJob job) {
        job.lines = lines.setUp(job.draws, job.frame.width(), job.frame.height());
        job.quads = quads.setUp(job.draws, job.frame.width(), job.frame.height());
    }

    private FrameRecord record(int chunkCount, int width, int height, RenderSettings settings) {
        return new FrameRecord(this, geometry.chunks(), chunkCount, width, height,
                settings.mode().knots() ? settings.knotError() : 0, probed());
    }

    /**
     * Notes, in the frames drawn from now on, which line segment or quad is drawn last at frame pixel
     * (x, y), over the triangles ({@link FrameRecord#probed}); for the pixel inspector. Costs a branch per
     * line or quad command of that pixel's band.
     *
     * @param x frame column, or -1 to stop noting
     * @param y frame row (0 at the top)
     */
    public void probe(int x, int y) {
        probeX = x;
        probeY = y;
    }

    /** What the probe found in the frame just drawn: {kind, ...} as {@link FrameRecord#probed}, or null. */
    private int[] probed() {
        int list = bands.probeList();
        if (list < 0) {
            return null;
        }
        Commands c = list == 0 ? lines.commands() : quads.commands();
        int command = c.command(bands.probeCommand());
        int ref = Commands.ref(command);
        if (Commands.kind(command) == Commands.LINE) {
            int[] o = lines.origin(ref);
            return new int[] {Commands.LINE, o[0], o[1]};
        }
        return new int[] {Commands.QUAD, ref};
    }

    /**
     * What the frame last drawn by {@link #render} drew, for the questions asked after it (which piece
     * shows a pixel, whose outline marks it, the knots of its row, the coverage); it answers until this
     * renderer draws again.
     *
     * @return the record, or null before the first frame and after a frame that failed
     * @throws IllegalStateException when the renderer is closed
     */
    public FrameRecord drawn() {
        checkOpen();
        return drawn;
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
        if (drawn != null && (frame.width() != drawn.width() || frame.height() != drawn.height())) {
            // The pieces are in the drawn frame's pixels: in another frame they would land anywhere.
            throw new IllegalArgumentException("the framebuffer is " + frame.width() + "x" + frame.height()
                    + " but the frame last drawn was " + drawn.width() + "x" + drawn.height()
                    + ": outline the framebuffer that was rendered");
        }
        long start = System.nanoTime();
        outlines.drawAll(frame, geometry.chunks(), drawn == null ? 0 : drawn.chunkCount(), style, tessellation,
                drawn == null ? 0 : drawn.knotError(), pool);
        return System.nanoTime() - start;
    }

    /**
     * Lays out {@code mesh} as a frame of {@code width x height} would (the geometry pass alone, nothing
     * filled) and counts, per pixel, how many of its filled triangles cover the pixel's centre: the
     * {@link FrameRecord#coverage} of that layout, which becomes {@link #drawn()}. For tests and
     * overdraw views.
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
            drawn = record(g.chunkCount(), width, height, settings);
            return drawn.coverage();
        } finally {
            single.clear();
        }
    }

    /** {@link FrameRecord#coverage}, on this renderer's threads. */
    int[] coverage(Chunks chunks, int chunkCount, int width, int height) {
        return bands.coverage(chunks, chunkCount, width, height, pool);
    }

    /** Throws unless {@code frame} is what this renderer drew last and the renderer is open. */
    void checkCurrent(FrameRecord frame) {
        checkOpen();
        if (frame != drawn) {
            throw new IllegalStateException("this record is of an earlier frame: the renderer has drawn since "
                    + "(ask the record of the frame last drawn: FrameRenderer.drawn())");
        }
    }

    /**
     * Gives back every working buffer now — the chunks with their screen triangles, split trees and
     * bands, the clip-space positions, the outline plans — instead of after the retention policy's
     * frames ({@link #TRIM_FRAMES}); they grow again with the next frame. For when the scene is replaced:
     * a view then holds the old scene's storage no longer than the new one takes to load. The last
     * frame's pieces go too: {@link #pieceAt} and the like answer as before the first frame, and
     * {@link #drawBorders} outlines nothing; the lit copies of textures go as well.
     */
    public void release() {
        checkOpen();
        drawn = null;
        geometry.release();
        outlines.release();
        lit.clear();
    }

    /**
     * Triangles the chunks' screen-triangle storage holds room for: what the renderer keeps for the
     * scenes it drew, for tests and diagnostics of trimming.
     *
     * @return room for screen triangles, in triangles
     */
    public long retainedTriangleCapacity() {
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
