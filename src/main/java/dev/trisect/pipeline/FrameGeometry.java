package dev.trisect.pipeline;

import dev.trisect.math.Viewport;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.TessellationSettings;
import dev.trisect.tessellate.PieceBudget;
import dev.trisect.tessellate.VertexLayout;

/**
 * The geometry half of a frame, up to what the fill reads: transform the positions
 * ({@link ClipSpace}), light the vertices when a draw is lit ({@link VertexColours}), cull, clip and tessellate or project every chunk of triangles on all threads
 * ({@link ChunkGeometry}) within the frame's piece budget ({@link DepthCapSearch}), and bin each
 * chunk's commands ({@link Chunk#commands}) into bands of {@link FrameRenderer#BAND_ROWS} rows. The chunks
 * ({@link #chunks()}) hold the result until the next frame. Not thread-safe: one frame at a time.
 */
final class FrameGeometry {
    /**
     * What one frame's geometry made.
     *
     * @param chunkCount     chunks holding the frame's screen triangles, 0.. in {@link #chunks()}
     * @param transformNanos wall time of the transform
     * @param pieceBudget    the frame's piece budget (0 outside the tessellated path)
     * @param budgetDepth    the depth cap the budget forced, or -1
     */
    record Result(int chunkCount, long transformNanos, long pieceBudget, int budgetDepth) {
    }

    /** The layout of a lit frame: s, t, then the lit colour r, g, b (0..1) in varyings 2..4. */
    static final VertexLayout LIT_LAYOUT = VertexLayout.of(5);
    /**
     * The layout of a lit frame without a smooth material: s, t, and the triangle's one colour as one
     * flat value ({@link dev.trisect.raster.PixelState#flatColour}: r, g, b packed), once per triangle
     * instead of in each corner, clipped and split never.
     */
    static final VertexLayout FLAT_LIT_LAYOUT = VertexLayout.of(2, 1);

    private final ClipSpace clipSpace = new ClipSpace();
    private final VertexColours vertexColours = new VertexColours();
    private final Chunks chunks = new Chunks();
    private final ChunkGeometry chunkGeometry;
    /** Shared by the threads' tessellators for one attempt. */
    private final PieceBudget pieceBudget = new PieceBudget();

    /** @param threads the threads of the pool that will run it */
    FrameGeometry(int threads) {
        chunkGeometry = new ChunkGeometry(threads);
    }

    /** Drops the chunks and the clip-space positions with all their storage (see {@link FrameRenderer#release}). */
    void release() {
        clipSpace.release();
        chunks.release();
    }

    /** The clip-space positions of the last {@link #run}. */
    ClipSpace clipSpace() {
        return clipSpace;
    }

    /** The chunks the last {@link #run} filled. */
    Chunks chunks() {
        return chunks;
    }

    /**
     * Makes the screen triangles of the draws, each seen through its own model-view-projection, in a
     * frame of {@code width x height} pixels, binned into bands. The chunks cut the frame's triangle
     * numbering (across all draws) exactly as they cut one mesh's.
     */
    Result run(Draws draws, RenderSettings settings, int width, int height, WorkerPool pool) {
        long start = System.nanoTime();
        Viewport viewport = new Viewport(width, height);
        clipSpace.transform(draws, pool);
        vertexColours.compute(draws, pool);
        // Frames with a lit (or otherwise modulated) material carry each corner's colour r, g, b as
        // varyings 2..4, or each triangle's when no lit material is smooth (every triangle has one
        // colour then); the others keep the textured layout.
        VertexLayout layout = !draws.carriesColour() ? VertexLayout.TEXTURED
                : draws.anySmooth() ? LIT_LAYOUT : FLAT_LIT_LAYOUT;
        VertexColours colours = vertexColours.lit() ? vertexColours : null;
        long transformNanos = System.nanoTime() - start;
        int triangles = draws.triangleCount();
        int chunkCount = Chunks.count(triangles);
        chunks.ensure(chunkCount);
        int perChunk = Chunks.size(triangles, chunkCount);
        double gx = 1 + 2.0 * ChunkGeometry.GUARD_PIXELS / width;
        double gy = 1 + 2.0 * ChunkGeometry.GUARD_PIXELS / height;
        boolean split = settings.mode().splits();
        TessellationSettings t = settings.tessellation();
        long limit = split ? t.framePieceBudget((long) width * height, triangles) : Long.MAX_VALUE;
        DepthCapSearch.Attempt attempt = (depth, pieces) -> {
            pieceBudget.reset(pieces);
            RenderSettings s = depth == t.maxDepth() ? settings : settings.withTessellation(t.withMaxDepth(depth));
            ChunkGeometry.Input in = new ChunkGeometry.Input(draws, clipSpace.positions(),
                    clipSpace.invalid(), s, viewport, gx, gy, split, pieceBudget, layout, colours);
            pool.run(chunkCount, (thread, c) -> {
                int from = Math.min(triangles, c * perChunk);
                int to = Math.min(triangles, from + perChunk);
                chunkGeometry.run(thread, chunks.get(c), in, from, to);
            });
            return !pieceBudget.exceeded();
        };
        int budgetDepth = DepthCapSearch.fit(attempt, t.maxDepth(), limit);
        pool.run(chunkCount, (thread, c) -> {
            Chunk chunk = chunks.get(c);
            // Trimmed before binning: giving back the bands' storage empties them.
            chunk.trimIfOversized();
            chunk.bin(height);
        });
        chunks.retain(chunkCount);
        return new Result(chunkCount, transformNanos, limit == Long.MAX_VALUE ? 0 : limit, budgetDepth);
    }
}
