import java.util.Arrays;
import java.util.Locale;

/**
 * Whether wide vector arithmetic lowers this processor's clock for the code that runs after it, as
 * Intel's AVX-512 frequency licences do (Skylake-SP and Cascade Lake: "heavy" 256- and 512-bit
 * instructions, floating point and integer multiplies, move the core to a lower-clocked licence, which
 * it keeps for a while after the last of them). That is what made the fogged frames slower than their
 * fog pass (docs/performance/fog.md, "Fog").
 *
 * <p>Times a chain of scalar integer arithmetic (a multiply and an add per step, each step waiting on
 * the last: its time is set by the clock alone, not by memory) in chunks of about a microsecond, for
 * about two and a half milliseconds, right after a burst of a vectorized float loop (what C2 compiles
 * {@code q[x] = q[x] * c + d} to: 512-bit instructions here) and right after none, in turn, after a
 * few milliseconds of scalar work each time so that the core has left any lower licence. Prints per
 * tenth of that time the median chunk time of each and how much longer the chunks after the
 * burst took. On a processor without such licences both columns agree.
 *
 *   java scripts/light/VectorClock.java [BURST_ROWS] [TRIALS]
 *   java -XX:MaxVectorSize=16 scripts/light/VectorClock.java   (128-bit vectors)
 *
 * BURST_ROWS: passes of the float loop over 2,048 floats (20, the default: under 10 µs here, about a
 * fifth of what the fog pass spends on a band); TRIALS: pairs of runs (100).
 */
public final class VectorClock {
    private static final int CHUNKS = 2000;
    private static final int STEPS = 1000;
    private static volatile int sink;

    public static void main(String[] args) {
        int burst = args.length > 0 ? Integer.parseInt(args[0]) : 20;
        int trials = args.length > 1 ? Integer.parseInt(args[1]) : 100;
        float[] q = new float[2048];
        Arrays.fill(q, 1);
        for (int warm = 0; warm < 3000; warm++) {
            wide(q, 1);
            sink += chain(STEPS);
        }
        long[][][] t = new long[2][CHUNKS][trials];
        long burstNanos = 0;
        for (int trial = 0; trial < trials; trial++) {
            for (int v = 0; v < 2; v++) {
                long settle = System.nanoTime() + 3_000_000;
                while (System.nanoTime() < settle) {
                    sink += chain(STEPS);
                }
                if (v == 1) {
                    long s = System.nanoTime();
                    wide(q, burst);
                    burstNanos += System.nanoTime() - s;
                }
                for (int c = 0; c < CHUNKS; c++) {
                    long s = System.nanoTime();
                    sink += chain(STEPS);
                    t[v][c][trial] = System.nanoTime() - s;
                }
            }
        }
        System.out.printf(Locale.ROOT, "burst %.1f µs (median chunk times, ns: after no burst, after a burst)%n",
                burstNanos / 1e3 / trials);
        double elapsed = 0;
        int bucket = CHUNKS / 10;
        for (int c0 = 0; c0 < CHUNKS; c0 += bucket) {
            double plain = 0;
            double after = 0;
            for (int c = c0; c < c0 + bucket; c++) {
                plain += median(t[0][c]);
                after += median(t[1][c]);
            }
            System.out.printf(Locale.ROOT, "from %5.0f µs after: %6.0f %6.0f  %+5.1f %%%n", elapsed / 1e3,
                    plain / bucket, after / bucket, 100 * (after - plain) / plain);
            elapsed += after;
        }
    }

    /** A vectorized float loop: {@code rows} passes of a multiply and an add over {@code q}. */
    private static void wide(float[] q, int rows) {
        for (int r = 0; r < rows; r++) {
            for (int x = 0; x < q.length; x++) {
                q[x] = q[x] * 0.999f + 0.001f;
            }
        }
    }

    /** {@code steps} dependent scalar steps of a multiply and an add. */
    private static int chain(int steps) {
        int h = 1;
        for (int i = 0; i < steps; i++) {
            h = h * 31 + (h >>> 7);
        }
        return h;
    }

    private static double median(long[] v) {
        long[] c = v.clone();
        Arrays.sort(c);
        return c[c.length / 2];
    }
}
