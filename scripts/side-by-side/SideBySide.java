import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.function.LongSupplier;

/**
 * Two builds in one JVM, their frames interleaved, timed by the rendering thread's CPU time: see
 * side-by-side.sh. Arguments: frame-classes-A frame-classes-B A.jar B.jar scene WxH reps frames path...
 */
public final class SideBySide {
    private SideBySide() {
    }

    public static void main(String[] args) throws Exception {
        String[] jars = {args[2], args[3]};
        String scene = args[4];
        String[] size = args[5].split("x");
        int width = Integer.parseInt(size[0]);
        int height = Integer.parseInt(size[1]);
        int reps = Integer.parseInt(args[6]);
        int frames = Integer.parseInt(args[7]);
        List<String> paths = Arrays.asList(args).subList(8, args.length);
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        LongSupplier[][] frame = new LongSupplier[2][paths.size()];
        long[][] pieces = new long[2][paths.size()];
        for (int b = 0; b < 2; b++) {
            URL[] urls = {Path.of(args[b]).toUri().toURL(), Path.of(jars[b]).toUri().toURL()};
            Class<?> c = new URLClassLoader(urls, ClassLoader.getPlatformClassLoader()).loadClass("Frame");
            for (int p = 0; p < paths.size(); p++) {
                frame[b][p] = (LongSupplier) c.getMethod("make", String.class, String.class, int.class, int.class)
                        .invoke(null, scene, paths.get(p), width, height);
                for (int k = 0; k < 30; k++) {
                    pieces[b][p] = frame[b][p].getAsLong();
                }
            }
        }
        double[][][] ms = new double[2][paths.size()][reps];
        for (int r = 0; r < reps; r++) {
            for (int p = 0; p < paths.size(); p++) {
                for (int k = 0; k < 2; k++) {
                    int b = r % 2 == 0 ? k : 1 - k;
                    long t0 = cpu.getCurrentThreadCpuTime();
                    for (int f = 0; f < frames; f++) {
                        frame[b][p].getAsLong();
                    }
                    ms[b][p][r] = (cpu.getCurrentThreadCpuTime() - t0) / 1e6 / frames;
                }
            }
        }
        System.out.printf("%s %s, one thread, CPU ms per frame, %d pairs of %d frames; A = %s, B = %s%n",
                scene, args[5], reps, frames, jars[0], jars[1]);
        System.out.printf("%-12s %8s %9s %9s  %s%n", "path", "pieces", "A median", "B median", "B/A median [range]");
        for (int p = 0; p < paths.size(); p++) {
            double[] ratio = new double[reps];
            for (int r = 0; r < reps; r++) {
                ratio[r] = ms[1][p][r] / ms[0][p][r];
            }
            System.out.printf("%-12s %8d %9.3f %9.3f  %.3f [%.3f..%.3f]%n", paths.get(p), pieces[1][p],
                    median(ms[0][p]), median(ms[1][p]), median(ratio), min(ratio), max(ratio));
        }
        int affine = paths.indexOf("affine");
        for (int p = 0; affine >= 0 && p < paths.size(); p++) {
            if (!paths.get(p).equals("edge") && !paths.get(p).equals("error")) {
                continue;
            }
            for (int b = 0; b < 2; b++) {
                // The tessellated frame fills the affine frame's pixels: the difference is what its extra pieces cost.
                double[] perPiece = new double[reps];
                for (int r = 0; r < reps; r++) {
                    perPiece[r] = (ms[b][p][r] - ms[b][affine][r]) * 1e6 / (pieces[b][p] - pieces[b][affine]);
                }
                System.out.printf("ns per extra piece, %s, %s: %.0f [%.0f..%.0f]%n", paths.get(p), b == 0 ? "A" : "B",
                        median(perPiece), min(perPiece), max(perPiece));
            }
        }
        // Each path against the per-pixel path with the same filter, in the same build and the same pair.
        for (int p = 0; p < paths.size(); p++) {
            String path = paths.get(p);
            String filter = path.contains("@") ? path.substring(path.indexOf('@')).split("\\+")[0] : "";
            int reference = paths.indexOf("perspective" + filter);
            if (reference < 0 || reference == p) {
                continue;
            }
            for (int b = 0; b < 2; b++) {
                double[] ratio = new double[reps];
                for (int r = 0; r < reps; r++) {
                    ratio[r] = ms[b][p][r] / ms[b][reference][r];
                }
                System.out.printf("%s / %s, %s: %.3f [%.3f..%.3f]%n", path, paths.get(reference), b == 0 ? "A" : "B",
                        median(ratio), min(ratio), max(ratio));
            }
        }
        System.exit(0);
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s[s.length / 2];
    }

    private static double min(double[] v) {
        return Arrays.stream(v).min().orElse(Double.NaN);
    }

    private static double max(double[] v) {
        return Arrays.stream(v).max().orElse(Double.NaN);
    }
}
