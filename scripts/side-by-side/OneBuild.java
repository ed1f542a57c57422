import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.function.LongSupplier;

/**
 * One build in a JVM of its own, for separate-jvms.sh: warms up each path in turn, then prints one
 * line of {@code path=median} CPU ms per frame of the rendering thread (one thread). Arguments:
 * frame-classes jar scene WxH warmup frames path...
 */
public final class OneBuild {
    private OneBuild() {
    }

    public static void main(String[] args) throws Exception {
        Class<?> frameClass = Builds.frameClass(args[0], args[1]);
        String[] size = args[3].split("x");
        int warmup = Integer.parseInt(args[4]);
        int frames = Integer.parseInt(args[5]);
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        StringBuilder line = new StringBuilder();
        for (int p = 6; p < args.length; p++) {
            LongSupplier frame = (LongSupplier) frameClass.getMethod("make", String.class, String.class, int.class,
                    int.class).invoke(null, args[2], args[p], Integer.parseInt(size[0]), Integer.parseInt(size[1]));
            for (int k = 0; k < warmup; k++) {
                frame.getAsLong();
            }
            double[] ms = new double[frames];
            for (int k = 0; k < frames; k++) {
                long t0 = cpu.getCurrentThreadCpuTime();
                frame.getAsLong();
                ms[k] = (cpu.getCurrentThreadCpuTime() - t0) / 1e6;
            }
            Arrays.sort(ms);
            line.append(p > 6 ? " " : "").append(args[p]).append('=').append(String.format("%.3f", ms[frames / 2]));
        }
        System.out.println(line);
        System.exit(0);
    }
}
