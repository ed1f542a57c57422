package dev.trisect.view.internal;

/**
 * The last few seconds of frame times, split by stage, for the developer tools' graph. The render
 * thread adds one frame at a time; the event thread takes a copy to draw. Every frame's stages add up
 * to the whole time from its start to the next frame's start ("other" holds what no stage claims:
 * camera, scheduling), so the graph accounts for everything a frame costs.
 */
public final class FrameTimes {
    /** Stage names, bottom to top of the stacked graph. */
    public static final String[] STAGES = {"transform", "clip", "tessellate", "raster", "overlay", "compare", "present",
        "other"};
    /** Frames kept: five seconds at 60 frames per second. */
    public static final int CAPACITY = 300;

    private final double[][] ms = new double[CAPACITY][];
    private long added;

    /**
     * Adds a frame.
     *
     * @param stagesMs  milliseconds of each of the first {@code STAGES.length - 1} stages
     * @param frameMs   the frame's whole time, start to the next frame's start; "other" is what is left
     */
    synchronized void add(double[] stagesMs, double frameMs) {
        double[] row = new double[STAGES.length];
        double sum = 0;
        for (int i = 0; i < STAGES.length - 1; i++) {
            row[i] = Math.max(0, stagesMs[i]);
            sum += row[i];
        }
        row[STAGES.length - 1] = Math.max(0, frameMs - sum);
        ms[(int) (added % CAPACITY)] = row;
        added++;
    }

    /** The frames kept, oldest first, each a row of milliseconds per stage. */
    public synchronized double[][] snapshot() {
        int n = (int) Math.min(added, CAPACITY);
        double[][] out = new double[n][];
        for (int i = 0; i < n; i++) {
            out[i] = ms[(int) ((added - n + i) % CAPACITY)].clone();
        }
        return out;
    }

    /** Frames added in all. */
    synchronized long added() {
        return added;
    }
}
