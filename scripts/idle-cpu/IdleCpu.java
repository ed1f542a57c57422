import dev.trisect.content.AssetScenes;
import dev.trisect.content.DemoScenes;
import dev.trisect.math.Transform;
import dev.trisect.mesh.Primitives;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.view.FrameInfo;
import dev.trisect.view.TrisectView;
import java.awt.Dimension;
import java.lang.management.ManagementFactory;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CopyOnWriteArrayList;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;

/**
 * What a view of a still scene costs: the demo scene in an 800x600 view, left alone. After the first
 * frame and a settling pause, the process's CPU time (every thread: render, event, garbage collector,
 * JIT) over the given seconds, as a share of one core; then, over 40 changes to the scene each made
 * after 0.2 s of idling, how long the idle render thread takes to start the frame that shows it
 * ("wake": the change to the update hook's call, which opens each frame) and to finish it, as the
 * median, 95th percentile and largest, against one frame at 60 Hz (16.7 ms). Between the changes, the
 * same 40 times, a bare thread, parked as the idle render thread is, is unparked and times how long it
 * takes to run ("bare_unpark"): what the machine's scheduler alone adds to a wake under the load of
 * the moment, so that a slow wake can be told from slow code. Prints one JSON line; exits 1 when the
 * share is 2 % or more. Needs a display. Arguments: [seconds]; default 30.
 */
public class IdleCpu {
    public static void main(String[] args) throws Exception {
        int seconds = args.length > 0 ? Integer.parseInt(args[0]) : 30;
        Scene scene = AssetScenes.scene(DemoScenes.demo());
        List<FrameInfo> frames = new CopyOnWriteArrayList<>();
        SceneObject moved = new SceneObject(Primitives.box(0.3, 0.3, 0.3), Material.colour(0x00FF00),
                Transform.translation(0, 2, 0));
        scene.add(moved);
        // When each frame starts: the update hooks run first thing in a frame.
        java.util.concurrent.atomic.AtomicLong started = new java.util.concurrent.atomic.AtomicLong();
        JFrame[] host = new JFrame[1];
        SwingUtilities.invokeAndWait(() -> {
            TrisectView view = new TrisectView(scene);
            view.setPreferredSize(new Dimension(800, 600));
            view.addFrameListener(frames::add);
            view.addUpdateListener((step, frame) -> {
                started.set(System.nanoTime());
                return false;
            });
            host[0] = new JFrame("idle");
            host[0].add(view);
            host[0].pack();
            host[0].setVisible(true);
        });
        while (frames.isEmpty()) {
            Thread.sleep(10);
        }
        Thread.sleep(3000);
        var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        int framesBefore = frames.size();
        long cpu0 = os.getProcessCpuTime();
        long t0 = System.nanoTime();
        Thread.sleep(seconds * 1000L);
        long cpu1 = os.getProcessCpuTime();
        long t1 = System.nanoTime();
        int framesIdle = frames.size() - framesBefore;
        double share = (double) (cpu1 - cpu0) / (t1 - t0);
        // Wake-up: a change made after a while of idling, and the frame that shows it; 40 times.
        int changes = 40;
        double[] wake = new double[changes];
        double[] shown = new double[changes];
        double[] bare = new double[changes];
        java.util.concurrent.atomic.AtomicLong woke = new java.util.concurrent.atomic.AtomicLong();
        Thread parked = new Thread(() -> {
            while (true) {
                java.util.concurrent.locks.LockSupport.park();
                woke.set(System.nanoTime());
            }
        }, "bare-unpark");
        parked.setDaemon(true);
        parked.start();
        for (int i = 0; i < changes; i++) {
            Thread.sleep(100);
            woke.set(0);
            long u0 = System.nanoTime();
            java.util.concurrent.locks.LockSupport.unpark(parked);
            while (woke.get() == 0) {
                Thread.sleep(0, 100_000);
            }
            bare[i] = (woke.get() - u0) / 1e6;
            Thread.sleep(100);
            int n = frames.size();
            long c0 = System.nanoTime();
            moved.setTransform(Transform.translation(0.01 * i, 2, 0));
            while (frames.size() == n) {
                Thread.sleep(0, 100_000);
            }
            wake[i] = (started.get() - c0) / 1e6;
            shown[i] = (System.nanoTime() - c0) / 1e6;
        }
        java.util.Arrays.sort(wake);
        java.util.Arrays.sort(shown);
        java.util.Arrays.sort(bare);
        FrameInfo f = frames.get(frames.size() - 1);
        int p95 = (int) Math.ceil(0.95 * changes) - 1;
        System.out.printf(Locale.ROOT, "{\"seconds\":%.1f,\"cpu_share_of_one_core\":%.4f,\"frames_while_idle\":%d,"
                + "\"changes\":%d,\"wake_ms_median\":%.2f,\"wake_ms_p95\":%.2f,\"wake_ms_max\":%.2f,"
                + "\"bare_unpark_ms_median\":%.2f,\"bare_unpark_ms_p95\":%.2f,\"bare_unpark_ms_max\":%.2f,"
                + "\"change_to_frame_done_ms_median\":%.1f,\"change_to_frame_done_ms_max\":%.1f,\"one_frame_at_60hz_ms\":16.7,"
                + "\"frame\":\"%dx%d\",\"load_average\":%.1f}%n", (t1 - t0) / 1e9, share, framesIdle, changes,
                wake[changes / 2], wake[p95], wake[changes - 1], bare[changes / 2], bare[p95], bare[changes - 1],
                shown[changes / 2], shown[changes - 1], f.width(), f.height(), os.getSystemLoadAverage());
        SwingUtilities.invokeAndWait(() -> host[0].dispose());
        System.exit(share < 0.02 ? 0 : 1);
    }
}
