package dev.trisect.raster;

import java.util.Arrays;

/**
 * The store of a frame's {@link Commands#LINE LINE} commands: screen segments as {@link LineSetup}
 * sets them up (each an OpenGL line as a parallelogram of edge functions in 1/256-pixel fixed point,
 * window space, with its columns, rows, colour and 1/w along its major axis), read by
 * {@link LineRaster}'s row loop. Storage grows as needed and is kept from frame to frame.
 */
public final class Segments {
    /** Longs per segment: c, dcdx, dcdy of each slanted edge (up to four). */
    static final int LSTRIDE = 12;
    /**
     * Ints per segment: first and last column, first and last frame row, colour, and the x-major flag
     * with the number of slanted edges (the rest are folded into the columns and rows) above it.
     */
    static final int ISTRIDE = 6;
    /** Doubles per segment: the major-axis coordinate of the depth origin, its 1/w, 1/w per pixel. */
    static final int DSTRIDE = 3;

    long[] planes = new long[LSTRIDE * 64];
    int[] ints = new int[ISTRIDE * 64];
    double[] depth = new double[DSTRIDE * 64];
    private int count;
    private int width;
    private int height;

    /** Forgets every segment, for a frame of {@code width x height} pixels. */
    public void begin(int width, int height) {
        this.width = width;
        this.height = height;
        count = 0;
    }

    /** Segments set up since {@link #begin}. */
    public int count() {
        return count;
    }

    /** The frame's width, pixels. */
    public int width() {
        return width;
    }

    /** The frame's height, pixels. */
    public int height() {
        return height;
    }

    /** Segment {@code s}'s first frame row (row 0 at the top). */
    public int firstRow(int s) {
        return ints[ISTRIDE * s + 2];
    }

    /** Segment {@code s}'s last frame row, inclusive. */
    public int lastRow(int s) {
        return ints[ISTRIDE * s + 3];
    }

    /** The index of a new segment, with room for it; {@link #commit} counts it once it is set up. */
    int next() {
        if (count * ISTRIDE == ints.length) {
            planes = Arrays.copyOf(planes, 2 * planes.length);
            ints = Arrays.copyOf(ints, 2 * ints.length);
            depth = Arrays.copyOf(depth, 2 * depth.length);
        }
        return count;
    }

    /** Counts the segment {@link #next} gave. */
    void commit() {
        count++;
    }
}
