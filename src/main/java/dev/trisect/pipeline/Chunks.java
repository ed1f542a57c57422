package dev.trisect.pipeline;

import java.util.Arrays;

/**
 * The chunks a frame's input triangles are cut into, kept from frame to frame, and the rule that
 * cuts them.
 *
 * <p>The chunks are set by the triangle count n alone (see {@link #count} and {@link #size}):
 * {@code min(MAX_CHUNKS, ceil(n / SMALL_MESH_CHUNK_CAP))} chunks (at least one), each of
 * {@code ceil(n / chunks)} consecutive triangles but the last, which holds the rest. So 1000
 * triangles make two chunks of 500, 32768 make 64 of 512, and 100,000 make 64 of 1563 (the last
 * 1531): past 32768 triangles chunks grow beyond the cap, their count does not.
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
final class Chunks {
    /** Largest chunk of a mesh of up to {@code SMALL_MESH_CHUNK_CAP * MAX_CHUNKS} (32768) triangles. */
    private static final int SMALL_MESH_CHUNK_CAP = 512;
    /** Most chunks: enough to balance many threads, few enough that each band's walk over them stays cheap. */
    private static final int MAX_CHUNKS = 64;

    private Chunk[] chunks = new Chunk[0];
    /** How many chunks to keep: those beyond recent frames' counts go, with all they hold. */
    private final Retention retention = new Retention(1);

    /** Chunks a mesh of {@code triangles} triangles is cut into. */
    static int count(int triangles) {
        return Math.max(1, Math.min(MAX_CHUNKS, (triangles + SMALL_MESH_CHUNK_CAP - 1) / SMALL_MESH_CHUNK_CAP));
    }

    /** Triangles in each of {@code count} chunks of {@code triangles} but the last, which holds the rest. */
    static int size(int triangles, int count) {
        return (triangles + count - 1) / count;
    }

    /** Makes sure chunks 0..count-1 exist; call on one thread, before the geometry. */
    void ensure(int count) {
        if (chunks.length < count) {
            Chunk[] grown = Arrays.copyOf(chunks, count);
            for (int i = chunks.length; i < count; i++) {
                grown[i] = new Chunk();
            }
            chunks = grown;
        }
    }

    /**
     * After a frame that used chunks 0..used-1: empties the chunks it did not use, gives back what
     * each holds beyond the policy's floor, and drops those beyond what recent frames used (see
     * {@link Retention}), so that one frame of a huge mesh does not keep 64 chunks' storage. Call on
     * one thread, after the frame's geometry.
     */
    void retain(int used) {
        for (int c = used; c < chunks.length; c++) {
            chunks[c].clear();
            chunks[c].trimIfOversized();
        }
        long keep = retention.keep(used, chunks.length);
        if (keep >= 0) {
            chunks = Arrays.copyOf(chunks, (int) Math.max(keep, used));
        }
    }

    /** Drops every chunk with its storage; the next frame makes those it needs. */
    void release() {
        chunks = new Chunk[0];
    }

    /** Chunk {@code c}. */
    Chunk get(int c) {
        return chunks[c];
    }

    /** Triangles the chunks' screen-triangle storage holds room for, for tests of trimming. */
    long retainedTriangleCapacity() {
        long total = 0;
        for (Chunk c : chunks) {
            total += c.out.capacity() + c.commands.bins().entryCapacity() / 2;
        }
        return total;
    }
}
