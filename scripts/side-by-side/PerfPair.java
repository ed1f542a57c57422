import java.io.PrintWriter;
import java.util.function.LongSupplier;

/**
 * Two builds in one JVM for side-by-side-perf.sh: each build's frame warmed up, then frames of the two
 * alternating (A B, then B A, ...), each frame's start and end on the monotonic clock
 * ({@link System#nanoTime}, which perf's {@code -k mono} samples share) written to a file as
 * "start end build", so that every sample perf takes can be given to the frame, and so the build, it
 * fell in. Arguments: frame-classes-A A.jar frame-classes-B B.jar scene WxH path threads pairs out-file;
 * with 0 pairs it only makes both frames, to check the scene and path (a bad one is a one-line message
 * and exit status 2).
 */
public final class PerfPair {
    private PerfPair() {
    }

    public static void main(String[] args) throws Exception {
        Builds.main("side-by-side-perf", () -> run(args));
    }

    private static void run(String[] args) throws Exception {
        String[] size = args[5].split("x");
        int pairs = Integer.parseInt(args[8]);
        LongSupplier[] frame = new LongSupplier[2];
        for (int b = 0; b < 2; b++) {
            frame[b] = Builds.frame(Builds.frameClass(args[2 * b], args[2 * b + 1]), args[4], args[6],
                    Integer.parseInt(size[0]), Integer.parseInt(size[1]), Integer.parseInt(args[7]));
            for (int k = 0; pairs > 0 && k < 60; k++) {
                frame[b].getAsLong();
            }
        }
        if (pairs == 0) {
            return;
        }
        long[] start = new long[2 * pairs];
        long[] end = new long[2 * pairs];
        int[] build = new int[2 * pairs];
        for (int r = 0; r < pairs; r++) {
            for (int k = 0; k < 2; k++) {
                int i = 2 * r + k;
                build[i] = r % 2 == 0 ? k : 1 - k;
                start[i] = System.nanoTime();
                frame[build[i]].getAsLong();
                end[i] = System.nanoTime();
            }
        }
        try (PrintWriter w = new PrintWriter(args[9])) {
            for (int i = 0; i < start.length; i++) {
                w.println(start[i] + " " + end[i] + " " + build[i]);
            }
        }
    }
}
