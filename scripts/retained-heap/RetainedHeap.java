import dev.trisect.math.Vec3;
import dev.trisect.mesh.Primitives;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderSettings;
import dev.trisect.scene.Camera;
import dev.trisect.scene.Material;
import dev.trisect.scene.Scene;
import dev.trisect.scene.SceneObject;
import dev.trisect.scene.SceneRenderer;
import dev.trisect.texture.ProceduralTextures;
import java.lang.management.ManagementFactory;

/**
 * The heap a long-lived SceneRenderer keeps after one huge frame: the heap in use after a full
 * collection with a box drawn (before), right after a frame of a grid of CELLS x CELLS quads (2 x CELLS²
 * triangles), and after FRAMES frames of the box again (after). Prints one line per stage and the ratio
 * after / before; exits 1 when it is above 2. Arguments: [cells] [WxH] [frames]; defaults 1000
 * (2,000,000 triangles) 1280x720 5.
 */
public class RetainedHeap {
    public static void main(String[] args) throws Exception {
        int cells = args.length > 0 ? Integer.parseInt(args[0]) : 1000;
        String[] size = (args.length > 1 ? args[1] : "1280x720").split("x");
        int frames = args.length > 2 ? Integer.parseInt(args[2]) : 5;
        int w = Integer.parseInt(size[0]);
        int h = Integer.parseInt(size[1]);
        Material m = Material.of(ProceduralTextures.uvGrid(256));
        Scene box = new Scene();
        box.add(new SceneObject(Primitives.box(1, 1, 1), m));
        Camera camera = Camera.looking(new Vec3(2.5, 1.8, 3), new Vec3(0, 0.4, 0));
        Framebuffer frame = new Framebuffer(w, h);
        RenderSettings settings = RenderSettings.defaults();
        try (SceneRenderer r = new SceneRenderer()) {
            for (int i = 0; i < frames; i++) {
                r.render(box, camera, settings, frame);
            }
            long before = used();
            report("before (box)", before);
            Scene grid = new Scene();
            grid.add(new SceneObject(Primitives.plane(20, 20, cells, cells), m));
            var stats = r.render(grid, camera, settings, frame);
            grid = null;
            report("after the grid (" + stats.trianglesIn() + " triangles, " + stats.pieces() + " pieces)", used());
            for (int i = 0; i < frames; i++) {
                r.render(box, camera, settings, frame);
            }
            long after = used();
            report("after " + frames + " box frames", after);
            double ratio = (double) after / before;
            System.out.printf("retained after / before: %.2f (at most 2 expected)%n", ratio);
            if (ratio > 2) {
                System.exit(1);
            }
        }
    }

    static long used() throws InterruptedException {
        for (int i = 0; i < 4; i++) {
            System.gc();
            Thread.sleep(50);
        }
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
    }

    static void report(String what, long bytes) {
        System.out.printf("%-50s %8.1f MiB%n", what, bytes / 1048576.0);
    }
}
