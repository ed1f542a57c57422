import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.function.Supplier;

/**
 * Two builds' overlay probes in one JVM, each in its own class loader, interleaved A B, B A, ...:
 * see overlay-probe.sh. Arguments: probe-classes-A A.jar probe-classes-B B.jar scene WxH policy pairs.
 */
public final class ProbePair {
    private static final String[] NAMES = {"prepare", "draw (rows read first)", "frame", "frame with borders"};

    private ProbePair() {
    }

    @SuppressWarnings("unchecked")
    public static void main(String[] args) throws Exception {
        String[] size = args[5].split("x");
        int pairs = Integer.parseInt(args[7]);
        Supplier<double[]>[] probe = new Supplier[2];
        for (int b = 0; b < 2; b++) {
            URL[] urls = {Path.of(args[2 * b]).toUri().toURL(), Path.of(args[2 * b + 1]).toUri().toURL()};
            Class<?> c = new URLClassLoader(urls, ClassLoader.getPlatformClassLoader())
                    .loadClass("dev.trisect.pipeline.Probe");
            probe[b] = (Supplier<double[]>) c.getMethod("make", String.class, String.class, int.class, int.class)
                    .invoke(null, args[4], args[6], Integer.parseInt(size[0]), Integer.parseInt(size[1]));
            for (int k = 0; k < 40; k++) {
                probe[b].get();
            }
        }
        double[][][] ms = new double[2][NAMES.length][pairs];
        for (int r = 0; r < pairs; r++) {
            for (int k = 0; k < 2; k++) {
                int b = r % 2 == 0 ? k : 1 - k;
                double[] t = probe[b].get();
                for (int i = 0; i < NAMES.length; i++) {
                    ms[b][i][r] = t[i];
                }
            }
        }
        System.out.printf("%s %s %s, one thread, CPU ms, %d pairs; A = %s, B = %s%n", args[4], args[5], args[6], pairs,
                args[1], args[3]);
        for (int i = 0; i < NAMES.length; i++) {
            double[] ratio = new double[pairs];
            for (int r = 0; r < pairs; r++) {
                ratio[r] = ms[1][i][r] / ms[0][i][r];
            }
            System.out.printf("%-24s A %8.3f  B %8.3f  B/A %.3f [%.3f..%.3f]%n", NAMES[i], median(ms[0][i]),
                    median(ms[1][i]), median(ratio), Arrays.stream(ratio).min().orElse(0),
                    Arrays.stream(ratio).max().orElse(0));
        }
        for (int b = 0; b < 2; b++) {
            double[] add = new double[pairs];
            for (int r = 0; r < pairs; r++) {
                add[r] = ms[b][3][r] / ms[b][2][r] - 1;
            }
            System.out.printf("borders add, %s: %.1f %% [%.1f..%.1f]%n", b == 0 ? "A" : "B", 100 * median(add),
                    100 * Arrays.stream(add).min().orElse(0), 100 * Arrays.stream(add).max().orElse(0));
        }
        System.exit(0);
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s[s.length / 2];
    }
}
