import jdk.incubator.vector.*;

/** Bilinear packed-ARGB sampling along rows: scalar vs Vector API (JDK 17 incubator), same output. */
/**
 * A standalone experiment for issue 16 (not part of the build): is the incubator Vector API of JDK 17
 * worth an optional SIMD path for the filtered loops? It samples a 256x256 texture bilinearly along
 * 1080 rows of 1920 pixels (steps of 0.3 to 3 texels per pixel), once with the packed-ARGB scalar
 * loop (8-bit weights, as LaneSampler blends) and once with IntVector lanes (four gathers per pixel
 * group), checks that both give the same texels, then times them side by side in one thread by
 * thread CPU time, 20 repetitions. Run from the repository root:
 *
 * <pre>java --add-modules jdk.incubator.vector -Dbits=256 scripts/vector-sample/VectorSample.java
 * java --add-modules jdk.incubator.vector -Dbits=512 scripts/vector-sample/VectorSample.java</pre>
 */
public class VectorSample {
    static final VectorSpecies<Integer> S = "512".equals(System.getProperty("bits")) ? IntVector.SPECIES_512
            : IntVector.SPECIES_256;
    static final int TW = 256, TH = 256, MASKX = TW - 1, MASKY = TH - 1, SHIFT = 8;

    static void scalar(int[] tex, int[] out, int n, int u0, int du, int v0, int dv) {
        int u = u0, v = v0;
        for (int i = 0; i < n; i++, u += du, v += dv) {
            int x0 = (u >> 16) & MASKX, y0 = (v >> 16) & MASKY;
            int x1 = (x0 + 1) & MASKX, y1 = (y0 + 1) & MASKY;
            int fx = (u >> 8) & 0xFF, fy = (v >> 8) & 0xFF;
            int a = tex[(y0 << SHIFT) | x0], b = tex[(y0 << SHIFT) | x1];
            int c = tex[(y1 << SHIFT) | x0], d = tex[(y1 << SHIFT) | x1];
            int w00 = (256 - fx) * (256 - fy) >> 8, w10 = fx * (256 - fy) >> 8;
            int w01 = (256 - fx) * fy >> 8, w11 = fx * fy >> 8;
            int rb = ((a & 0xFF00FF) * w00 + (b & 0xFF00FF) * w10 + (c & 0xFF00FF) * w01 + (d & 0xFF00FF) * w11) >>> 8;
            int ag = ((a >>> 8) & 0xFF00FF) * w00 + ((b >>> 8) & 0xFF00FF) * w10 + ((c >>> 8) & 0xFF00FF) * w01
                    + ((d >>> 8) & 0xFF00FF) * w11;
            out[i] = (rb & 0xFF00FF) | (ag & 0xFF00FF00);
        }
    }


