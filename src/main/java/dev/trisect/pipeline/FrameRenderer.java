package dev.trisect.pipeline;

import dev.trisect.math.Mat4;
import dev.trisect.math.Viewport;
import dev.trisect.mesh.Mesh;
import dev.trisect.raster.BorderOverlay;
import dev.trisect.raster.BorderStyle;
import dev.trisect.raster.Framebuffer;
import dev.trisect.raster.Rasterizer;
import dev.trisect.raster.ScreenTriangles;
import dev.trisect.tessellate.PieceBudget;
import dev.trisect.tessellate.PieceSink;
import dev.trisect.tessellate.TessellationSettings;
import dev.trisect.tessellate.Tessellator;
import dev.trisect.texture.Texture;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Draws one frame: transform, cull, clip, tessellate (or project), rasterize, overlay, statistics.
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
    /** Guard band beyond each side of the viewport, pixels. */
    static final int GUARD_PIXELS = 8192;
    /** Triangles per timing batch inside a chunk. */
    private static final int BATCH = 1024;
    /**
     * Largest chunk of a mesh of up to {@code SMALL_MESH_CHUNK_CAP * MAX_CHUNKS} (32768) triangles. The chunks
     * are set by the triangle count n alone (see {@link #chunkCount} and {@link #chunkSize}):
     * {@code min(MAX_CHUNKS, ceil(n / SMALL_MESH_CHUNK_CAP))} chunks (at least one), each of
     * {@code ceil(n / chunks)} consecutive triangles but the last, which holds the rest. So 1000
     * triangles make two chunks of 500, 32768 make 64 of 512, and 100,000 make 64 of 1563 (the last
     * 1531): past 32768 triangles chunks grow beyond this cap, their count does not.
     *
     * <p>The chunks never depend on the thread count: the border overlay walks an edge two triangles
     * of one chunk share once, which makes the faded and coloured outlines depend on where chunks
     * end, and they must be the same for any thread count ({@code BorderPassTest}). Chunks are many
     * and small because their costs differ widely: in the tessellated path, the few triangles near
     * the camera make most of the pieces, and a chunk holding them alone would leave the other
     * threads idle. Measured at 1920x1080 by the tasks' processor times (before: four chunks per
     * thread of at least 2048 triangles): the largest geometry task of the floor's tessellated frame
     * went from 1.12 to 0.66 ms of 2.45, of the 160k-triangle sphere from 1.25 to 0.29 ms of 6.6.
     */
    private static final int SMALL_MESH_CHUNK_CAP = 512;
    /** Most chunks: enough to balance many threads, few enough that each band's walk over them stays cheap. */
    private static final int MAX_CHUNKS = 64;
    /**
     * Scratch that has been more than this many times larger than a frame needed, for
     * {@link #TRIM_FRAMES} frames in a row, shrinks to twice the need: memory taken by one extreme
     * frame goes back to the collector within about a second, while steady frames allocate nothing.
     */
    static final int TRIM_FACTOR = 4;
    public static final int TRIM_FRAMES = 60;
    /** Storage below this many triangles is never worth trimming. */
    static final int TRIM_FLOOR = 16384;

    private final int threads;
    private final WorkerPool pool;
    private final Worker[] workers;
    private Chunk[] chunks = new Chunk[0];
    private double[] clip = new double[0];
    private boolean[] invalidPosition = new boolean[0];

    /** A renderer using every available processor. */
    public FrameRenderer() {
        this(Runtime.getRuntime().availableProcessors());
    }

    /** @param threads threads to render with, &gt;= 1 (the calling thread is one of them) */
    public FrameRenderer(int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be at least 1, got " + threads);
        }
        this.threads = threads;
        this.workers = new Worker[threads];
        for (int i = 0; i < threads; i++) {
            workers[i] = new Worker();
        }
        this.pool = new WorkerPool(threads, "trisect-render");
    }

    /** Threads this renderer fills frames with. */
    public int threads() {
        return threads;
    }

    /**
     * Draws {@code mesh} into {@code frame}.
     *
     * @param textures       the texture of each material of the mesh, by material index
     * @param viewProjection world space to clip space (projection * view), as OpenGL
     * @return what the frame did
     */
    public FrameStats render(Mesh mesh, Texture[] textures, Mat4 viewProjection, RenderSettings settings,
                             Framebuffer frame) {
        long start = System.nanoTime();
        int bands = bandCount(frame.height());
        int chunkCount = geometry(mesh, textures, viewProjection, settings, frame.width(), frame.height());
        long transformed = start + transformNanos;
        long geometryDone = System.nanoTime();

        boolean perspective = settings.mode() == RenderMode.PERSPECTIVE;
        int width = frame.width();
        int height = frame.height();
        int background = settings.background();
        for (Worker w : workers) {
            w.pixels = 0;
            w.fillNanos = 0;
            w.overlayNanos = 0;
        }
        lastChunkCount = chunkCount;
        // With borders on, the chunks' outlines are prepared by the first tasks of the band pass and
        // each band is outlined right after it is filled, while its rows are in cache. A band waits
        // for all preparations before outlining; they are all taken before any band is, so the
        // wait ends, and it overlaps the preparations' uneven costs with filling.
        boolean borders = settings.borders();
        int prepTasks = borders ? chunkCount : 0;
        if (borders) {
            outlines.resize(chunkCount);
        }
        AtomicInteger prepared = new AtomicInteger();
        BorderStyle style = settings.borderStyle();
        parallel(prepTasks + bands, (w, task) -> {
            long t0 = System.nanoTime();
            if (task < prepTasks) {
                try {
                    outlines.prepare(task, chunks[task].out, style, settings.tessellation(), height);
                } finally {
                    prepared.incrementAndGet();
                }
                w.overlayNanos += System.nanoTime() - t0;
                return;
            }
            int b = task - prepTasks;
            int y0 = b * BAND_ROWS;
            int y1 = Math.min(height, y0 + BAND_ROWS);
            frame.clearRows(y0, y1, background);
            w.rasterizer.filter(settings.filter());
            for (int c = 0; c < chunkCount; c++) {
                Chunk chunk = chunks[c];
                w.pixels += w.rasterizer.fill(frame, chunk.out, chunk.binItems, chunk.binStart[b],
                        chunk.binStart[b + 1], textures, perspective, 0, y0, width, y1);
            }
            w.fillNanos += System.nanoTime() - t0;
            if (borders) {
                // The wait is neither filling nor outlining: it is left out of both measures.
                if (!awaitPrepared(prepared, prepTasks)) {
                    return;
                }
                long t2 = System.nanoTime();
                outlines.drawBand(w.overlay, frame, b, y0, y1);
                w.overlayNanos += System.nanoTime() - t2;
            }
        });
        long end = System.nanoTime();
        // Filling and outlining run interleaved on all threads, so neither has a wall time of its
        // own: the band pass's wall time is shared out in proportion to the time the threads spent
        // on each, an estimate that FrameStats names as such.
        long fillTime = 0;
        long overlayTime = 0;
        for (Worker w : workers) {
            fillTime += w.fillNanos;
            overlayTime += w.overlayNanos;
        }
        long work = fillTime + overlayTime;
        long overlay = !borders || work == 0 ? 0 : Math.round((end - geometryDone) * (double) overlayTime / work);
        long rasterDone = end - overlay;
        return statistics(mesh.triangleCount(), chunkCount, start, transformed, geometryDone, rasterDone, end,
                borders);
    }

    /**
     * The filled triangle of the last frame drawn by {@link #render} that shows pixel (x, y), for the
     * pixel inspector: see {@link PieceLookup#find}.
     *
     * @return the piece, or null when none holds the pixel
     */
    public PieceInfo pieceAt(int x, int y, int triangle, double depth) {
        return PieceLookup.find(chunks, lastChunkCount, x, y, triangle, depth);
    }

    /**
     * Outlines the pieces of the frame last drawn by {@link #render} into {@code frame}, exactly as
     * rendering with borders on would have. Lets a caller measure the image before the overlay covers
     * it (the comparison with another path must never count the overlay), then add the overlay.
     * Valid until the next {@code render} or {@code coverage} call; {@code frame} must be the one rendered.
     * The style colours by split depth (red at {@code tessellation}'s depth cap) or by error bound
     * (yellow at its Max error), and may fade outlines where pieces are dense.
     *
     * @return nanoseconds it took
     */
    public long drawBorders(Framebuffer frame, BorderStyle style, TessellationSettings tessellation) {
        long start = System.nanoTime();
        int height = frame.height();
        int prepTasks = lastChunkCount;
        outlines.resize(prepTasks);
        AtomicInteger prepared = new AtomicInteger();
        // As in render: the preparations first, each band waiting for them all before outlining.
        parallel(prepTasks + bandCount(height), (w, task) -> {
            if (task < prepTasks) {
                try {
                    outlines.prepare(task, chunks[task].out, style, tessellation, height);
                } finally {
                    prepared.incrementAndGet();
                }
                return;
            }
            int y0 = (task - prepTasks) * BAND_ROWS;
            int y1 = Math.min(height, y0 + BAND_ROWS);
            // The frame has long left the cache: fetch the band's rows in order first, which costs
            // less than missing on them at every line pixel.
            w.touched += frame.touchRows(y0, y1);
            if (!awaitPrepared(prepared, prepTasks)) {
                return;
            }
            outlines.drawBand(w.overlay, frame, task - prepTasks, y0, y1);
        });
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
        int chunkCount = geometry(mesh, textures, viewProjection, settings, width, height);
        lastChunkCount = 0;
        int[] counts = new int[width * height];
        int bands = bandCount(height);
        parallel(bands, (w, b) -> {
            int y0 = b * BAND_ROWS;
            int y1 = Math.min(height, y0 + BAND_ROWS);
            for (int c = 0; c < chunkCount; c++) {
                Chunk chunk = chunks[c];
                w.rasterizer.countCoverage(counts, width, chunk.out, chunk.binItems, chunk.binStart[b],
                        chunk.binStart[b + 1], 0, y0, width, y1);
            }
        });
        return counts;
    }

    /**
     * Waits until {@code tasks} outline preparations are done. They are all taken before any band
     * is, by threads that are running them, so this ends; it yields rather than spins, so that on a
     * busy machine a preparing thread that lost its core gets it back sooner.
     *
     * @return true when they are done; false when a task of the pass has failed (the frame is lost)
     */
    private boolean awaitPrepared(AtomicInteger prepared, int tasks) {
        while (prepared.get() < tasks) {
            if (pool.failed()) {
                return false;
            }
            Thread.yield();
        }
        return true;
    }

    /** Chunks a mesh of {@code triangles} triangles is cut into: see {@link #SMALL_MESH_CHUNK_CAP}. */
    static int chunkCount(int triangles) {
        return Math.max(1, Math.min(MAX_CHUNKS, (triangles + SMALL_MESH_CHUNK_CAP - 1) / SMALL_MESH_CHUNK_CAP));
    }

    /** Triangles in each of {@code chunkCount} chunks of {@code triangles} but the last, which holds the rest. */
    static int chunkSize(int triangles, int chunkCount) {
        return (triangles + chunkCount - 1) / chunkCount;
    }

    private static int bandCount(int height) {
        return (height + BAND_ROWS - 1) / BAND_ROWS;
    }

    private long transformNanos;
    /** Shared by the threads' tessellators for one frame. */
    private final PieceBudget pieceBudget = new PieceBudget();
    /** The last frame's piece budget (Long.MAX_VALUE when not tessellated). */
    private long frameBudget;
    /** The depth cap the last frame's budget forced, or -1. */
    private int budgetDepth = -1;
    /** The border overlay's preparation of the chunks. */
    private final Outlines outlines = new Outlines();
    /** Chunks holding the last rendered frame's screen triangles, for {@link #drawBorders}. */
    private int lastChunkCount;

    /** Transforms, culls, clips and tessellates into the chunks, and bins them; returns the chunk count. */
    private int geometry(Mesh mesh, Texture[] textures, Mat4 viewProjection, RenderSettings settings,
                         int width, int height) {
        if (textures.length < mesh.materialCount()) {
            throw new IllegalArgumentException("mesh has " + mesh.materialCount() + " materials but "
                    + textures.length + " textures were given");
        }
        long start = System.nanoTime();
        Viewport viewport = new Viewport(width, height);
        transform(mesh, viewProjection);
        transformNanos = System.nanoTime() - start;
        int bands = bandCount(height);
        int triangles = mesh.triangleCount();
        int chunkCount = chunkCount(triangles);
        ensureChunks(chunkCount);
        int perChunk = chunkSize(triangles, chunkCount);
        double gx = 1 + 2.0 * GUARD_PIXELS / width;
        double gy = 1 + 2.0 * GUARD_PIXELS / height;
        boolean split = settings.mode() == RenderMode.TESSELLATED;
        TessellationSettings t = settings.tessellation();
        long limit = split ? t.framePieceBudget((long) width * height, triangles) : Long.MAX_VALUE;
        Attempt attempt = (depth, pieces) -> {
            pieceBudget.reset(pieces);
            RenderSettings s = depth == t.maxDepth() ? settings : settings.withTessellation(t.withMaxDepth(depth));
            parallel(chunkCount, (w, c) -> {
                int from = Math.min(triangles, c * perChunk);
                int to = Math.min(triangles, from + perChunk);
                chunks[c].geometry(w, mesh, textures, clip, invalidPosition, from, to, s, viewport, gx, gy, split,
                        pieceBudget);
            });
            return !pieceBudget.exceeded();
        };
        budgetDepth = fitBudget(attempt, t.maxDepth(), limit);
        frameBudget = limit;
        parallel(chunkCount, (w, c) -> {
            chunks[c].bin(bands, height);
            chunks[c].trimIfOversized();
        });
        return chunkCount;
    }

    /** One try at the frame's geometry with edge levels capped at {@code depth}; true if within {@code pieces}. */
    @FunctionalInterface
    private interface Attempt {
        boolean run(int depth, long pieces);
    }

    /**
     * Runs the geometry at the configured depth cap and, if the frame's pieces exceed its budget,
     * searches for the deepest cap at which they fit, leaving that attempt's geometry in the chunks:
     * first the cap one below (a frame just over its budget costs two attempts), then bisection
     * between 0 and that. Lowering the level cap is crack-free (it is per edge) and the pieces it
     * stops short of the policy are filled per pixel, so the bound holds. Each attempt is cut off at
     * about the budget, and there are at most log2(maxDepth) + 3 of them; each verdict is
     * thread-count-independent (see {@link PieceBudget}), so the chosen cap is too. Depth 0 (no
     * splitting) is accepted whatever its count.
     *
     * @return the depth cap the budget forced, or -1 if the configured one fit
     */
    private static int fitBudget(Attempt attempt, int maxDepth, long limit) {
        if (attempt.run(maxDepth, limit)) {
            return -1;
        }
        if (maxDepth > 0 && attempt.run(maxDepth - 1, limit)) {
            return maxDepth - 1;
        }
        // Depth 0 counts as fitting even when it does not: the triangles are the least a frame can be.
        int fits = 0;
        int fails = Math.max(0, maxDepth - 1);
        boolean lastRunFits = false;
        while (fails - fits > 1) {
            int mid = (fits + fails) >>> 1;
            lastRunFits = attempt.run(mid, limit);
            if (lastRunFits) {
                fits = mid;
            } else {
                fails = mid;
            }
        }
        if (!lastRunFits) {
            // The last attempt was over budget: redo the deepest cap that fit.
            attempt.run(fits, Long.MAX_VALUE);
        }
        return fits;
    }

    private FrameStats statistics(int triangles, int chunkCount, long start, long transformed, long geometryDone,
                                  long rasterDone, long end, boolean bandTimesEstimated) {
        long back = 0;
        long frustum = 0;
        long degenerate = 0;
        long invalid = 0;
        long clipped = 0;
        long pieces = 0;
        long offScreen = 0;
        long splits = 0;
        int deepest = 0;
        long caps = 0;
        long fallback = 0;
        long clipCpu = 0;
        long tessCpu = 0;
        for (int c = 0; c < chunkCount; c++) {
            Chunk k = chunks[c];
            back += k.culledBack;
            frustum += k.culledFrustum;
            degenerate += k.culledDegenerate;
            invalid += k.invalid;
            clipped += k.clipped;
            pieces += k.pieces;
            offScreen += k.offScreen;
            splits += k.splits;
            deepest = Math.max(deepest, k.deepest);
            caps += k.caps;
            fallback += k.fallback;
            clipCpu += k.clipNanos;
            tessCpu += k.tessellateNanos;
        }
        long pixels = 0;
        for (Worker w : workers) {
            pixels += w.pixels;
        }
        // Clipping and tessellation run interleaved on all threads; their wall time is shared out in
        // proportion to the processor time each took.
        long geometryWall = geometryDone - transformed;
        long cpu = clipCpu + tessCpu;
        long clipWall = cpu == 0 ? 0 : Math.round(geometryWall * (double) clipCpu / cpu);
        return new FrameStats(triangles, back, frustum, degenerate, invalid, clipped, pieces, offScreen, splits,
                deepest,
                caps, fallback, frameBudget == Long.MAX_VALUE ? 0 : frameBudget, budgetDepth, pixels, threads, transformed - start, clipWall, geometryWall - clipWall,
                rasterDone - geometryDone, end - rasterDone, bandTimesEstimated, end - start);
    }

    private void transform(Mesh mesh, Mat4 viewProjection) {
        int n = mesh.positionCount();
        if (clip.length < 4 * n) {
            clip = new double[4 * n];
            invalidPosition = new boolean[n];
        }
        float[] p = mesh.positions();
        int parts = n < 65536 ? 1 : threads;
        int per = (n + parts - 1) / parts;
        parallel(parts, (w, part) -> {
            int to = Math.min(n, (part + 1) * per);
            for (int i = part * per; i < to; i++) {
                viewProjection.transformPoint(p[3 * i], p[3 * i + 1], p[3 * i + 2], clip, 4 * i);
                invalidPosition[i] = !(Double.isFinite(clip[4 * i]) && Double.isFinite(clip[4 * i + 1])
                        && Double.isFinite(clip[4 * i + 2]) && Double.isFinite(clip[4 * i + 3]));
            }
        });
    }

    /** Triangles the chunks' screen-triangle storage holds room for, for tests of trimming. */
    long retainedTriangleCapacity() {
        long total = 0;
        for (Chunk c : chunks) {
            total += c.out.capacity() + c.binItems.length / 2;
        }
        return total;
    }

    private void ensureChunks(int count) {
        if (chunks.length < count) {
            Chunk[] grown = Arrays.copyOf(chunks, count);
            for (int i = chunks.length; i < count; i++) {
                grown[i] = new Chunk();
            }
            chunks = grown;
        }
    }

    /** A job over an index, run with the scratch of whichever thread takes it. */
    @FunctionalInterface
    private interface Job {
        void run(Worker worker, int index);
    }

    /** Runs {@code job} for indices 0..count-1 on all threads, each index once; see {@link WorkerPool#run}. */
    private void parallel(int count, Job job) {
        pool.run(count, (thread, index) -> job.run(workers[thread], index));
    }

    @Override
    public void close() {
        pool.close();
    }

    /** Per-thread scratch. */
    static final class Worker {
        final Clipper clipper = new Clipper();
        final Tessellator tessellator = new Tessellator();
        final Rasterizer rasterizer = new Rasterizer();
        final BorderOverlay overlay = new BorderOverlay();
        /** The three corners of the triangle being culled and clipped. */
        final double[] cornerScratch = new double[3 * Clipper.STRIDE];
        /** Clipped triangles of the current batch: 3 vertices of Clipper.STRIDE doubles each. */
        double[] batch = new double[3 * Clipper.STRIDE * BATCH];
        int[] batchIds = new int[BATCH];
        int[] batchMaterials = new int[BATCH];
        long pixels;
        /**
         * Nanoseconds this thread spent this frame clearing and filling bands, and on the border
         * overlay (preparing chunks' outlines and outlining bands, not waiting for the preparations).
         */
        long fillNanos;
        long overlayNanos;
        /** Keeps what {@link Framebuffer#touchRows} read. */
        long touched;
    }

    /** One contiguous range of input triangles: its screen triangles, their bins and its counters. */
    static final class Chunk implements PieceSink {
        /** The tessellator feeding {@link #piece} during {@link #geometry}. */
        private Tessellator currentTessellator;
        final ScreenTriangles out = new ScreenTriangles();
        int[] binStart = new int[1];
        int[] binItems = new int[0];
        private int[] firstBand = new int[0];
        private int[] lastBand = new int[0];
        long culledBack;
        long culledFrustum;
        long culledDegenerate;
        long invalid;
        long clipped;
        long pieces;
        long offScreen;
        long splits;
        int deepest;
        long caps;
        long fallback;
        long clipNanos;
        long tessellateNanos;
        private int currentId;
        private int currentMaterial;
        private int oversizedFrames;
        /** Band-list entries the last frame used. */
        private int lastBinItems;

        /** Gives back storage that has long been far larger than frames need (see TRIM_FACTOR). */
        void trimIfOversized() {
            int need = Math.max(out.count(), TRIM_FLOOR / TRIM_FACTOR);
            boolean oversized = out.capacity() > TRIM_FLOOR && out.capacity() > TRIM_FACTOR * need;
            oversizedFrames = oversized ? oversizedFrames + 1 : 0;
            if (oversizedFrames >= TRIM_FRAMES) {
                oversizedFrames = 0;
                out.shrinkTo(2 * need);
                binItems = new int[Math.min(binItems.length, Math.max(2 * lastBinItems, 2 * need))];
                firstBand = new int[Math.min(firstBand.length, 2 * need)];
                lastBand = new int[firstBand.length];
            }
        }

        void geometry(Worker w, Mesh mesh, Texture[] textures, double[] clip, boolean[] invalidPosition,
                      int from, int to, RenderSettings settings, Viewport viewport, double gx, double gy,
                      boolean split, PieceBudget budget) {
            out.clear();
            culledBack = culledFrustum = culledDegenerate = invalid = clipped = 0;
            clipNanos = tessellateNanos = 0;
            Tessellator tess = w.tessellator;
            currentTessellator = tess;
            tess.configure(viewport, settings.tessellation());
            tess.budget(budget);
            tess.resetStatistics();
            w.clipper.guardBand(gx, gy);
            boolean cullBack = settings.cull() == CullMode.BACK;
            // An attempt over budget is thrown away: stop as soon as it is known.
            for (int batchStart = from; batchStart < to && !budget.exceeded(); batchStart += BATCH) {
                int batchEnd = Math.min(to, batchStart + BATCH);
                long t0 = System.nanoTime();
                int n = cullAndClip(w, mesh, textures, clip, invalidPosition, batchStart, batchEnd, cullBack);
                long t1 = System.nanoTime();
                double[] b = w.batch;
                int stride = 3 * Clipper.STRIDE;
                for (int i = 0; i < n; i++) {
                    currentId = w.batchIds[i];
                    currentMaterial = w.batchMaterials[i];
                    int o = i * stride;
                    tess.process(b, o, o + Clipper.STRIDE, o + 2 * Clipper.STRIDE, split, this);
                }
                long t2 = System.nanoTime();
                clipNanos += t1 - t0;
                tessellateNanos += t2 - t1;
            }
            pieces = tess.pieces();
            offScreen = tess.culledOffScreen();
            splits = tess.splits();
            deepest = tess.deepestLevel();
            caps = tess.capsReached();
            fallback = tess.fallbackPieces();
        }

        /**
         * Culls and clips input triangles [from, to) into the worker's batch as triangles in clip
         * space with texel coordinates; returns how many.
         */
        private int cullAndClip(Worker w, Mesh mesh, Texture[] textures, double[] clip, boolean[] invalidPosition,
                                int from, int to, boolean cullBack) {
            int[] corners = mesh.cornerPositions();
            int[] cornerUvs = mesh.cornerUvs();
            int[] materials = mesh.triangleMaterials();
            float[] uvs = mesh.uvs();
            Clipper clipper = w.clipper;
            int count = 0;
            double[] corner = w.cornerScratch;
            for (int t = from; t < to; t++) {
                int c = 3 * t;
                int p0 = corners[c];
                int p1 = corners[c + 1];
                int p2 = corners[c + 2];
                int material = materials[t];
                Texture tex = textures[material];
                if (invalidPosition[p0] || invalidPosition[p1] || invalidPosition[p2]
                        || !loadCorner(corner, 0, clip, p0, uvs, cornerUvs[c], tex)
                        || !loadCorner(corner, Clipper.STRIDE, clip, p1, uvs, cornerUvs[c + 1], tex)
                        || !loadCorner(corner, 2 * Clipper.STRIDE, clip, p2, uvs, cornerUvs[c + 2], tex)) {
                    invalid++;
                    continue;
                }
                int f0 = Clipper.frustumCode(corner[0], corner[1], corner[2], corner[3]);
                int f1 = Clipper.frustumCode(corner[6], corner[7], corner[8], corner[9]);
                int f2 = Clipper.frustumCode(corner[12], corner[13], corner[14], corner[15]);
                if ((f0 & f1 & f2) != 0) {
                    culledFrustum++;
                    continue;
                }
                // Facing from the homogeneous determinant of (x, y, w): its sign is the projected
                // winding for w > 0 and stays right for triangles crossing the eye plane.
                double det = determinant(corner);
                if (det == 0) {
                    culledDegenerate++;
                    continue;
                }
                if (cullBack && det < 0) {
                    culledBack++;
                    continue;
                }
                int g = clipper.clipCode(corner[0], corner[1], corner[2], corner[3])
                        | clipper.clipCode(corner[6], corner[7], corner[8], corner[9])
                        | clipper.clipCode(corner[12], corner[13], corner[14], corner[15]);
                if (g == 0) {
                    count = append(w, count, corner, 0, Clipper.STRIDE, 2 * Clipper.STRIDE, t, material);
                    continue;
                }
                clipped++;
                int n = clipper.clip(corner, 0, Clipper.STRIDE, 2 * Clipper.STRIDE, g);
                if (n == 0) {
                    culledFrustum++;
                    continue;
                }
                double[] poly = clipper.vertices();
                for (int k = 1; k + 1 < n; k++) {
                    count = append(w, count, poly, 0, k * Clipper.STRIDE, (k + 1) * Clipper.STRIDE, t, material);
                }
            }
            return count;
        }

        private static boolean loadCorner(double[] dst, int o, double[] clip, int p, float[] uvs, int uvIndex,
                                          Texture tex) {
            System.arraycopy(clip, 4 * p, dst, o, 4);
            double u = 0;
            double v = 0;
            if (uvIndex >= 0) {
                u = uvs[2 * uvIndex];
                v = uvs[2 * uvIndex + 1];
            }
            dst[o + 4] = u * tex.width();
            dst[o + 5] = v * tex.height();
            return Double.isFinite(dst[o + 4]) && Double.isFinite(dst[o + 5]);
        }

        private static double determinant(double[] c) {
            double x0 = c[0];
            double y0 = c[1];
            double w0 = c[3];
            double x1 = c[6];
            double y1 = c[7];
            double w1 = c[9];
            double x2 = c[12];
            double y2 = c[13];
            double w2 = c[15];
            return x0 * (y1 * w2 - y2 * w1) - y0 * (x1 * w2 - x2 * w1) + w0 * (x1 * y2 - x2 * y1);
        }

        private static int append(Worker w, int count, double[] src, int a, int b, int c, int id, int material) {
            int stride = 3 * Clipper.STRIDE;
            if ((count + 1) * stride > w.batch.length) {
                w.batch = Arrays.copyOf(w.batch, w.batch.length * 2);
                w.batchIds = Arrays.copyOf(w.batchIds, w.batchIds.length * 2);
                w.batchMaterials = Arrays.copyOf(w.batchMaterials, w.batchMaterials.length * 2);
            }
            int o = count * stride;
            System.arraycopy(src, a, w.batch, o, Clipper.STRIDE);
            System.arraycopy(src, b, w.batch, o + Clipper.STRIDE, Clipper.STRIDE);
            System.arraycopy(src, c, w.batch, o + 2 * Clipper.STRIDE, Clipper.STRIDE);
            w.batchIds[count] = id;
            w.batchMaterials[count] = material;
            return count + 1;
        }

        @Override
        public void piece(double[] v, int a, int b, int c, boolean fallback) {
            // Tessellator vertex layout: clip x, y, z, w, s, t, screen x, screen y.
            out.add(v[a + 6], v[a + 7], 1 / v[a + 3], v[a + 4], v[a + 5],
                    v[b + 6], v[b + 7], 1 / v[b + 3], v[b + 4], v[b + 5],
                    v[c + 6], v[c + 7], 1 / v[c + 3], v[c + 4], v[c + 5],
                    currentId, currentMaterial, fallback);
            out.levelOfLast(currentTessellator.pieceLevel());
        }

        /** Sorts this chunk's screen triangles into bands of rows, keeping their order within a band. */
        void bin(int bands, int height) {
            int n = out.count();
            if (binStart.length < bands + 1) {
                binStart = new int[bands + 1];
            }
            if (firstBand.length < n) {
                firstBand = new int[Math.max(n, 2 * firstBand.length)];
                lastBand = new int[firstBand.length];
            }
            Arrays.fill(binStart, 0, bands + 1, 0);
            int total = 0;
            for (int i = 0; i < n; i++) {
                int r0 = Math.max(0, out.firstRow(i));
                int r1 = Math.min(height, out.endRow(i));
                if (r0 >= r1) {
                    firstBand[i] = 1;
                    lastBand[i] = 0;
                    continue;
                }
                int b0 = r0 / BAND_ROWS;
                int b1 = (r1 - 1) / BAND_ROWS;
                firstBand[i] = b0;
                lastBand[i] = b1;
                for (int b = b0; b <= b1; b++) {
                    binStart[b + 1]++;
                }
                total += b1 - b0 + 1;
            }
            for (int b = 0; b < bands; b++) {
                binStart[b + 1] += binStart[b];
            }
            if (binItems.length < total) {
                binItems = new int[Math.max(total, 2 * binItems.length)];
            }
            lastBinItems = total;
            // Fill each band's list in triangle order, using binStart as moving cursors, then restore.
            for (int i = 0; i < n; i++) {
                for (int b = firstBand[i]; b <= lastBand[i]; b++) {
                    binItems[binStart[b]++] = i;
                }
            }
            for (int b = bands; b > 0; b--) {
                binStart[b] = binStart[b - 1];
            }
            binStart[0] = 0;
        }
    }
}
