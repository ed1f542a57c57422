import java.lang.management.*;
import java.util.*;

/**
 * What finding a row's pieces by descending the split tree would cost (issue 15 item 2; see
 * docs/performance.md, "The one-pass fill, measured"): a random binary tree of split lines over a row
 * of 220 pixels (a tessellated demo row's width), each line's crossing column a multiply-add of the
 * row; per row the interval is cut at each node's crossing, children in order, leaves written as
 * segments. One thread, CPU time, 6,484 rows (a demo frame's rows of input triangles), median of 31.
 *
 * <pre>java scripts/one-pass/Descent.java 26</pre> (leaves per row: 26 at edge 32, about 14 at error 0.5)
 */
public class Descent {
    // Tree: internal nodes 0..n-1 with split line col(y) = k0 + k1 * y; children (>= 0 internal, < 0 leaf ~id).
    static int nodes; static double[] k0, k1; static int[] left, right;
    static int[] stack = new int[3 * 256];
    static int[] segLeaf = new int[256], segStart = new int[256], segEnd = new int[256];

    public static void main(String[] a) {
        Random rnd = new Random(7);
        int leaves = Integer.parseInt(a[0]);
        // A random binary tree over [0, 220) at row 0..15: split lines nearly vertical, random positions.
        nodes = leaves - 1; k0 = new double[nodes]; k1 = new double[nodes]; left = new int[nodes]; right = new int[nodes];
        int[] leafCount = {0};
        build(0, 0, 220, leaves, rnd, new int[]{1}, leafCount);
        int rows = 6484;
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        long sink = 0;
        double[] ms = new double[31];
        for (int rep = 0; rep < 60 + ms.length; rep++) {
            long t0 = cpu.getCurrentThreadCpuTime();
            long segs = 0;
            for (int r = 0; r < rows; r++) {
                int n = descend(r & 15, 0, 220);
                segs += n;
                sink += segEnd[n - 1];
            }
            long t = cpu.getCurrentThreadCpuTime() - t0;
            if (rep >= 60) ms[rep - 60] = t / 1e6;
            if (rep == 0) System.out.println("segments per frame " + segs);
        }
        Arrays.sort(ms);
        System.out.printf("leaves %d: %.3f ms per %d rows [%.3f..%.3f], %.1f ns per row (sink %d)%n", leaves,
                ms[15], rows, ms[0], ms[30], ms[15] * 1e6 / rows, sink % 7);
    }

    static int build(int node, double lo, double hi, int leavesHere, Random rnd, int[] nextNode, int[] leafCount) {
        int leftLeaves = leavesHere / 2 + (leavesHere % 2 == 1 && rnd.nextBoolean() ? 1 : 0);
        int rightLeaves = leavesHere - leftLeaves;
        double mid = lo + (hi - lo) * leftLeaves / leavesHere + (rnd.nextDouble() - 0.5) * 2;
        k0[node] = mid; k1[node] = (rnd.nextDouble() - 0.5) * 0.8;
        left[node] = leftLeaves == 1 ? ~(leafCount[0]++) : build(nextNode[0]++, lo, mid, leftLeaves, rnd, nextNode, leafCount);
        right[node] = rightLeaves == 1 ? ~(leafCount[0]++) : build(nextNode[0]++, mid, hi, rightLeaves, rnd, nextNode, leafCount);
        return node;
    }

    /** Segments of row y over [xs, xe), left to right, into seg*; returns how many. */
    static int descend(int y, int xs, int xe) {
        int[] st = stack;
        int top = 0;
        int n = 0;
        st[0] = 0; st[1] = xs; st[2] = xe; top = 3;
        while (top > 0) {
            top -= 3;
            int node = st[top]; int a = st[top + 1]; int b = st[top + 2];
            if (node < 0) {
                segLeaf[n] = ~node; segStart[n] = a; segEnd[n] = b; n++;
                continue;
            }
            int c = (int) Math.ceil(k0[node] + k1[node] * y);
            c = Math.max(a, Math.min(b, c));
            // Right child first on the stack, so the left one is taken next.
            if (c < b) { st[top] = right[node]; st[top + 1] = c; st[top + 2] = b; top += 3; }
            if (a < c) { st[top] = left[node]; st[top + 1] = a; st[top + 2] = c; top += 3; }
        }
        return n;
    }
}