    static void vector(int[] tex, int[] out, int n, int u0, int du, int v0, int dv, int[] idx) {
        IntVector lane = IntVector.zero(S).addIndex(1);
        int L = S.length();
        IntVector uu = lane.mul(du).add(u0), vv = lane.mul(dv).add(v0);
        int step = S.length();
        IntVector dU = IntVector.broadcast(S, du * step), dV = IntVector.broadcast(S, dv * step);
        int i = 0;
        for (; i + step <= n; i += step, uu = uu.add(dU), vv = vv.add(dV)) {
            IntVector x0 = uu.lanewise(VectorOperators.ASHR, 16).and(MASKX);
            IntVector y0 = vv.lanewise(VectorOperators.ASHR, 16).and(MASKY);
            IntVector x1 = x0.add(1).and(MASKX), y1 = y0.add(1).and(MASKY);
            IntVector fx = uu.lanewise(VectorOperators.ASHR, 8).and(0xFF), fy = vv.lanewise(VectorOperators.ASHR, 8).and(0xFF);
            IntVector r0 = y0.lanewise(VectorOperators.LSHL, SHIFT), r1 = y1.lanewise(VectorOperators.LSHL, SHIFT);
            r0.or(x0).intoArray(idx, 0); r0.or(x1).intoArray(idx, L); r1.or(x0).intoArray(idx, 2 * L); r1.or(x1).intoArray(idx, 3 * L);
            IntVector a = IntVector.fromArray(S, tex, 0, idx, 0), b = IntVector.fromArray(S, tex, 0, idx, L);
            IntVector c = IntVector.fromArray(S, tex, 0, idx, 2 * L), d = IntVector.fromArray(S, tex, 0, idx, 3 * L);
            IntVector gx = fx.neg().add(256), gy = fy.neg().add(256);
            IntVector w00 = gx.mul(gy).lanewise(VectorOperators.ASHR, 8), w10 = fx.mul(gy).lanewise(VectorOperators.ASHR, 8);
            IntVector w01 = gx.mul(fy).lanewise(VectorOperators.ASHR, 8), w11 = fx.mul(fy).lanewise(VectorOperators.ASHR, 8);
            IntVector rb = a.and(0xFF00FF).mul(w00).add(b.and(0xFF00FF).mul(w10)).add(c.and(0xFF00FF).mul(w01))
                    .add(d.and(0xFF00FF).mul(w11)).lanewise(VectorOperators.LSHR, 8);
            IntVector ag = a.lanewise(VectorOperators.LSHR, 8).and(0xFF00FF).mul(w00)
                    .add(b.lanewise(VectorOperators.LSHR, 8).and(0xFF00FF).mul(w10))
                    .add(c.lanewise(VectorOperators.LSHR, 8).and(0xFF00FF).mul(w01))
                    .add(d.lanewise(VectorOperators.LSHR, 8).and(0xFF00FF).mul(w11));
            rb.and(0xFF00FF).or(ag.and(0xFF00FF00)).intoArray(out, i);
        }
        for (; i < n; i++) { int[] one = new int[1]; scalar(tex, one, 1, u0 + i * du, du, v0 + i * dv, dv); out[i] = one[0]; }
    }

    public static void main(String[] args) {
        int[] tex = new int[TW * TH];
        java.util.Random r = new java.util.Random(1);
        for (int i = 0; i < tex.length; i++) tex[i] = r.nextInt();
        int n = 1920;
        int[] a = new int[n], b = new int[n], idx = new int[64];
        int rows = 1080;
        // Row parameters as a minified floor would give: step 0.3..3 texels per pixel, some rotation.
        int[][] rowp = new int[rows][4];
        for (int y = 0; y < rows; y++) rowp[y] = new int[] {r.nextInt(1 << 24), (int) ((0.3 + 2.7 * y / rows) * 65536), r.nextInt(1 << 24), (int) (0.2 * 65536)};
        for (int y = 0; y < rows; y++) {
            scalar(tex, a, n, rowp[y][0], rowp[y][1], rowp[y][2], rowp[y][3]);
            vector(tex, b, n, rowp[y][0], rowp[y][1], rowp[y][2], rowp[y][3], idx);
            if (!java.util.Arrays.equals(a, b)) throw new AssertionError("differ at row " + y);
        }
        double[] ratio = new double[20];
        for (int rep = 0; rep < 20; rep++) {
            long t0 = java.lang.management.ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime();
            for (int k = 0; k < 3; k++) for (int y = 0; y < rows; y++) scalar(tex, a, n, rowp[y][0], rowp[y][1], rowp[y][2], rowp[y][3]);
            long t1 = java.lang.management.ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime();
            for (int k = 0; k < 3; k++) for (int y = 0; y < rows; y++) vector(tex, b, n, rowp[y][0], rowp[y][1], rowp[y][2], rowp[y][3], idx);
            long t2 = java.lang.management.ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime();
            double ns = 3.0 * rows * n;
            ratio[rep] = (double) (t2 - t1) / (t1 - t0);
            System.out.printf("rep %d scalar %.2f ns/sample  vector %.2f ns/sample  vector/scalar %.3f%n", rep, (t1 - t0) / ns, (t2 - t1) / ns, ratio[rep]);
        }
        java.util.Arrays.sort(ratio);
        System.out.printf(S + ": median vector/scalar %.3f [%.3f..%.3f] (20 reps, thread CPU time, same outputs)%n", (ratio[9] + ratio[10]) / 2, ratio[0], ratio[19]);
    }
}
