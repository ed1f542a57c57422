package dev.trisect.raster;

import java.util.Arrays;

/**
 * A store of {@link Commands#LINE LINE} commands: screen segments, each set up for the coverage rule
 * of its store, read by {@link LineRaster}'s row loop, which dispatches on the rule once per command.
 *
 * <ul>
 * <li>{@link #DIAMOND}: OpenGL's aliased lines, as {@link LineSetup} sets them up (a parallelogram of
 * edge functions in 1/256-pixel fixed point, window space, with its columns, rows, colour and 1/w
 * along its major axis), depth-tested and written as OpenGL does: a frame's lines.</li>
 * <li>{@link #CROSSING}: the pixel an edge crosses at each column (or row) centre within it, as
 * {@link LineCrossing} sets it up, written by the {@link BorderOverlay}'s depth test against the
 * outlined triangles of an {@link OutlinePlan}: the border overlay's edges.</li>
 * </ul>
 *
 * <p>Storage grows as needed and is kept from frame to frame; {@link #shrink} gives it back.
 */
public final class Segments {
    /** The rule of a frame's lines: OpenGL's diamond exit (OpenGL 1.x, section 3.4.1). */
    public static final int DIAMOND = 0;
    /** The rule of the border overlay's edges: the pixel each column or row centre's crossing lies in. */
    public static final int CROSSING = 1;

    /** Longs per {@link #DIAMOND} segment: c, dcdx, dcdy of each slanted edge (up to four). */
    static final int LSTRIDE = 12;
    /**
     * Ints per {@link #DIAMOND} segment: first and last column, first and last frame row, colour, and
     * the x-major flag with the number of slanted edges (the rest are folded into the columns and
     * rows) above it.
     */
    static final int ISTRIDE = 6;
    /** Doubles per {@link #DIAMOND} segment: the major-axis coordinate of the depth origin, its 1/w, 1/w per pixel. */
    static final int DSTRIDE = 3;

    private final int rule;
    private final int intStride;
    private final int doubleStride;
    private final int longStride;
    long[] planes;
    int[] ints;
    double[] depth;
    /** For {@link #CROSSING}: the plan whose triangles' outlines the edges are (their depth planes and colours). */
    OutlinePlan plan;
    private int count;
    private int width;
    private int height;

    /** A store of {@link #DIAMOND} segments: a frame's lines. */
    public Segments() {
        this(DIAMOND);
    }

    /** A store of segments of {@code rule}, {@link #DIAMOND} or {@link #CROSSING}. */
    Segments(int rule) {
        this.rule = rule;
        boolean diamond = rule == DIAMOND;
        intStride = diamond ? ISTRIDE : LineCrossing.ISTRIDE;
        doubleStride = diamond ? DSTRIDE : LineCrossing.DSTRIDE;
        longStride = diamond ? LSTRIDE : 0;
        int room = diamond ? 64 : 0;
        planes = new long[longStride * room];
        ints = new int[intStride * room];
        depth = new double[doubleStride * room];
    }

    /** The coverage rule of every segment of this store: {@link #DIAMOND} or {@link #CROSSING}. */
    public int rule() {
        return rule;
    }

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

    /** {@link #DIAMOND} segment {@code s}'s first frame row (row 0 at the top). */
    public int firstRow(int s) {
        return ints[ISTRIDE * s + 2];
    }

    /** {@link #DIAMOND} segment {@code s}'s last frame row, inclusive. */
    public int lastRow(int s) {
        return ints[ISTRIDE * s + 3];
    }

    /** The index of a new segment, with room for it; {@link #commit} counts it once it is set up. */
    int next() {
        if (count * intStride == ints.length) {
            reserve(Math.max(64, 2 * count));
        }
        return count;
    }

    /** Makes room for at least {@code n} segments. */
    void reserve(int n) {
        if (ints.length < intStride * n) {
            planes = Arrays.copyOf(planes, longStride * n);
            ints = Arrays.copyOf(ints, intStride * n);
            depth = Arrays.copyOf(depth, doubleStride * n);
        }
    }

    /** Makes the first {@code n} segments, written in place after {@link #reserve}, this store's segments. */
    void count(int n) {
        count = n;
    }

    /** Counts the segment {@link #next} gave. */
    void commit() {
        count++;
    }

    /** Room for segments held now (for tests of trimming). */
    int capacity() {
        return ints.length / intStride;
    }

    /** Gives storage back: room for {@code n} segments (at least those held). */
    void shrink(int n) {
        int keep = Math.max(n, count);
        if (capacity() > keep) {
            planes = Arrays.copyOf(planes, longStride * keep);
            ints = Arrays.copyOf(ints, intStride * keep);
            depth = Arrays.copyOf(depth, doubleStride * keep);
        }
    }
}
