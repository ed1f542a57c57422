import java.io.*;
import java.lang.management.*;
import java.util.*;

/**
 * The shapes of the nearest affine pixel loop over the same segments (issue 15 item 2; see
 * docs/performance.md, "The one-pass fill, measured"): a row of an input triangle is cut into the
 * segments of its pieces, and each shape fills them all, one thread, timed by the thread's CPU time,
 * the shapes interleaved so that they see the same load.
 *
 * <ul>
 * <li>pieces: one counted loop per segment, as the piece-by-piece fill runs;</li>
 * <li>switch: one loop per row, which loads the next segment's texel start and steps when the
 *     column reaches its first pixel (the one-pass fill);</li>
 * <li>countdown: the same with a counter down to the next segment;</li>
 * <li>long: one loop per row with the first segment's plane throughout (wrong texels, the same
 *     pixels): the cost of the pixels alone, as the affine frame fills them.</li>
 * </ul>
 *
 * Segments: {@code synthetic} draws 6,484 rows of 26 segments with the lengths (1 to 31 pixels) and
 * frequencies counted in a tessellated demo frame at 1920x1080 (edge 32); or a file of rows written by
 * an instrumented build: per row int y, int n, then per segment int start, int end, long s, long t,
 * long ds, long dt (texel coordinates and steps, 32.32 fixed point), double q, double qDx.
 *
 * <pre>java scripts/one-pass/LoopBench.java synthetic pieces switch countdown long</pre>
 */
public class LoopBench {
    static int W = 1920, H = 1080;
    static int nRuns; static int[] runY, runFirst, runCount;
    static int[] sStart, sEnd; static long[] sS, sT, sDs, sDt; static double[] sQ, sQDx;
    static int[] color = new int[W * H]; static float[] depth = new float[W * H];
    static int tw = 256, th = 256; static int[] texels = new int[tw * th];

    /** Segment lengths 1..31 px and how often each occurs in a tessellated demo frame (edge 32, 1920x1080). */
    static final int[] HISTOGRAM = {12094, 11920, 11958, 11825, 11857, 11821, 11684, 11433, 10968, 9121, 8528, 7853,
        6800, 5911, 5151, 4815, 3660, 3004, 2496, 2123, 1615, 934, 575, 424, 246, 86, 74, 47, 41, 15, 7};

    /** Writes 6,484 runs of 26 segments with lengths drawn from HISTOGRAM in the format of a dump. */
    static byte[] synthetic() throws IOException {
        Random rnd = new Random(26);
        long total = 0;
        for (int h : HISTOGRAM) total += h;
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        for (int r = 0; r < 6484; r++) {
            int y = r % H;
            int[] len = new int[26];
            int sum = 0;
            for (int i = 0; i < 26; i++) {
                long pick = (long) (rnd.nextDouble() * total);
                int k = 0;
                while (pick >= HISTOGRAM[k]) { pick -= HISTOGRAM[k]; k++; }
                len[i] = k + 1;
                sum += len[i];
            }
            int x = rnd.nextInt(W - sum);
            out.writeInt(y); out.writeInt(26);
            for (int i = 0; i < 26; i++) {
                long ds = (long) ((0.3 + rnd.nextDouble()) * 4294967296.0);
                long dt = (long) ((rnd.nextDouble() - 0.5) * 4294967296.0);
                out.writeInt(x); out.writeInt(x + len[i]);
                out.writeLong((long) (rnd.nextDouble() * 200 * 4294967296.0)); out.writeLong((long) (rnd.nextDouble() * 200 * 4294967296.0));
                out.writeLong(ds); out.writeLong(dt);
                out.writeDouble(0.1 + rnd.nextDouble() * 0.1); out.writeDouble(1e-5 * rnd.nextGaussian());
                x += len[i];
            }
        }
        out.flush();
        return bytes.toByteArray();
    }

    public static void main(String[] a) throws Exception {
        InputStream source = a[0].equals("synthetic") ? new ByteArrayInputStream(synthetic()) : new FileInputStream(a[0]);
        DataInputStream in = new DataInputStream(new BufferedInputStream(source));
        List<int[]> runs = new ArrayList<>();
        int segs = 0;
        int cap = 300000;
        sStart = new int[cap]; sEnd = new int[cap]; sS = new long[cap]; sT = new long[cap]; sDs = new long[cap]; sDt = new long[cap]; sQ = new double[cap]; sQDx = new double[cap];
        try {
            while (true) {
                int y = in.readInt(); int n = in.readInt();
                runs.add(new int[]{y, segs, n});
                for (int i = 0; i < n; i++) {
                    sStart[segs] = in.readInt(); sEnd[segs] = in.readInt(); sS[segs] = in.readLong(); sT[segs] = in.readLong();
                    sDs[segs] = in.readLong(); sDt[segs] = in.readLong(); sQ[segs] = in.readDouble(); sQDx[segs] = in.readDouble();
                    segs++;
                }
            }
        } catch (EOFException e) { }
        nRuns = runs.size(); runY = new int[nRuns]; runFirst = new int[nRuns]; runCount = new int[nRuns];
        long px = 0;
        for (int i = 0; i < nRuns; i++) { int[] r = runs.get(i); runY[i] = r[0]; runFirst[i] = r[1]; runCount[i] = r[2]; }
        for (int g = 0; g < segs; g++) px += sEnd[g] - sStart[g];
        System.out.println("runs " + nRuns + " segments " + segs + " pixels " + px);
        Random rnd = new Random(1); for (int i = 0; i < texels.length; i++) texels[i] = rnd.nextInt();
        String[] variants = Arrays.copyOfRange(a, 1, a.length);
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        double[][] ms = new double[variants.length][];
        int reps = 30;
        for (int v = 0; v < variants.length; v++) ms[v] = new double[reps];
        for (int w = 0; w < 20; w++) for (String v : variants) frame(v);
        for (int k = 0; k < reps; k++) {
            for (int v = 0; v < variants.length; v++) {
                long t0 = cpu.getCurrentThreadCpuTime();
                frame(variants[v]);
                ms[v][k] = (cpu.getCurrentThreadCpuTime() - t0) / 1e6;
            }
        }
        for (int v = 0; v < variants.length; v++) { Arrays.sort(ms[v]); System.out.printf("%-10s median %.3f ms  [%.3f..%.3f]%n", variants[v], ms[v][reps/2], ms[v][0], ms[v][reps-1]); }
    }

