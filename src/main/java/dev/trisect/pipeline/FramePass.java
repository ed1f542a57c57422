package dev.trisect.pipeline;

/**
 * One pass of a frame. {@link FrameRenderer} runs its passes in order on every frame, each on the
 * renderer's threads through the frame's {@link FrameJob}: the {@link FrameGeometry geometry} (transform,
 * clip, tessellate or project, bin), the {@link LineGeometry lines' geometry} (their segments set up
 * and binned), then the {@link BandPass fill} (each band cleared, filled, fogged, with the borders on
 * outlined, and its lines drawn, while its rows are in cache); a later pass (screen text, say) comes
 * after them. A pass reads what the
 * passes before it left in the job and leaves its own results there; it never keeps a frame's data
 * past the frame, except in the renderer's storage that the next frame reuses.
 *
 * <p>Adding a pass is a class implementing this and one line in {@link FrameRenderer}'s list.
 */
interface FramePass {
    /**
     * Runs this pass over the frame of {@code job}, on the calling thread and {@code job.pool}'s.
     *
     * @param job the frame being drawn, with the results of the passes before this one
     */
    void run(FrameJob job);
}
