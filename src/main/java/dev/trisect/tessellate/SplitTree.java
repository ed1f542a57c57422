package dev.trisect.tessellate;


import java.util.Arrays;

/**
 * The split tree of the last triangle a {@link Tessellator} split: which of its pieces each point of
 * the input triangle lies in, for a fill that takes coverage from the input triangle and finds each
 * pixel's piece by descending the tree along its row.
 *
 * <p>Each node is one split, whose line (from the cut point to the opposite corner, unsnapped screen
 * pixels) divides its triangle into the two pieces it made; its left child is the one on the side of
 * smaller screen x along every row (for a horizontal line, the one above it). A reference is a node
 * number (&gt;= 0), a piece ({@code -1 - k} for the k-th piece handed on for the input triangle,
 * counting from 0), or {@link #NO_PIECE}. The leaves tile the input triangle exactly, whatever
 * their snapped corners, caps included.
 *
 * <p>Scratch of its tessellator: read it before the next {@link Tessellator#process}.
 */
public final class SplitTree {
    /**
     * A reference to a piece that was dropped for lying off screen: no pixel centre of the viewport
     * lies in it.
     */
    public static final int NO_PIECE = Integer.MIN_VALUE;
    /** Doubles per node in {@link #lines()}. */
    public static final int LINE = 2;
    /**
     * The steepest slope a split line is given, in pixels of x per pixel of y: flatter lines, and
     * horizontal ones, are taken as this slope (with their own sign; minus it for horizontal ones).
     * Through any row whose centre is not within 2^-30 pixel of the line's height it puts the line
     * more than 2^30 pixels away, beyond the frame, so the row lies wholly on the line's side, as it
     * does for the true line; a row closer than that lies on the line within rounding. A horizontal
     * line is never evaluated: {@link #rows()} sends every row to one side of it, the row of centres
     * on it to the piece below.
     */
    public static final double STEEPEST = 0x1p60;

    /**
     * How far beyond the ends of a split line, in pixels, a row of centres still evaluates the line
     * rather than going wholly to one side ({@link #rows()}). The input triangle's covered pixels may
     * lie just outside its pieces: its coverage is its own, from corners snapped to 1/256 px (up to
     * about 0.003 px beyond it), and a cut point of an edge along a row of centres (y = 8.5) may lie
     * at 8.500000000000004, leaving that row's centres above the pieces along the edge. In a row just
     * beyond a line's end such a centre may lie beside either child, both of which reach the row, so
     * only the line can place it; further out the row's own rule holds for it too.
     */
    public static final double END_MARGIN = 1.0 / 64;

    private int[] kids = new int[2 * 64];
    private double[] lines = new double[LINE * 64];
    private int[] rows = new int[3 * 64];
    private int nodes;
    private int root = NO_PIECE;
    private int leaves;
    private boolean complete;

    SplitTree() {
    }

    /** Empties the tree for a new input triangle. */
    void clear() {
        nodes = 0;
        leaves = 0;
        root = NO_PIECE;
        complete = false;
    }

    /**
     * Whether the last {@link Tessellator#process} with {@code split} true finished its triangle, so
     * that the tree is whole (false when the piece budget stopped it).
     */
    public boolean complete() {
        return complete;
    }

    void complete(boolean whole) {
        complete = whole;
    }

    /** The root: a reference (see the class comment). */
    public int root() {
        return root;
    }

    /** Nodes in the tree. */
    public int nodes() {
        return nodes;
    }

    /** Pieces handed on for the input triangle: the leaves that are not {@link #NO_PIECE}. */
    public int leaves() {
        return leaves;
    }

    /** The children of the nodes: node n's left child at {@code 2n}, right child at {@code 2n + 1}, references. */
    public int[] kids() {
        return kids;
    }

    /**
     * The nodes' lines, {@link #LINE} doubles per node: {@code k, m}, screen pixels. Along the row of
     * pixel centres {@code y + 0.5} (y the pixel row) the line lies at screen x = {@code k y + m + 0.5}:
     * k is the line's dx/dy, within {@link #STEEPEST}. Points at smaller x are in the left child (for
     * a horizontal line, the rows above it).
     */
    public double[] lines() {
        return lines;
    }