    static long frame(String v) {
        Arrays.fill(depth, 0f);
        long w = 0;
        switch (v) {
            case "pieces": for (int r = 0; r < nRuns; r++) w += pieces(runY[r], runFirst[r], runCount[r]); break;
            case "switch": for (int r = 0; r < nRuns; r++) w += switched(runY[r], runFirst[r], runCount[r]); break;
            case "countdown": for (int r = 0; r < nRuns; r++) w += countdown(runY[r], runFirst[r], runCount[r]); break;
            case "long": for (int r = 0; r < nRuns; r++) w += longRow(runY[r], runFirst[r], runCount[r]); break;
        }
        return w;
    }

    /** Old shape: one counted loop per segment. */
    static long pieces(int y, int first, int n) {
        long written = 0; int rowOffset = y * W; int wMask = tw - 1, hMask = th - 1, topRow = th - 1;
        for (int g = first; g < first + n; g++) {
            long s = sS[g], t = sT[g], ds = sDs[g], dt = sDt[g]; double qRow = sQ[g], qDx = sQDx[g];
            int end = sEnd[g]; double xd = sStart[g];
            for (int x = sStart[g]; x < end; x++, xd++, s += ds, t += dt) {
                float qf = (float) (qRow + qDx * xd); int idx = rowOffset + x;
                if (qf > depth[idx]) { depth[idx] = qf; int si = (int) (s >> 32); int ti = (int) (t >> 32);
                    color[idx] = texels[(topRow - (ti & hMask)) * tw + (si & wMask)] | 0xFF000000; written++; }
            }
        }
        return written;
    }

    static long switched(int y, int first, int n) {
        long written = 0; int rowOffset = y * W; int wMask = tw - 1, hMask = th - 1, topRow = th - 1;
        int xStart = sStart[first], xEnd = sEnd[first + n - 1];
        int i = first; int next = xStart; long s = 0, t = 0, ds = 0, dt = 0; double qRow = 0, qDx = 0; double xd = xStart;
        for (int x = xStart; x < xEnd; x++, xd++, s += ds, t += dt) {
            if (x == next) { next = sEnd[i]; s = sS[i]; t = sT[i]; ds = sDs[i]; dt = sDt[i]; qRow = sQ[i]; qDx = sQDx[i]; i++; }
            float qf = (float) (qRow + qDx * xd); int idx = rowOffset + x;
            if (qf > depth[idx]) { depth[idx] = qf; int si = (int) (s >> 32); int ti = (int) (t >> 32);
                color[idx] = texels[(topRow - (ti & hMask)) * tw + (si & wMask)] | 0xFF000000; written++; }
        }
        return written;
    }

    static long countdown(int y, int first, int n) {
        long written = 0; int rowOffset = y * W; int wMask = tw - 1, hMask = th - 1, topRow = th - 1;
        int xStart = sStart[first], xEnd = sEnd[first + n - 1];
        int i = first; int left = 0; long s = 0, t = 0, ds = 0, dt = 0; double qRow = 0, qDx = 0; double xd = xStart;
        for (int x = xStart; x < xEnd; x++, xd++, s += ds, t += dt) {
            if (--left < 0) { left = sEnd[i] - x - 1; s = sS[i]; t = sT[i]; ds = sDs[i]; dt = sDt[i]; qRow = sQ[i]; qDx = sQDx[i]; i++; }
            float qf = (float) (qRow + qDx * xd); int idx = rowOffset + x;
            if (qf > depth[idx]) { depth[idx] = qf; int si = (int) (s >> 32); int ti = (int) (t >> 32);
                color[idx] = texels[(topRow - (ti & hMask)) * tw + (si & wMask)] | 0xFF000000; written++; }
        }
        return written;
    }

    /** Lower bound: the whole run with the first segment's plane (wrong texels, same pixels). */
    static long longRow(int y, int first, int n) {
        long written = 0; int rowOffset = y * W; int wMask = tw - 1, hMask = th - 1, topRow = th - 1;
        int xStart = sStart[first], xEnd = sEnd[first + n - 1];
        long s = sS[first], t = sT[first], ds = sDs[first], dt = sDt[first]; double qRow = sQ[first], qDx = sQDx[first]; double xd = xStart;
        for (int x = xStart; x < xEnd; x++, xd++, s += ds, t += dt) {
            float qf = (float) (qRow + qDx * xd); int idx = rowOffset + x;
            if (qf > depth[idx]) { depth[idx] = qf; int si = (int) (s >> 32); int ti = (int) (t >> 32);
                color[idx] = texels[(topRow - (ti & hMask)) * tw + (si & wMask)] | 0xFF000000; written++; }
        }
        return written;
    }
}
