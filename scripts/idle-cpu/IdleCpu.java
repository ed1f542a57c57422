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
 * median, 95th percentile and largest, against one frame at 60 Hz (16.7 ms). Prints one JSON line;
 * exits 1 when the share is 2 % or more. Needs a display. Arguments: [seconds]; default 30.
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
        for (int i = 0; i < changes; i++) {
            Thread.sleep(200);
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
        FrameInfo f = frames.get(frames.size() - 1);
        System.out.printf(Locale.ROOT, "{\"seconds\":%.1f,\"cpu_share_of_one_core\":%.4f,\"frames_while_idle\":%d,"
                + "\"changes\":%d,\"wake_ms_median\":%.2f,\"wake_ms_p95\":%.2f,\"wake_ms_max\":%.2f,"
                + "\"change_to_frame_done_ms_median\":%.1f,\"change_to_frame_done_ms_max\":%.1f,\"one_frame_at_60hz_ms\":16.7,"
                + "\"frame\":\"%dx%d\"}%n", (t1 - t0) / 1e9, share, framesIdle, changes, wake[changes / 2],
                wake[(int) Math.ceil(0.95 * changes) - 1], wake[changes - 1], shown[changes / 2], shown[changes - 1],
                f.width(), f.height());
        SwingUtilities.invokeAndWait(() -> host[0].dispose());
        System.exit(share < 0.02 ? 0 : 1);
    }
}