    /**
     * Per node, three ints: the rows where its line must be evaluated, and where the others lie. Rows
     * y below the first ({@code y < rows[3n]}: their centres lie more than {@link #END_MARGIN} above
     * both ends of the line) lie wholly in one child, rows from the second on ({@code y >= rows[3n + 1]},
     * more than that below both ends) wholly in the other; the third is 0 when the first of these is
     * the left child, 1 when it is the right. For a
     * horizontal line the first two are equal (the row alone says which side a centre lies on): a row
     * whose centres lie on it goes with the rows below, as the tie rule says, without evaluating the
     * line (where {@code k y + m} would cancel to the rounding of m, up to hundreds of pixels, and cut
     * the row anywhere).
     */
    public int[] rows() {
        return rows;
    }

    /** Records a piece handed on, where {@code slot} says ({@link #refer}); returns its leaf number. */
    int leaf(int slot) {
        refer(slot, -1 - leaves);
        return leaves++;
    }

    /** Puts reference {@code ref} where {@code slot} says: a parent's child ({@code 2n} or {@code 2n + 1}), or the root for -1. */
    void refer(int slot, int ref) {
        if (slot < 0) {
            root = ref;
        } else {
            kids[slot] = ref;
        }
    }

    /**
     * A new node for the split of a piece along the line from cut point {@code m} to corner {@code r}
     * (offsets into {@code v} of each vertex's screen x, followed by its screen y: {@link
     * VertexLayout#screenX()}) with p the split edge's other end beside m,
     * referred to from {@code slot}; its children are referred to as they are decided.
     *
     * @return which child slot of the node takes the piece with corner p: {@code 2n} or {@code 2n + 1}
     */
    int split(double[] v, int slot, int m, int r, int p) {
        int n = nodes++;
        if (2 * n + 2 > kids.length) {
            kids = Arrays.copyOf(kids, kids.length * 2);
            lines = Arrays.copyOf(lines, lines.length * 2);
            rows = Arrays.copyOf(rows, rows.length * 2);
        }
        double mx = v[m];
        double my = v[m + 1];
        double dy = v[r + 1] - my;
        double k = dy == 0 ? -STEEPEST : Math.max(-STEEPEST, Math.min(STEEPEST, (v[r] - mx) / dy));
        int o = LINE * n;
        // x = mx + k (y + 0.5 - my) on the row of centres y + 0.5, as k y + m + 0.5.
        lines[o] = k;
        lines[o + 1] = mx + k * (0.5 - my) - 0.5;
        refer(slot, n);
        // Which side of the line the piece with corner p lies on.
        // (For a horizontal line the left child is the one above it.)
        int pSide = dy == 0 ? (v[p + 1] < my ? 0 : 1)
                : v[p] - 0.5 < lines[o] * (v[p + 1] - 0.5) + lines[o + 1] ? 0 : 1;
        double top = Math.min(my, v[r + 1]);
        double bottom = Math.max(my, v[r + 1]);
        int ro = 3 * n;
        // Row y's centre is above top when y < ceil(top - 1/2), below bottom when y > bottom - 1/2;
        // more than END_MARGIN above or below likewise (see rows()). Rows above both ends
        // lie in the child of whichever of p and the split edge's other end is above m, rows below
        // both in the other.
        rows[ro] = (int) Math.ceil(top - 0.5 - END_MARGIN);
        rows[ro + 1] = (int) Math.floor(bottom - 0.5 + END_MARGIN) + 1;
        if (dy == 0) {
            // A horizontal line: the row of centres on it (if any) goes with the rows below, the tie rule.
            rows[ro] = (int) Math.ceil(top - 0.5);
            rows[ro + 1] = rows[ro];
        }
        rows[ro + 2] = v[p + 1] < my ? pSide : 1 - pSide;
        return 2 * n + pSide;
    }
}
