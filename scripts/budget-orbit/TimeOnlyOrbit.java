import dev.trisect.content.DemoScenes;
import dev.trisect.content.SceneAsset;
import dev.trisect.math.Vec3;
import dev.trisect.math.Viewport;
import dev.trisect.perf.BudgetController;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.FrameStats;
import dev.trisect.render.Framebuffer;
import dev.trisect.render.RenderMode;
import dev.trisect.render.RenderSettings;
import dev.trisect.render.TessellationSettings;
import dev.trisect.scene.Camera;
import java.util.Locale;

/**
 * The budget controller as builds before issue 18 drove it: {@code bench --target-ms MS --orbit} of the
 * demo scene (edge policy, ceiling 32 px, floor 1/64 of it, frame time alone), printing what that
 * bench did not: whether each frame went over its piece budget. Runs against any build's jar, since it
 * uses only what every build has: {@code java -cp BUILD.jar TimeOnlyOrbit.java MS W H FRAMES WARMUP}.
 */
public class TimeOnlyOrbit {
    public static void main(String[] a) {
        double target = Double.parseDouble(a[0]);
        int w = Integer.parseInt(a[1]), h = Integer.parseInt(a[2]), frames = Integer.parseInt(a[3]), warmup = Integer.parseInt(a[4]);
        SceneAsset scene = DemoScenes.demo();
        RenderSettings base = RenderSettings.defaults().withMode(RenderMode.TESSELLATED);
        TessellationSettings t = base.tessellation();
        double ceiling = t.maxEdge();
        BudgetController c = new BudgetController(target, ceiling, BudgetController.defaultFloor(ceiling), ceiling);
        Framebuffer fb = new Framebuffer(w, h);
        Viewport vp = new Viewport(w, h);
        Camera cam = scene.camera();
        int over = 0;
        try (FrameRenderer r = new FrameRenderer(2)) {
            for (int i = 0; i < warmup; i++) r.render(scene.mesh(), scene.textureArray(), cam.viewProjection(vp), base, fb);
            System.out.printf(Locale.ROOT, "%6s %12s %10s %10s %6s%n", "frame", "threshold", "ms", "pieces", "over");
            for (int i = 0; i < frames; i++) {
                double th = c.threshold();
                RenderSettings s = base.withTessellation(t.withMaxEdge(th));
                Vec3 d = cam.eye().sub(cam.target());
                double ang = 2 * Math.PI * i / frames, cos = Math.cos(ang), sin = Math.sin(ang);
                Camera ci = new Camera(cam.target().add(new Vec3(d.x() * cos + d.z() * sin, d.y(), -d.x() * sin + d.z() * cos)),
                        cam.target(), cam.up(), cam.fovY(), cam.near(), cam.far());
                long t0 = System.nanoTime();
                FrameStats st = r.render(scene.mesh(), scene.textureArray(), ci.viewProjection(vp), s, fb);
                double ms = (System.nanoTime() - t0) / 1e6;
                over += st.budgetReached() ? 1 : 0;
                System.out.printf(Locale.ROOT, "%6d %12.4f %10.3f %10d %6s%n", i, th, ms, st.pieces() + st.piecesOffScreen(), st.budgetReached() ? "over" : "-");
                c.update(ms);
            }
        }
        System.out.println("frames over the piece budget: " + over + " of " + frames);
    }
}
