import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.LongSupplier;

/**
 * Two builds in one JVM, their frames interleaved, timed by the rendering thread's CPU time (one
 * thread) or by the wall clock and the CPU time of the frame's rendering threads (more threads): see
 * side-by-side.sh. Arguments: frame-classes-A frame-classes-B A.jar B.jar scene WxH reps frames threads path...
 */
public final class SideBySide {
    private SideBySide() {
    }

    public static void main(String[] args) throws Exception {
        Builds.main("side-by-side", () -> run(args));
    }

    private static void run(String[] args) throws Exception {
        String[] jars = {args[2], args[3]};
        String scene = args[4];
        String[] size = args[5].split("x");
        int width = Integer.parseInt(size[0]);
        int height = Integer.parseInt(size[1]);
        int reps = Integer.parseInt(args[6]);
        int frames = Integer.parseInt(args[7]);
        int threads = Integer.parseInt(args[8]);
        List<String> paths = Arrays.asList(args).subList(9, args.length);
        LongSupplier[][] frame = new LongSupplier[2][paths.size()];
        long[][] pieces = new long[2][paths.size()];
        // Each build's rendering threads: this thread and the helpers its renderers started.
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        long[][] renderers = new long[2][];
        String[] helperNames = new String[2];
        for (int b = 0; b < 2; b++) {
            Set<Long> before = new HashSet<>();
            for (long id : cpu.getAllThreadIds()) {
                before.add(id);
            }
            Class<?> c = Builds.frameClass(args[b], jars[b]);
            for (int p = 0; p < paths.size(); p++) {
                frame[b][p] = Builds.frame(c, scene, paths.get(p), width, height, threads);
                for (int k = 0; k < 30; k++) {
                    pieces[b][p] = frame[b][p].getAsLong();
                }
            }
            List<Long> ids = new java.util.ArrayList<>(List.of(Thread.currentThread().getId()));
            Set<String> names = new java.util.TreeSet<>();
            for (java.lang.management.ThreadInfo t : cpu.getThreadInfo(cpu.getAllThreadIds())) {
                if (t != null && !before.contains(t.getThreadId())) {
                    ids.add(t.getThreadId());
                    names.add(t.getThreadName());
                }
            }
            renderers[b] = ids.stream().mapToLong(Long::longValue).toArray();
            helperNames[b] = names.size() + " helpers " + names;
        }
        double[][][] ms = new double[2][paths.size()][reps];
        double[][][] cpuMs = new double[2][paths.size()][reps];
        if (threads == 1) {
            oneThread(frame, frames, ms);
        } else {
            threads(frame, frames, ms, cpuMs, renderers);
        }
        System.out.printf("%s %s, %s, %d pairs of %d frames; A = %s, B = %s%n", scene, args[5],
                threads == 1 ? "one thread, CPU ms per frame" : threads + " threads, wall ms per frame", reps, frames,
                jars[0], jars[1]);
        table("path", paths, pieces, ms);
        if (threads > 1) {
            System.out.printf("CPU ms per frame of the frame's rendering threads (this thread and its build's %s,"
                    + " B's %s; not the compiler's, the collector's or the other build's):%n", helperNames[0], helperNames[1]);
            table("cpu", paths, pieces, cpuMs);
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

    /** Each pair: {@code frames} frames of one build, then of the other (A first in even pairs), timed by this thread's CPU time. */
    private static void oneThread(LongSupplier[][] frame, int frames, double[][][] ms) {
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        for (int r = 0; r < ms[0][0].length; r++) {
            for (int p = 0; p < frame[0].length; p++) {
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
    }

    /**
     * Renderers of several threads, whose work the calling thread's CPU time does not hold: each pair
     * interleaves the builds frame by frame (A B B A A B ..., so that neither is always first after the
     * other) and times each frame by the wall clock and by the CPU time of that build's rendering threads
     * ({@code renderers[b]}: this thread and the helpers its renderers started, each by its own clock;
     * the process clock would count the compiler's and the collector's threads, which serve both
     * builds, and ticks in 10 ms).
     * A pair's figure per build is the median of its frames, so that a frame stalled by another
     * process on this shared machine does not move it.
     */
    private static void threads(LongSupplier[][] frame, int frames, double[][][] ms, double[][][] cpuMs,
                                long[][] renderers) {
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        double[][] wall = new double[2][frames];
        double[][] used = new double[2][frames];
        for (int r = 0; r < ms[0][0].length; r++) {
            for (int p = 0; p < frame[0].length; p++) {
                for (int f = 0; f < frames; f++) {
                    for (int k = 0; k < 2; k++) {
                        int b = (r + f) % 2 == 0 ? k : 1 - k;
                        long c0 = cpuTime(cpu, renderers[b]);
                        long t0 = System.nanoTime();
                        frame[b][p].getAsLong();
                        wall[b][f] = (System.nanoTime() - t0) / 1e6;
                        used[b][f] = (cpuTime(cpu, renderers[b]) - c0) / 1e6;
                    }
                }
                for (int b = 0; b < 2; b++) {
                    ms[b][p][r] = median(wall[b]);
                    cpuMs[b][p][r] = median(used[b]);
                }
            }
        }
    }

    /** The CPU nanoseconds the given threads have used so far (a thread that has ended counts as none). */
    private static long cpuTime(ThreadMXBean cpu, long[] ids) {
        long sum = 0;
        for (long id : ids) {
            sum += Math.max(0, cpu.getThreadCpuTime(id));
        }
        return sum;
    }

    /** One line per path: pieces, each build's median ms per frame, and the per-pair B/A ratio's median and range. */
    private static void table(String title, List<String> paths, long[][] pieces, double[][][] ms) {
        System.out.printf("%-12s %8s %9s %9s  %s%n", title, "pieces", "A median", "B median", "B/A median [range]");
        for (int p = 0; p < paths.size(); p++) {
            double[] ratio = new double[ms[0][p].length];
            for (int r = 0; r < ratio.length; r++) {
                ratio[r] = ms[1][p][r] / ms[0][p][r];
            }
            System.out.printf("%s%-12s %8d %9.3f %9.3f  %.3f [%.3f..%.3f]%n", title.equals("path") ? "" : title + " ",
                    paths.get(p), pieces[1][p], median(ms[0][p]), median(ms[1][p]), median(ratio), min(ratio), max(ratio));
        }
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
