package dev.trisect.raster;

import java.util.Arrays;

/**
 * A command list for the band fill, binned into bands of rows: what llvmpipe's bins hold per tile
 * ({@code lp_setup} sets a primitive up and bins it, {@code lp_rast} runs each bin's commands), here
 * per band of rows. Each command is a kind and a reference into the store of that kind, which its
 * setup filled before binning; {@link BandFill} draws a band's commands, dispatching once per command
 * on its kind to that kind's loop.
 *
 * <table>
 * <caption>The kinds</caption>
 * <tr><th>kind</th><th>reference</th><th>set up by</th><th>drawn by</th></tr>
 * <tr><td>{@link #TRIANGLE}</td><td>a screen triangle of {@link #triangles()}</td>
 * <td>{@link ScreenTriangles#add} (per band: {@link TriangleSetup})</td><td>{@link Rasterizer}'s loops</td></tr>
 * <tr><td>{@link #TREE}</td><td>an input triangle with its split tree, of {@link #trees()}</td>
 * <td>{@link SplitTrees#add}</td><td>{@link Rasterizer}'s one-pass fill ({@link TreeFill})</td></tr>
 * <tr><td>{@link #LINE}</td><td>a screen segment of {@link #segments()}</td>
 * <td>{@link LineSetup}</td><td>{@link LineRaster}</td></tr>
 * <tr><td>{@link #QUAD}</td><td>a screen-aligned textured rectangle of {@link #quads()}</td>
 * <td>{@link QuadRaster#add}, {@link QuadRaster#setUp}</td><td>{@link QuadRaster#rows}</td></tr>
 * </table>
 *
 * <p>Order: within every band the commands are drawn in the order they were added, whatever their
 * kinds (the bins keep it, {@link BandBins}); what is submitted later is drawn over what is submitted
 * earlier where the depth test lets it.
 *
 * <p>Use: give the list the stores of the kinds it holds ({@link #triangles(ScreenTriangles)}, ...),
 * {@link #clear}, {@link #add} each command in order with the rows its setup says it may light,
 * {@link #bin}; then band b's commands are {@code command(bins().items()[k])} for k in
 * {@code [bins().start(b), bins().start(b + 1))}. Not thread-safe to fill; read by any number of
 * threads after {@link #bin}.
 */
public final class Commands {
    /** A screen triangle, filled by the loop of the frame's path and filter. */
    public static final int TRIANGLE = 0;
    /** An input triangle with its split tree: the tessellated path's one-pass fill. */
    public static final int TREE = 1;
    /** A screen segment: an OpenGL line, depth-tested. */
    public static final int LINE = 2;
    /** A screen-aligned textured rectangle at one depth: a billboard, a glyph, a backdrop. */
    public static final int QUAD = 3;
    /** A command's kind sits in its bits from this one up, its reference below. */
    private static final int KIND_SHIFT = 28;
    /** The largest reference a command holds. */
    public static final int MAX_REF = (1 << KIND_SHIFT) - 1;

    private ScreenTriangles triangles;
    private SplitTrees trees;
    private Segments segments;
    private QuadRaster quads;
    private int[] commands = new int[1024];
    /** Per command, the first row it may light and the row after its last (unclipped). */
    private int[] rows = new int[2 * 1024];
    private int count;
    private final BandBins bins = new BandBins();

    /** Sets the store of {@link #TRIANGLE} commands; returns this list. */
    public Commands triangles(ScreenTriangles store) {
        triangles = store;
        return this;
    }

    /** Sets the store of {@link #TREE} commands; returns this list. */
    public Commands trees(SplitTrees store) {
        trees = store;
        return this;
    }

    /** Sets the store of {@link #QUAD} commands; returns this list. */
    public Commands quads(QuadRaster store) {
        quads = store;
        return this;
    }

    /** Sets the store of {@link #LINE} commands; returns this list. */
    public Commands segments(Segments store) {
        segments = store;
        return this;
    }

    /** Removes every command, keeping the storage (the stores are cleared by their owners). */
    public void clear() {
        count = 0;
    }

    /**
     * Appends a command of {@code kind} drawing item {@code ref} of that kind's store, which may light
     * frame rows {@code [firstRow, endRow)} (its setup says which; rows beyond the frame are allowed).
     */
    public void add(int kind, int ref, int firstRow, int endRow) {
        if (ref < 0 || ref > MAX_REF) {
            throw new IllegalArgumentException("command reference out of range: " + ref);
        }
        if (count == commands.length) {
            commands = Arrays.copyOf(commands, 2 * count);
            rows = Arrays.copyOf(rows, 4 * count);
        }
        rows[2 * count] = firstRow;
        rows[2 * count + 1] = endRow;
        commands[count++] = kind << KIND_SHIFT | ref;
    }

    /** Commands added since {@link #clear}. */
    public int count() {
        return count;
    }

    /** Command {@code i}: a kind and a reference, read by {@link #kind} and {@link #ref}. */
    public int command(int i) {
        return commands[i];
    }

    /** The kind of {@code command}: {@link #TRIANGLE}, {@link #TREE}, {@link #LINE} or {@link #QUAD}. */
    public static int kind(int command) {
        return command >>> KIND_SHIFT;
    }

    /** The item of its kind's store that {@code command} draws. */
    public static int ref(int command) {
        return command & MAX_REF;
    }

    /**
     * Sorts the commands into bands of {@code bandRows} rows of a frame {@code height} rows high, each
     * listed in every band holding a row it may light, in the order added.
     */
    public void bin(int height, int bandRows) {
        bins.prepare(count);
        for (int i = 0; i < count; i++) {
            int first = Math.max(0, rows[2 * i]);
            int end = Math.min(height, rows[2 * i + 1]);
            if (first >= end) {
                bins.none(i);
            } else {
                bins.rows(i, first, end - 1, bandRows);
            }
        }
        bins.build(count, BandBins.bandCount(height, bandRows));
    }

    /** The bands' lists of command indices (see the class comment). */
    public BandBins bins() {
        return bins;
    }

    /** The store of {@link #TRIANGLE} commands (null for a list without). */
    public ScreenTriangles triangles() {
        return triangles;
    }

    /** The store of {@link #TREE} commands (null for a list without). */
    public SplitTrees trees() {
        return trees;
    }

    /** The store of {@link #QUAD} commands (null for a list without). */
    public QuadRaster quads() {
        return quads;
    }

    /** The store of {@link #LINE} commands (null for a list without). */
    public Segments segments() {
        return segments;
    }

    /** Room for commands held now (for tests of trimming). */
    int capacity() {
        return commands.length;
    }

    /** Gives storage back: room for {@code n} commands and at most {@code entries} band entries. */
    public void shrink(int n, int entries) {
        int keep = Math.max(1, Math.min(commands.length, Math.max(n, count)));
        commands = Arrays.copyOf(commands, keep);
        rows = Arrays.copyOf(rows, 2 * keep);
        bins.shrink(n, entries);
    }
}
